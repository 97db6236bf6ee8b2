-- A bar pulled in tension through a potential crack.
--
-- Expected: the crack forms at sigma_t; the load drops to zero; the open crack carries no
-- tension (its contacts' normal force exactly 0 while open); pushed back, the faces close and
-- the bar's compression stiffness is that of rock and crack in series,
--   k = 1 / (H / E' + 1 / kn) per unit width, E' = E / (1 - nu^2) (plane strain, free sides).
--
-- Bar: W = 0.2 m by H = 1 m, elastic rock (seed E = 415.52 MPa, nu = 0.136) with one potential
-- crack across it at mid-height (crackseed angle 0), judged by the seed strength
-- (sigma_t = 0.0546 MPa); zones of edge 0.05 m. Its crack takes a joint material with
-- kn = ks = 1880 MPa/m, no strength. The base is fixed in y (its centre in x), the top pulled
-- (held in y, free in x): in steps, held and solved, to 90 % of the onset, then slowly
-- (1/400000 of the elastic elongation at sigma_t per cycle) until the crack forms, and on to
-- twice the elongation at the onset; then pushed back in steps of 10 % of it, held and solved
-- after each, to a compression of 2 sigma_t.
-- Tolerances: onset 1 %; stress after the crack below 1e-6 sigma_t; open contacts' normal force
-- 0 exactly; compression stiffness 1 % (the rock's stiffness with the mesh exact; the crack's
-- from its contacts, whose lengths add up to the width: each face carries half).
local check = require "edem.check"

local W, H, EDGE = 0.2, 1.0, 0.05
local E, NU, TENSION = 415.52e6, 0.136, 0.0546e6
local KN = 1880e6
local RATIO = 1e-7

block{ x = { -W / 2, W / 2 }, y = { 0, H } }
crackseed{ angle = 0, spacing = 10, origin = { 0, H / 2 }, material = "strength", after = "crack" }
zone{ edge = EDGE }
material{ "rock", young = E, poisson = NU, density = 1505 }
material{ "strength", model = "mohr", young = E, poisson = NU, cohesion = 0.143e6, friction = 34,
          tension = TENSION }
assign{ material = "rock" }
joint_material{ "crack", kn = KN, ks = KN, friction = 31.2 }
judge{ every = 10 }
boundary{ side = "bottom", fix = "y" }
local base = gp_near(0, 0).position
boundary{ polygon = { { base.x - 0.005, -0.005 }, { base.x + 0.005, -0.005 }, { base.x + 0.005, 0.005 },
                      { base.x - 0.005, 0.005 } }, fix = "x" }

local function platen_stress()  -- the zones' mean syy, tension positive [Pa]
  local syy, area = 0, 0
  for z in zones() do syy, area = syy + z.syy * z.area, area + z.area end
  return syy / area
end
local function top() return gp_near(0, H).uy end

local function step(du, speed)
  local n = math.max(10, math.ceil(math.abs(du) / speed))
  boundary{ side = "top", yvel = du / n }
  cycle(n)
  boundary{ side = "top", yvel = 0 }
  solve{ ratio = RATIO, max_cycles = 100000 }
end

history{ "tension_cracks", every = 10 }
print(("sections %d, zones %d"):format(info().sections, info().zones))
local reach = TENSION * H * (1 - NU * NU) / E  -- elongation at the onset [m]
local at_crack
local watch = every(10, function() if info().cracks > 0 and not at_crack then at_crack = platen_stress() end end)
while platen_stress() < 0.9 * TENSION and info().cracks == 0 do step(0.05 * reach, reach / 40000) end
boundary{ side = "top", yvel = reach / 400000 }
for _ = 1, 100 do
  cycle(1000)
  if info().cracks > 0 then break end
end
cancel(watch)
local sections, broken = info().sections, info().cracks
print(("crack at cycle %d: %d of %d sections, mode %s"):format(cracks()().cycle, broken, sections, cracks()().mode))
-- On to twice the elongation at the onset.
boundary{ side = "top", yvel = 0 }
step(2 * reach - top(), reach / 40000)
local after = platen_stress()
local open, open_force, length = 0, 0, 0
for c in contacts() do
  length = length + c.length
  if c.state == "open" then open, open_force = open + 1, math.max(open_force, math.abs(c.fn)) end
end
print(("after the crack: top up %.4g mm, stress %.3g Pa; %d contacts open, largest |fn| %.3g N/m, "
       .. "contact length %.6g m"):format(top() * 1e3, after, open, open_force, length))
check.report("stress at the crack [Pa]", at_crack, TENSION, 0.01)
-- The history of the crack count steps from 0 to all sections at the crack's cycle.
local csv = os.tmpname()
history_write(csv)
local first_nonzero, last
for line in io.lines(csv) do
  local cycle, value = line:match("^([%d.e+]+),([%d.e+-]+)")
  if cycle and tonumber(value) > 0 then
    first_nonzero = first_nonzero or tonumber(cycle)
    last = tonumber(value)
  end
end
os.remove(csv)
check.report("history tension_cracks: first counted at the crack's cycle", first_nonzero or -1, cracks()().cycle, 0,
             { absolute = true })
check.report("history tension_cracks: count", last or -1, sections, 0, { absolute = true })
check.report("all sections broken, in tension (1 = yes)",
             (broken == sections and info().tension_cracks == sections) and 1 or 0, 1, 0, { absolute = true })
check.report("stress once open [Pa]", after, 0, 1e-6 * TENSION, { absolute = true })
local all = 0
for _ in contacts() do all = all + 1 end
check.report("open contacts (1 = every contact)", (open > 0 and open == all) and 1 or 0, 1, 0, { absolute = true })
check.report("normal force of open contacts [N/m]", open_force, 0, 0, { absolute = true })
check.report("contact length along the crack over the width", length / W, 1, 1e-6)

-- Pushed back: close and compress to 2 sigma_t.
local points = {}
while platen_stress() > -2 * TENSION do
  step(-0.1 * reach, reach / 40000)
  points[#points + 1] = { u = top(), s = platen_stress() }
end
local a, b = points[#points - 1], points[#points]
local k = (b.s - a.s) / (b.u - a.u) * H  -- stress per strain over the bar [Pa]
local expected = H / (H * (1 - NU * NU) / E + 1 / KN)
local closed = 0
for c in contacts() do if c.state ~= "open" then closed = closed + 1 end end
print(("closed again: %d contacts pressing; compression stiffness H ds/du %.6g Pa, series %.6g Pa, "
       .. "intact %.6g Pa"):format(closed, k, expected, E / (1 - NU * NU)))
check.report("compression stiffness after closing [Pa]", k, expected, 0.01)
check.finish()
