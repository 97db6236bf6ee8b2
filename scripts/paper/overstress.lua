-- How much rock the cavern overstresses at each depth: the rock mass of a case as one continuum
-- (joints tied), the whole cavern dug, at 158, 212 and 262 m, with a parameter set's rock
-- (scripts/paper/README.md, "Sensitivities": Set M's hardly grows with depth, Set P's does). Two
-- areas of rock left in place, per depth:
--   * where the elastic stress breaks the seed's shear criterion (1) or tension criterion (2):
--     what an explicit run's sections, judged on the stress of elastic blocks, start from;
--   * where the Mohr-Coulomb prepass yields: where case.lua places its potential cracks.
-- Beside them the same two for a circular opening of the cavern's area in the same stresses, in
-- closed form: Kirsch's elastic stresses, and Salencon's plastic ring under the mean in-situ
-- stress (hydrostatic; no support).
--
--   edem --quiet run scripts/paper/overstress.lua   (Case 3, Set P; --set case=1 or 2, --set set=M)
--
-- About 3 minutes on one core, most of it the three Mohr-Coulomb prepasses.
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local shapes = require "edem.shapes"

local CASE = arg and arg.case or 3
local DEPTHS = { 158, 212, 262 }
local K0 = 0.6
local SET = tostring(arg and arg.set or "P")
local rock = (seed[SET] or error(("overstress: set must be P, S or M, got %s"):format(SET), 0)).rock
local phi = math.rad(rock.friction)
local sin_phi, cos_phi = math.sin(phi), math.cos(phi)

-- Criterion (1) as edem's judge has it: below zero, s1 the most compressive (compression negative).
local function breaks_shear(s1, s3)
  return (1 - sin_phi) * s1 - (1 + sin_phi) * s3 + 2 * rock.cohesion * cos_phi < 0
end

local c = cavern.warhead{}
local names = {}
for _, s in ipairs(c.stages) do names[#names + 1] = s.name end

-- The areas [m2] of rock in place where a prepass's zones break each criterion or yielded, how
-- far from the outline the farthest zone breaking (1) lies [m], and the area dug.
local function areas(pre, area)
  local shear, tension, yielded, deepest, dug = 0, 0, 0, 0, 0
  for _, z in ipairs(pre.zones) do
    if z.states[#z.states] == "excavated" then
      dug = dug + area[z.id]
    else
      if breaks_shear(z.s1, z.s3) then
        shear = shear + area[z.id]
        deepest = math.max(deepest, shapes.distance_to(c.outline, z.x, z.y))
      end
      if z.s3 > rock.tension then tension = tension + area[z.id] end
      if z.state ~= "none" then yielded = yielded + area[z.id] end
    end
  end
  return shear, tension, yielded, deepest, dug
end

-- Kirsch's stresses around a circular hole of radius a, the vertical in-situ stress sv and the
-- horizontal k0 sv (compression positive, as given), integrated over the ring a < r < 6 a: the
-- area where they break (1).
local function kirsch_shear_area(a, sv)
  sv = -sv  -- compression negative from here on, as the criterion takes it
  local sh = K0 * sv
  local p, q = 0.5 * (sv + sh), 0.5 * (sh - sv)  -- q along x
  local area, rings, rays = 0, 1000, 720
  local dr = 5 * a / rings
  for i = 0, rings - 1 do
    local r = a + (i + 0.5) * dr
    local ar = (a / r) ^ 2
    for j = 0, rays - 1 do
      local th = 2 * math.pi * (j + 0.5) / rays
      local sr = p * (1 - ar) + q * (1 - 4 * ar + 3 * ar * ar) * math.cos(2 * th)
      local st = p * (1 + ar) - q * (1 + 3 * ar * ar) * math.cos(2 * th)
      local tr = -q * (1 + 2 * ar - 3 * ar * ar) * math.sin(2 * th)
      local centre, half = 0.5 * (sr + st), math.sqrt((0.5 * (sr - st)) ^ 2 + tr * tr)
      if breaks_shear(centre - half, centre + half) then area = area + r * dr * 2 * math.pi / rays end
    end
  end
  return area
end

-- Salencon's plastic radius around an unsupported circular hole under the hydrostatic stress p0
-- (positive: compression), Mohr-Coulomb with tension ignored.
local function salencon_ring_area(a, p0)
  local n_phi = (1 + sin_phi) / (1 - sin_phi)
  local h = rock.cohesion / math.tan(phi)
  local r0 = a * (2 / (n_phi + 1) * (p0 + h) / h) ^ (1 / (n_phi - 1))
  return math.pi * (r0 * r0 - a * a)
end

local rows = {}
for _, depth in ipairs(DEPTHS) do
  seed.region{ case = CASE, set = "M", depth = depth, regions = c.stages, near = { c.outline }, edge = 1.5,
               far = 10, tolerance = 7e-4 }
  local area = {}
  for z in zones() do area[z.id] = z.area end
  material{ "elastic", density = rock.density, young = rock.young, poisson = rock.poisson }
  assign{ material = "elastic" }
  local shear, tension, _, deepest, dug = areas(prepass{ stages = names, joints = false, steps = 1, solver = "lu" },
                                                area)
  local radius = math.sqrt(dug / math.pi)
  seed.intact(SET)
  -- As case.lua's prepass, so that the yielded zones are the ones its cracks are placed in.
  local pre = prepass{ stages = names, joints = false, steps = 2, restarts = 4, on_failure = "keep", solver = "lu" }
  if pre.failure then error(("depth %d m: the prepass stopped short, so its yielded area is not the whole "
                             .. "cavern's: %s"):format(depth, pre.failure), 0) end
  local _, _, yielded = areas(pre, area)
  -- The in-situ stress at the cavern's centre (its crown 24 m above it).
  local sv = rock.density * 9.81 * (depth + 24)
  rows[#rows + 1] = { depth = depth, sv = sv, dug = dug, radius = radius, shear = shear, deepest = deepest,
                      tension = tension, yielded = yielded,
                      kirsch = kirsch_shear_area(radius, sv), ring = salencon_ring_area(radius, 0.5 * (1 + K0) * sv) }
end

print(("Case %d, Set M, the cavern dug whole (%.0f m2; a circle of that area has radius %.2f m):"):format(
  CASE, rows[1].dug, rows[1].radius))
print("| depth [m] | sigma_v [MPa] | c / sigma_v | elastic, breaks (1) [m2] | farthest [m] | elastic, breaks (2) "
      .. "[m2] | prepass yielded [m2] | circle: Kirsch, breaks (1) [m2] | circle: Salencon's ring [m2] |")
print("|---|---|---|---|---|---|---|---|---|")
for _, r in ipairs(rows) do
  print(("| %d | %.2f | %.3f | %.0f | %.1f | %.0f | %.0f | %.0f | %.0f |"):format(r.depth, r.sv / 1e6,
    rock.cohesion / r.sv, r.shear, r.deepest, r.tension, r.yielded, r.kirsch, r.ring))
end
local first, last = rows[1], rows[#rows]
print(("From %d to %d m: elastic area breaking (1) x%.3f, prepass yielded x%.3f; circle: Kirsch x%.3f, "
       .. "Salencon x%.3f"):format(first.depth, last.depth, last.shear / first.shear, last.yielded / first.yielded,
       last.kirsch / first.kirsch, last.ring / first.ring))
