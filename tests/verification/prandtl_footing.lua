-- Plastic locking: a smooth rigid strip footing on a Tresca material (Mohr-Coulomb with
-- phi = psi = 0, associated, so the limit load is unique). Prandtl: q_u = (2 + pi) c.
--
-- Half model, footing half-width b = 1 m on [0, 8] x [-6, 0] (fixed base, roller sides),
-- E = 100 MPa, nu = 0.3, c = 100 kPa, no gravity. The footing's gridpoints are pushed down at
-- 2e-6 m a step (halving the rate lowers q by 0.7 %) with local damping, to a settlement of
-- 0.056 m, where q has levelled off. Zones of 0.1 m over [0, 4] x [-2, 0], which holds
-- Prandtl's mechanism (to x = 3b, depth 1.4b), growing to 0.5 m beyond: 0.1 m throughout gives the
-- same q within 0.03 % in five times the run time. Check: q with the mixed discretisation within
-- 5 % of (2 + pi) c (the rest is the zoning at the footing's corner). Plain triangles are run too
-- and printed, not checked: volumetric locking makes them about 10 % too strong.
local check = require "edem.check"

local c, b = 100e3, 1.0
local expected = (2 + math.pi) * c

local function run(mixed)
  model{ title = "Prandtl footing" }
  block{ x = { 0, 8 }, y = { -6, 0 } }
  zone{ edge = 0.1, far = 0.5, growth = 0.2, near = { { { 0, 0 }, { 0, -2 }, { 4, -2 }, { 4, 0 } } } }
  material{ "soil", model = "mohr", density = 2000, young = 100e6, poisson = 0.3, cohesion = c,
            friction = 0, dilation = 0, tension = 1e9 }
  assign{ material = "soil" }
  set{ mixed = mixed, damping = "local" }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "right", fix = "x" }
  boundary{ side = "bottom", fix = "xy" }
  boundary{ polygon = { { -0.01, -0.01 }, { b + 1e-4, -0.01 }, { b + 1e-4, 0.01 }, { -0.01, 0.01 } }, yvel = -2e-6 }
  cycle(28000)
  -- The footing load: the soil's force on the held gridpoints under it.
  local force = 0
  for g in gridpoints() do
    if g.y > -1e-6 and g.x <= b + 1e-4 then force = force + g.fy end
  end
  return force / b, -gp_near(0, 0).uy
end

local plain = run(false)
print(("  plain triangles: q = %.4g Pa, %+.1f %% off"):format(plain, (plain / expected - 1) * 100))
local q, settlement = run(true)
print(("  mixed: settlement %.4f m"):format(settlement))
check.report("mixed: footing limit pressure q_u [Pa]", q, expected, 0.05)
check.finish()
