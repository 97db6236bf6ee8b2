-- Joint normal and shear stiffness (the joint element of Goodman, Taylor & Brekke 1968: closure
-- sigma_n / kn, elastic shear tau / ks, then Coulomb slip), two stacked blocks.
--
-- A 1 m x 2 m column cut by one horizontal joint at mid-height, E = 10 GPa, nu = 0.25; joint
-- kn = 10 GPa/m, ks = 1 GPa/m, friction 30, no cohesion. Static mode, solved to ratio 1e-10.
--   1. Normal: sigma_n = 0.1 .. 1 MPa on the top in 10 increments (base on rollers, left side on
--      rollers, right side free, so the stress is uniaxial and uniform), then back to 0.5 MPa.
--      Every contact's closure against sigma_n / kn (0.1 mm at 1 MPa) and the top's settlement
--      against sigma H (1 - nu^2) / E + sigma / kn, within 0.5 %; unloading is linear: the
--      closure at 0.5 MPa after unloading equals the one on the way up.
--   2. Shear at sigma_n = 1 MPa (a 1 m x 1.5 m column): the upper block's sides and top moved
--      sideways at a slow rate, like a shear box, base fixed, to five times the peak shear
--      displacement. Each contact's tau against ks us while elastic (0.5 %), the
--      mean tau at full slip against sigma_n tan(phi) = 0.57735 MPa (0.5 %); with dilation 10 deg
--      the upper block rises by slip tan(psi) (1 %).
--   3. Tension: pulling the top up opens a joint of zero tensile strength with sigma_n = 0 exactly;
--      with tension = 0.5 MPa it holds to 0.5 MPa (0.5 %) and carries nothing once broken.
-- The box holds the upper block's sides down to 1 mm above the joint, so the normal stress along
-- the joint is nearly but not quite uniform while shearing; the checks are per contact or on
-- the sums, which hold all the same (c = 0: the sum of the Coulomb limits is tan(phi) times the
-- load).
local check = require "edem.check"

local E, nu, kn, ks, phi = 10e9, 0.25, 10e9, 1e9, 30

local function column(joint)
  model{ title = "two blocks: " .. joint.what }
  block{ x = {0, 1}, y = {0, joint.height or 2} }
  jset{ angle = 0, spacing = 10, origin = {0, 1} }
  zone{ edge = 0.1 }
  material{ "rock", density = 2600, young = E, poisson = nu }
  assign{ material = "rock" }
  joint_material{ "j", kn = kn, ks = ks, friction = phi, dilation = joint.dilation or 0,
                  tension = joint.tension or 0, cohesion = joint.cohesion or 0 }
  jassign{ material = "j" }
end

-- Length-weighted mean of f(c) over the contacts, and the largest |f(c) / expected - 1|.
local function over_contacts(f, expected)
  local sum, length, worst = 0, 0, 0
  for c in contacts() do
    sum = sum + f(c) * c.length
    length = length + c.length
    if expected then worst = math.max(worst, math.abs(f(c) / expected - 1)) end
  end
  return sum / length, worst
end

local function solved()
  local r = solve{ ratio = 1e-10, max_cycles = 200000 }
  if not r.converged then error("not solved: ratio " .. r.ratio) end
end

-- 1. Normal loading and unloading.
column{ what = "normal" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "left", fix = "x" }
local closure_up = {}
local worst = 0
for k = 1, 10 do
  local sigma = 0.1e6 * k
  boundary{ side = "top", stress = {0, -sigma, 0} }
  solved()
  local mean, w = over_contacts(function(c) return -c.un end, sigma / kn)
  closure_up[k] = mean
  worst = math.max(worst, w)
end
check.report("normal: mean closure at 1 MPa [m]", closure_up[10], 1e6 / kn, 0.005)
check.report("normal: worst contact closure, all steps (rel. error)", worst, 0, 0.005, { absolute = true })
check.report("normal: top settlement at 1 MPa [m]", -gp_near(0.5, 2).uy,
             1e6 * 2 * (1 - nu * nu) / E + 1e6 / kn, 0.005)
