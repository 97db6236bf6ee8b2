-- The plastic work a zone keeps (zones(): plastic_work [J/m^3]) against the closed form of a
-- Mohr-Coulomb element driven in plane-strain pure shear, and against the energy balance.
--
-- Every gridpoint moves with the homogeneous strain rates exx = +rate, eyy = -rate a cycle from
-- an isotropic stress -p (szz too). The volume does not change, so with dilation 0 the in-plane
-- mean stress stays -p and szz stays -p, the intermediate stress. The Mohr circle's radius grows
-- as 2 G e (e = exx) until the shear criterion s1 - N s3 + 2 c sqrt(N) = 0 holds, at
--   r = ((N - 1) p + 2 c sqrt(N)) / (N + 1),  reached at e_y = r / (2 G),
-- then stays there. The work done on the element per unit volume, (sxx - syy) de = 2 r de past
-- e_y, all goes into plastic work (the elastic energy no longer grows), so
--   W_p = 2 r (e - e_y)  for e > e_y, 0 before.
-- Checked at half the yield strain (none), at 2 e_y and 10 e_y, in every zone (the field is
-- homogeneous: the largest departure), to one step's worth of work, 2 r rate: the step in which
-- the zone first yields is worked on its mid-step stress.
-- Then: the zones' plastic work times their area is the energy balance's plastic term (1e-9),
-- and reset{ "state" } clears it with the state flags.
local check = require "edem.check"

local young, nu, p, c, phi = 1e9, 0.25, 1e6, 1e6, 30.0
local rate = 2e-7  -- exx a cycle (static mode)
local shear = young / (2 * (1 + nu))
local s = math.sin(math.rad(phi))
local N = (1 + s) / (1 - s)
local r = ((N - 1) * p + 2 * c * math.sqrt(N)) / (N + 1)
local e_y = r / (2 * shear)
local function closed_form(e) return e > e_y and 2 * r * (e - e_y) or 0 end

model{ title = "plastic work, pure shear" }
block{ x = { 0, 1 }, y = { 0, 1 } }
zone{ edge = 1 }
material{ "rock", model = "mohr", density = 2000, young = young, poisson = nu, cohesion = c, friction = phi,
          tension = 1e6 }
assign{ material = "rock" }
insitu{ sxx = -p, syy = -p, szz = -p }
for g in gridpoints() do
  local x, y = g.x, g.y
  boundary{ polygon = { { x - 0.01, y - 0.01 }, { x + 0.01, y - 0.01 }, { x + 0.01, y + 0.01 }, { x - 0.01, y + 0.01 } },
            xvel = rate * x, yvel = -rate * y }
end
energy{ reset = true }

local strain = 0
local function run_to(e)
  local n = math.floor((e - strain) / rate + 0.5)
  cycle(n)
  strain = strain + n * rate
end
for _, at in ipairs({ 0.5, 2, 10 }) do
  run_to(at * e_y)
  local lo, hi = math.huge, -math.huge
  for z in zones() do lo, hi = math.min(lo, z.plastic_work), math.max(hi, z.plastic_work) end
  local expected = closed_form(strain)
  local worst = math.abs(lo - expected) > math.abs(hi - expected) and lo or hi
  check.report(("pure shear at e = %.4g (%g e_y): plastic work, the zone furthest off [J/m^3]"):format(strain, at),
               worst, expected, 2 * r * rate, { absolute = true })
end

local total = 0
for z in zones() do total = total + z.area * z.plastic_work end
check.report("the zones' plastic work against the energy balance's plastic term [J/m]", total, energy().plastic, 1e-9)

reset{ "state" }
local left = 0
for z in zones() do left = math.max(left, math.abs(z.plastic_work)) end
check.report("reset{ \"state\" } clears it: largest left [J/m^3]", left, 0, 0, { absolute = true })
check.finish()
