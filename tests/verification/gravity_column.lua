-- Gravity column and in-situ stress with K0.
--
-- 1. An elastic column (H = 100 m, rho = 2650 kg/m3, E = 10 GPa, nu = 0.25), roller sides,
--    fixed base, gravity switched on from zero stress: sv = rho g z, sh = nu/(1-nu) sv and the
--    top settles by rho g H^2 / (2 M).
-- 2. The same column initialised with K0 = 0.6 (insitu{ surface = }): the unbalanced-force
--    ratio is below 1e-6 before any cycle, and solving moves nothing.
local check = require "edem.check"

local H, width, rho, g, E, nu = 100.0, 10.0, 2650.0, 9.81, 10e9, 0.25
local M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))

local function column()
  model{ title = "gravity column" }
  block{ x = { 0, width }, y = { 0, H } }
  zone{ edge = 1.0 }
  material{ "rock", density = rho, young = E, poisson = nu }
  assign{ material = "rock" }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "right", fix = "x" }
  boundary{ side = "bottom", fix = "xy" }
  gravity{ 0, -g }
end

-- 1. gravity switched on
column()
local result = solve{ ratio = 1e-7 }
local worst_v, worst_h = 0, 0
for z in zones() do
  if z.x > 0.2 * width and z.x < 0.8 * width then  -- away from the corner zones
    local sv = -rho * g * (H - z.y)
    worst_v = math.max(worst_v, math.abs(z.syy - sv) / (rho * g * H))
    worst_h = math.max(worst_h, math.abs(z.sxx - nu / (1 - nu) * sv) / (rho * g * H))
  end
end
check.report("column sv, max |error| / (rho g H)", worst_v, 0, 0.005, { absolute = true })
check.report("column sh, max |error| / (rho g H)", worst_h, 0, 0.005, { absolute = true })
local top = gp_near(width / 2, H)
check.report("column top settlement [m]", -top.uy, rho * g * H * H / (2 * M), 0.005)
check.report("column sv at the base [Pa]", -zone_at(width / 2, 0.3).syy, rho * g * (H - 0.3), 0.01)
print(("  gravity turn-on solved in %d cycles"):format(result.cycles))

-- 2. initialised with K0 = 0.6
column()
insitu{ surface = H, density = rho, k0 = 0.6 }
local before = solve{ ratio = 1e-6 }
check.report("K0 model: cycles needed to reach ratio 1e-6", before.cycles, 0, 0, { absolute = true })
check.report("K0 model: initial ratio", before.ratio, 0, 1e-6, { absolute = true })
cycle(1000)
local moved = 0
for p in gridpoints() do moved = math.max(moved, math.abs(p.ux), math.abs(p.uy)) end
check.report("K0 model: max displacement after 1000 cycles / (rho g H^2 / M)", moved / (rho * g * H * H / M), 0, 1e-6, { absolute = true })
local z = zone_at(width / 2, 50)
check.report("K0 model sv at y = 50 [Pa]", z.syy, -rho * g * (H - z.y), 0.0005)
check.report("K0 model sh at y = 50 [Pa]", z.sxx, -0.6 * rho * g * (H - z.y), 0.0005)
check.finish()