boundary{ side = "top", stress = {0, -0.5e6, 0} }
solved()
local down = over_contacts(function(c) return -c.un end)
check.report("normal: closure at 0.5 MPa, unloaded [m]", down, 0.5e6 / kn, 0.005)
check.report("normal: unloading against loading at 0.5 MPa", down, closure_up[5], 1e-4)

-- 2. Shear at constant normal stress, without and with dilation.
local tau_peak = 1e6 * math.tan(math.rad(phi))
local us_peak = tau_peak / ks
local rate = 2e-7  -- [m per cycle] (static mode)
for _, psi in ipairs({ 0, 10 }) do
  column{ what = "shear", dilation = psi, height = 1.5 }
  boundary{ side = "bottom", fix = "xy" }
  boundary{ side = "top", stress = {0, -1e6, 0} }
  solved()
  local upper = { {-0.1, 1.001}, {1.1, 1.001}, {1.1, 1.6}, {-0.1, 1.6} }  -- its sides and top
  local tau0 = {}
  for c in contacts() do tau0[c.id] = { c.tau, c.us } end
  boundary{ polygon = upper, xvel = rate }
  cycle(math.floor(0.4 * us_peak / rate))  -- about 40 % of the peak: all elastic
  local slope_worst = 0
  for c in contacts() do
    local t0 = tau0[c.id]
    if t0 and c.state ~= "slip" then
      -- tau is the stress on the gridpoint, against its shear displacement: tau = -ks us
      slope_worst = math.max(slope_worst, math.abs(-(c.tau - t0[1]) / (c.us - t0[2]) / ks - 1))
    end
  end
  local lift0, slip0 = gp_near(0.5, 1.5).uy, over_contacts(function(c) return c.slip end)
  cycle(math.floor(4.6 * us_peak / rate))
  local tau = over_contacts(function(c) return math.abs(c.tau) end)
  local sn = over_contacts(function(c) return -c.sn end)
  local label = ("shear, psi = %g: "):format(psi)
  check.report(label .. "worst elastic contact, tau / (ks us) - 1", slope_worst, 0, 0.005, { absolute = true })
  if psi == 0 then
    check.report(label .. "mean tau at full slip [Pa]", tau, tau_peak, 0.005)
  else
    -- Dilating at this rate, the upper block lags a few micrometres behind the opening and the
    -- joint is pressed 3.6 % harder than the 1 MPa on top; Coulomb holds at that stress.
    print(("  mean sigma_n while slipping %.6g Pa"):format(sn))
    check.report(label .. "mean tau / mean sigma_n at full slip", tau / sn, math.tan(math.rad(phi)), 0.005)
  end
  boundary{ polygon = upper, xvel = 0 }
  solved()
  if psi > 0 then
    local slip = over_contacts(function(c) return c.slip end) - slip0
    check.report(label .. "rise of the upper block [m]", gp_near(0.5, 1.5).uy - lift0,
                 slip * math.tan(math.rad(psi)), 0.01)
  end
end

-- 3. Pulling the blocks apart.
-- (A bond in tension needs cohesion too: with none, Coulomb gives it no shear strength under
-- tension, and the slightest shear breaks it, as in UDEC.)
for _, tension in ipairs({ 0, 0.5e6 }) do
  column{ what = "tension", tension = tension, cohesion = 2 * tension }
  boundary{ side = "bottom", fix = "xy" }
  local highest = 0
  every(1, function()
    local mean = over_contacts(function(c) return c.sn end)
    highest = math.max(highest, mean)
  end)
  boundary{ side = "top", yvel = 1e-8 }
  cycle(math.floor((tension * (1 / kn + 2 / E) + 5e-5) / 1e-8))
  boundary{ side = "top", yvel = 0 }
  solved()
  local states, sn_max = {}, 0
  for c in contacts() do
    states[c.state] = (states[c.state] or 0) + 1
    sn_max = math.max(sn_max, math.abs(c.sn))
  end
  local label = ("tension %g Pa: "):format(tension)
  check.report(label .. "largest |sigma_n| once open [Pa]", sn_max, 0, 0, { absolute = true })
  check.report(label .. "contacts not open", 0 + (states.elastic or 0) + (states.slip or 0) + (states.bonded or 0),
               0, 0, { absolute = true })
  if tension > 0 then check.report(label .. "strength [Pa]", highest, tension, 0.005) end
end
check.finish()
