-- A strain-softening Mohr-Coulomb element (model = "ss") in plane-strain compression at a
-- constant confining stress follows the closed-form stress path of FLAC's ss model.
--
-- Cohesion softens linearly from c0 to cr over e_ps in [0, e_r]; friction phi constant, dilation
-- 0; N = (1 + sin phi) / (1 - sin phi), E' = E / (1 - nu^2), e1 = K + 4G/3, e2 = K - 2G/3.
-- Closed form (compression negative; e = axial shortening, sxx = -p throughout):
--   elastic:   syy = -p - E' e, lateral strain e2/e1 e;
--   peak:      syy = -(N p + 2 c0 sqrt(N)) at e_peak;
--   softening: with psi = 0 the flow rule gives plastic strains lambda (1, 0, -1) on (yy, zz, xx),
--              so d e_ps = |lambda|, and staying on the surface with c(e_ps) gives
--              e_ps = E' (e - e_peak) / (E' - K),  K = 2 sqrt(N) (c0 - cr) / e_r,
--              syy = -(N p + 2 sqrt(N) c(e_ps)), lateral strain rate (E' - K e2/e1) / (E' - K);
--   residual:  syy = -(N p + 2 sqrt(N) cr) once e_ps >= e_r; then e_ps grows as e, lateral rate 1.
-- The element: a 1 m x 1 m square of 6 zones with no interior gridpoint, every gridpoint moved
-- with the closed form's homogeneous strain rates (axial 5e-7 a cycle, lateral by the phase).
-- Why driven so: under a confining stress on free sides, a softening sample of several zones
-- localises after the peak (zones that soften and zones that unload, as they should: the
-- homogeneous path is then one solution among others), and the zoning makes at least 6 zones.
-- Driven, every zone sees the same strain; the law must then keep sxx at -p by itself and put
-- syy and e_ps on the closed form. Checked before the peak, at the peak, mid-softening and at the
-- residual. Tolerance 1e-3 of the peak deviator (N - 1) p + 2 c0 sqrt(N) (5.5 kPa) for stresses:
-- the strength of a step is the one its e_ps had at the step's start (as in FLAC), a lag of
-- K d e_ps = 0.2 kPa a cycle, and the phases switch at a whole cycle, E' 5e-7 = 0.5 kPa; e_ps 1 %.
-- Where the method can fail: a table that does not increase in e_ps is refused, naming the key.
local check = require "edem.check"

local young, nu = 1e9, 0.25
local p, phi, c0, cr, e_r = 1e6, 30.0, 1e6, 0.2e6, 0.01
local rate = 5e-7  -- axial shortening a cycle (static mode)
local bulk, shear = young / (3 * (1 - 2 * nu)), young / (2 * (1 + nu))
local e1, e2 = bulk + 4 * shear / 3, bulk - 2 * shear / 3
local s = math.sin(math.rad(phi))
local N = (1 + s) / (1 - s)
local Ep = young / (1 - nu * nu)
local K = 2 * math.sqrt(N) * (c0 - cr) / e_r
local peak = N * p + 2 * math.sqrt(N) * c0
local residual = N * p + 2 * math.sqrt(N) * cr
local deviator = peak - p
local e_peak = (peak - p) / Ep
local e_res = e_peak + e_r * (Ep - K) / Ep

-- The closed form: axial stress magnitude and e_ps at an axial shortening e.
local function closed_form(e)
  if e <= e_peak then return p + Ep * e, 0 end
  local eps = Ep * (e - e_peak) / (Ep - K)
  if eps >= e_r then return residual, e_r + (e - e_res) end
  return N * p + 2 * math.sqrt(N) * (c0 - (c0 - cr) * eps / e_r), eps
end

model{ title = "strain-softening element" }
block{ x = { 0, 1 }, y = { 0, 1 } }
zone{ edge = 1 }
material{ "rock", model = "ss", density = 2000, young = young, poisson = nu, cohesion = c0, friction = phi,
          cohesion_table = { { 0, c0 }, { e_r, cr } } }
assign{ material = "rock" }
insitu{ sxx = -p, syy = -p, szz = -p }

-- Every gridpoint moves with the homogeneous strain rates: x rate `lateral` x, y rate -`rate` y.
local points = {}
for g in gridpoints() do points[#points + 1] = { g.x, g.y } end
local function drive(lateral)
  for _, xy in ipairs(points) do
    local x, y = xy[1], xy[2]
    boundary{ polygon = { { x - 0.01, y - 0.01 }, { x + 0.01, y - 0.01 }, { x + 0.01, y + 0.01 }, { x - 0.01, y + 0.01 } },
              xvel = lateral * rate * x, yvel = -rate * y }
  end
end

local path, highest, shortening = {}, 0, 0
local function record()
  local sxx, syy, eps, area = 0, 0, 0, 0
  for z in zones() do
    sxx, syy, eps, area = sxx + z.sxx * z.area, syy + z.syy * z.area, eps + z.e_ps * z.area, area + z.area
  end
  path[#path + 1] = { e = shortening, s = -syy / area, sxx = sxx / area, eps = eps / area }
  highest = math.max(highest, -syy / area)
end
local function run_to(e, lateral)
  drive(lateral)
  while shortening + rate <= e + 0.5 * rate do
    local n = math.min(100, math.floor((e - shortening) / rate + 0.5))
    cycle(n)
    shortening = shortening + n * rate
    record()
  end
end
run_to(e_peak, e2 / e1)
run_to(e_res, (Ep - K * e2 / e1) / (Ep - K))
run_to(0.016, 1)

local function at(e)  -- the record nearest to shortening e
  local best
  for _, r in ipairs(path) do if not best or math.abs(r.e - e) < math.abs(best.e - e) then best = r end end
  return best
end

local e_mid = 0.5 * (e_peak + e_res)
for _, case in ipairs({ { "elastic, half the peak strain", 0.5 * e_peak }, { "mid-softening", e_mid },
                        { "residual", 0.015 } }) do
  local r = at(case[2])
  check.report(("%s (e = %.4g): axial stress [Pa]"):format(case[1], r.e), r.s, (closed_form(r.e)),
               1e-3 * deviator, { absolute = true })
end
check.report("peak axial stress [Pa]", highest, peak, 1e-3 * deviator, { absolute = true })
local worst = 0
for _, r in ipairs(path) do worst = math.max(worst, math.abs(r.sxx + p)) end
check.report("lateral stress, largest departure from -p over the path [Pa]", worst, 0, 1e-3 * deviator,
             { absolute = true })
for _, e in ipairs({ e_mid, 0.015 }) do
  local r = at(e)
  local _, eps = closed_form(r.e)
  check.report(("e_ps at e = %.4g"):format(r.e), r.eps, eps, 0.01)
end

-- A cohesion table whose e_ps goes back is refused, naming the key and the values.
local ok, message = pcall(material, { "bad", model = "ss", young = young, poisson = nu, cohesion = c0,
                                      friction = phi, cohesion_table = { { 0, c0 }, { 0.02, cr }, { 0.01, cr } } })
print("unsorted table: " .. tostring(message))
check.report("unsorted cohesion_table refused, naming it (1 = yes)",
             (not ok and tostring(message):find("cohesion_table point 3: e_ps must increase", 1, true)) and 1 or 0,
             1, 0, { absolute = true })
check.finish()
