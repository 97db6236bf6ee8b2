-- The seed cavern (Case 3, H = 158 m, edem.seed's Set P rock as Mohr-Coulomb,
-- the warhead's 16 stages), solved through all stages by the implicit prepass and by the explicit
-- solver: their plastic zones after the final stage overlap (intersection over union >= 0.8); and
-- crackseed{ auto } puts potential cracks only in the zones the prepass found yielding, at the
-- angles the seed's rule gives.
--
-- The joints are bonded and stiff in both runs (kn = ks = 5e11 Pa/m, cohesion and tension 1e12 Pa:
-- they add 0.2 % to the rock's compliance at 8 m spacing), the way a UDEC user glues joints for an
-- elastoplastic analysis. With Set P's own joints (kn 83.9 MPa/m) neither solver reaches a static
-- state: the explicit run stops at stage 3 on a 0.15 m overlap (more than half a zone edge) and
-- the implicit one at stage 4 with an out-of-balance force it cannot remove.
--   Implicit: prepass{ joints = true }, 2 load steps a stage, the joints as interface elements.
--   Explicit: excavate{ release = 2000 } and solve{ ratio = 1e-5 } per stage, in static mode.
-- A zone is plastic when it yielded (shear or tension) at any stage and is not excavated.
-- Run: cd stdlib && ../build/interp/edem ../tests/verification/prepass_seed_cavern.lua [EDGE]
--   EDGE: zone edge at the cavern [m], default 1.5 (~7k zones)
local check = require "edem.check"
local seed = require "edem.seed"
local cavern = require "edem.cavern"

local EDGE = tonumber(arg and arg[1]) or 1.5
local TOLERANCE = tonumber(arg and arg[2]) or 1e-5
local c = cavern.warhead{}
local stages = {}
for _, s in ipairs(c.stages) do stages[#stages + 1] = s.name end

local function build()
  local n = seed.region{ regions = c.stages, near = { c.outline }, edge = EDGE, far = 10, tolerance = TOLERANCE }
  seed.elastoplastic{}
  return n
end

-- Point p inside triangle t (three {x, y}), or within `slack` of it.
local function distance_to_triangle(p, t)
  local inside, nearest = true, math.huge
  for i = 1, 3 do
    local a, b = t[i], t[i % 3 + 1]
    local ex, ey = b[1] - a[1], b[2] - a[2]
    local px, py = p[1] - a[1], p[2] - a[2]
    if ex * py - ey * px < 0 then inside = false end  -- counter-clockwise zones
    local s = math.max(0, math.min(1, (px * ex + py * ey) / (ex * ex + ey * ey)))
    nearest = math.min(nearest, math.sqrt((px - s * ex) ^ 2 + (py - s * ey) ^ 2))
  end
  return inside and 0 or nearest
end

local function axis_difference(a, b)
  local d = math.abs(a - b) % 180
  return math.min(d, 180 - d)
end

-- Implicit.
local n = build()
print(("%d zones, %d blocks, edge %g m at the cavern"):format(n.zones, n.blocks, EDGE))
local pre = prepass{ stages = stages, joints = true, steps = 2 }
local implicit, yielded = {}, {}   -- plastic at the end; every yielded zone still there, by id
for _, z in ipairs(pre.zones) do
  if z.state ~= "none" and z.states[#z.states] ~= "excavated" then
    implicit[z.id] = true
    yielded[z.id] = z
  end
end
local triangle, area = {}, {}
for z in zones() do
  if yielded[z.id] then
    triangle[z.id] = { { z.vertices[1].x, z.vertices[1].y }, { z.vertices[2].x, z.vertices[2].y },
                       { z.vertices[3].x, z.vertices[3].y } }
    area[z.id] = z.area
  end
end
local implicit_seconds = pre.seconds

-- Automatic placement, on the prepass's model.
-- Cuts bend by up to the larger of the model's tolerance and the zones' sliver rule (zone{ sliver }:
-- a cut point within 0.1 of the local zone edge of a vertex snaps onto it, so no edge is shorter).
local SLIVER = 0.1
local tolerance = math.max(TOLERANCE * math.sqrt(200 ^ 2 + 180 ^ 2), SLIVER * EDGE)
local phi = seed.P.rock.friction
local groups = crackseed{ auto = pre }
local cuts, worst_angle, worst_rule, worst_place, wrong_mode, fitted = 0, 0, 0, 0, 0, 0
for _, g in ipairs(groups) do
  -- The group's principal direction, recomputed from its zones (area-weighted axial mean).
  -- Its mode: tension where the zones that yielded in tension cover more than half its area.
  local sc, ss, tension_area, group_area = 0, 0, 0, 0
  for _, id in ipairs(g.zones) do
    local z = yielded[id]
    if not z then error(("group %d has zone %d, which did not yield"):format(g.seed, id)) end
    if z.state:find("tension") ~= nil then tension_area = tension_area + area[id] end
    group_area = group_area + area[id]
    sc = sc + area[id] * math.cos(math.rad(2 * z.angle))
    ss = ss + area[id] * math.sin(math.rad(2 * z.angle))
  end
  if (tension_area > 0.5 * group_area) ~= (g.mode == "tension") then wrong_mode = wrong_mode + 1 end
  local principal = 0.5 * math.deg(math.atan(ss, sc))
  -- The seed's rule: shear, +-(45 + phi/2) from the major principal plane (normal to the most
  -- compressive stress); tension, along and across it.
  local plane = principal + 90
  local want = g.mode == "shear" and { plane + 45 + phi / 2, plane - 45 - phi / 2 } or { plane, plane + 90 }
  for k = 1, 2 do worst_rule = math.max(worst_rule, axis_difference(g.angles[k], want[k])) end
  for _, cut in ipairs(g.cuts) do
    cuts = cuts + 1
    local a, b = cut[1], cut[2]
    local direction = math.deg(math.atan(b.y - a.y, b.x - a.x))
    worst_angle = math.max(worst_angle, math.min(axis_difference(direction, g.angles[1]),
                                                 axis_difference(direction, g.angles[2])))
    for s = 0, 10 do  -- 11 points along it, ends included: each in a yielded zone of its group
      local p = { a.x + s / 10 * (b.x - a.x), a.y + s / 10 * (b.y - a.y) }
      local nearest = math.huge
      for _, id in ipairs(g.zones) do nearest = math.min(nearest, distance_to_triangle(p, triangle[id])) end
      worst_place = math.max(worst_place, nearest)
    end
  end
  fitted = fitted + #g.zones
end
print(("crackseed{ auto }: %d groups over %d of %d yielded zones, %d cuts, %d sections"):format(#groups, fitted,
  (function() local k = 0 for _ in pairs(yielded) do k = k + 1 end return k end)(), cuts, info().sections))
check.report("auto: groups placed", #groups > 0 and 1 or 0, 1, 0, { absolute = true })
check.report("auto: groups whose mode is not that of most of their area", wrong_mode, 0, 0,
             { absolute = true })
check.report("auto: set angles against the seed's rule [deg]", worst_rule, 0, 1e-9, { absolute = true })
check.report("auto: cut directions against their set's [deg]", worst_angle, 0, 1e-9, { absolute = true })
check.report("auto: cut points outside their group's zones [m]", worst_place, 0, 1e-9, { absolute = true })
-- The rebuilt model: every section lies on yielded rock (within the cutter's bending) along a set.
local off_rock, off_angle, count = 0, 0, 0
for s in sections() do
  count = count + 1
  local nearest = math.huge
  for id, t in pairs(triangle) do nearest = math.min(nearest, distance_to_triangle({ s.x, s.y }, t)) end
  off_rock = math.max(off_rock, nearest)
  local best = 90
  for _, g in ipairs(groups) do
    for k = 1, 2 do best = math.min(best, axis_difference(s.angle, g.angles[k])) end
  end
  off_angle = math.max(off_angle, best)
end
check.report("auto: sections placed", count > 0 and 1 or 0, 1, 0, { absolute = true })
-- Every cut became sections: none was dropped as ending inside a block.
local empty = 0
for _, g in ipairs(groups) do
  for _, cut in ipairs(g.cuts) do
    local a, b, on = cut[1], cut[2], false
    for s in sections() do
      local ex, ey = b.x - a.x, b.y - a.y
      local t = math.max(0, math.min(1, ((s.x - a.x) * ex + (s.y - a.y) * ey) / (ex * ex + ey * ey)))
      if math.sqrt((s.x - a.x - t * ex) ^ 2 + (s.y - a.y - t * ey) ^ 2) <= tolerance then on = true break end
    end
    local merged = 0  -- a cut within the sliver tolerance of a block boundary merges into it
    if not on then
      for ct in contacts() do
        local ex, ey = b.x - a.x, b.y - a.y
        local t = ((ct.x - a.x) * ex + (ct.y - a.y) * ey) / (ex * ex + ey * ey)
        if t >= 0 and t <= 1 and
           math.sqrt((ct.x - a.x - t * ex) ^ 2 + (ct.y - a.y - t * ey) ^ 2) <= tolerance then merged = merged + 1 end
      end
      print(("cut with no section: (%.3f, %.3f) to (%.3f, %.3f), %.3f m long, %d contact(s) along it"):format(
        a.x, a.y, b.x, b.y, math.sqrt((b.x - a.x) ^ 2 + (b.y - a.y) ^ 2), merged))
    end
    if not on and merged == 0 then empty = empty + 1 end
  end
end
check.report("auto: cuts with no section on them", empty, 0, 0, { absolute = true })
check.report(("auto: section midpoints off yielded rock [m] (bending tolerance %.3g m)"):format(tolerance),
             off_rock, 0, tolerance, { absolute = true })
-- A section is a zone edge along a cut; bent cuts turn by at most atan(tolerance / zone edge).
check.report("auto: section directions against the sets [deg]", off_angle, 0,
             math.deg(math.atan(2 * tolerance / EDGE)), { absolute = true })
-- The dynamic run starts from the in-situ state: the cracks are tied shut, nothing moves.
local r = solve{ ratio = 1e-5, max_cycles = 100 }
check.report("auto: in-situ state balanced after the rebuild (ratio)", r.ratio, 0, 1e-5, { absolute = true })

-- Explicit, on a fresh model (the same zones: the build is deterministic).
build()
local clock = os.clock()
solve{ ratio = 1e-6, max_cycles = 40000 }
for _, s in ipairs(c.stages) do
  excavate{ region = s.name, release = 2000 }
  local result = solve{ ratio = 1e-5, max_cycles = 100000 }
  if not result.converged then error(("explicit: stage %s did not converge"):format(s.name)) end
end
local explicit_seconds = os.clock() - clock
local both, either, counted_implicit, counted_explicit = 0, 0, 0, 0
for z in zones() do
  if not z.excavated then
    local e, i = z.state ~= "elastic", implicit[z.id] or false
    if e then counted_explicit = counted_explicit + 1 end
    if i then counted_implicit = counted_implicit + 1 end
    if e and i then both = both + 1 end
    if e or i then either = either + 1 end
  end
end
print(("plastic zones: implicit %d, explicit %d, both %d, either %d; implicit %.1f s, explicit %.1f s cpu"):format(
  counted_implicit, counted_explicit, both, either, implicit_seconds, explicit_seconds))
check.report("plastic zones, intersection over union (>= 0.8)", both / either, 1, 0.2, { absolute = true })
check.finish()
