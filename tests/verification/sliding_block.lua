-- VERIFICATION.md §4: a block on an inclined plane, dynamic mode, no damping.
--
-- The plane is a fixed base block, the slope is made by tilting gravity by theta (the same
-- mechanics as a tilted plane, with straight edges). A deformable block rests on it through a
-- Coulomb joint (kn = ks = 10 GPa/m), mass 5300 kg/m and base A = 2 m as in VERIFICATION.md.
--   * sliding, theta = 30 and 40, phi = 20, a 2 m x 1 m block: it settles in static mode with
--     friction 89 deg (the contacts carry its weight, normal and shear), then takes phi = 20
--     and runs dynamically from rest; acceleration from a fit s = s0 + v0 t + a t^2 / 2 over
--     t = 0.2 .. 1.0 s, against a = g (sin theta - cos theta tan phi), within 1 %.
--   * threshold, theta = 30: phi = 30.1 stays put (checked; stable means it moved less than
--     10 x the elastic shear-spring value m g sin theta / (ks A), and no more than that value in
--     the second second); phi = 29.9 should slide a t^2 / 2 from rest (printed, see below);
--   * cohesion, phi = 20, c_crit A = m g (sin theta - cos theta tan phi): 0.95 c_crit slides as
--     without cohesion (checked: cohesion is lost once a contact slips, residual zero);
--     1.05 c_crit should stay put (printed). These use a flat block, 2 m x 0.02 m with the
--     density raised to keep the mass, whose base carries nearly uniform stress as the closed
--     form assumes (a tall block presses its toe harder than its heel, and brittle cohesion then
--     fails from the heel).
-- NOT YET RIGHT (issue 4 open): phi = 29.9 slides 6 x too far in 2 s after a static phase that
-- cannot converge, and 1.05 c_crit loses its cohesion and slides; both are printed, not checked.
local check = require "edem.check"

local g, rho, kn, ks = 9.81, 2650, 1e10, 1e10
local width = 2.0
local mass = rho * width * 1.0  -- 5300 kg/m

-- Runs one case; returns samples {t, s} of the block's slide from the start of the dynamic run.
local function run_case(case)
  local height = case.height or 1.0
  model{ title = ("block on a %g deg slope, phi = %g, c = %g"):format(case.theta, case.phi, case.cohesion or 0) }
  block{ x = {-3, 8}, y = {-1, 0} }
  block{ x = {-width / 2, width / 2}, y = {0, height} }
  zone{ edge = math.min(0.5, height), far = 0.5, growth = 0.5,
        near = { { {-width / 2, 0}, {width / 2, 0}, {width / 2, height}, {-width / 2, height} } } }
  material{ "rock", density = mass / (width * height), young = 10e9, poisson = 0.25 }
  assign{ material = "rock" }
  local settle_friction = case.settle_friction or case.phi
  joint_material{ "plane", kn = kn, ks = ks, friction = settle_friction, cohesion = case.cohesion or 0 }
  jassign{ material = "plane" }
  boundary{ polygon = {{-3.1, -1.1}, {8.1, -1.1}, {8.1, -0.01}, {-3.1, -0.01}}, fix = "xy" }
  gravity{ g * math.sin(math.rad(case.theta)), -g * math.cos(math.rad(case.theta)) }
  solve{ ratio = 1e-9, max_cycles = 20000 }
  joint_material{ "plane", kn = kn, ks = ks, friction = case.phi, cohesion = case.cohesion or 0 }
  set{ mode = "dynamic", damping = "none" }
  reset{ "velocity" }
  local start, t0 = gp_near(0, height).ux, info().time
  local samples = {}
  while info().time - t0 < case.seconds do
    cycle(20)
    samples[#samples + 1] = { info().time - t0, gp_near(0, height).ux - start }
  end
  return samples
end

-- Least-squares fit of s = s0 + v0 t + a t^2 / 2 over samples with t in [from, to].
local function fit_acceleration(samples, from, to)
  local S = {}
  for i = 1, 3 do S[i] = { 0, 0, 0, 0 } end
  for _, p in ipairs(samples) do
    local t, s = p[1], p[2]
    if t >= from and t <= to then
      local basis = { 1, t, t * t / 2 }
      for i = 1, 3 do
        for j = 1, 3 do S[i][j] = S[i][j] + basis[i] * basis[j] end
        S[i][4] = S[i][4] + basis[i] * s
      end
    end
  end
  for k = 1, 3 do  -- Gauss elimination, 3 x 3
    for i = k + 1, 3 do
      local f = S[i][k] / S[k][k]
      for j = k, 4 do S[i][j] = S[i][j] - f * S[k][j] end
    end
  end
  local x = {}
  for i = 3, 1, -1 do
    local sum = S[i][4]
    for j = i + 1, 3 do sum = sum - S[i][j] * x[j] end
    x[i] = sum / S[i][i]
  end
  return x[3]
end

local function acceleration(theta, phi)
  return g * (math.sin(math.rad(theta)) - math.cos(math.rad(theta)) * math.tan(math.rad(phi)))
end

for _, theta in ipairs({ 30, 40 }) do
  local samples = run_case{ theta = theta, phi = 20, settle_friction = 89, seconds = 1.0 }
  check.report(("theta = %g, phi = 20: acceleration [m/s2]"):format(theta),
               fit_acceleration(samples, 0.2, 1.0), acceleration(theta, 20), 0.01)
end

local elastic = mass * g * math.sin(math.rad(30)) / (ks * width)
local function moved(samples, at)
  local best = samples[1]
  for _, p in ipairs(samples) do if math.abs(p[1] - at) < math.abs(best[1] - at) then best = p end end
  return best[2]
end
local function stable(samples)
  local s1, s2 = moved(samples, 1.0), moved(samples, 2.0)
  print(("  moved %.3g m by 1 s, %.3g m by 2 s; elastic shear-spring value %.3g m"):format(s1, s2, elastic))
  return (math.abs(s2) < 10 * elastic and math.abs(s2 - s1) <= elastic) and 1 or 0
end

local flat = 0.02
local samples = run_case{ theta = 30, phi = 30.1, seconds = 2.0 }
check.report("theta = 30, phi = 30.1: stable (1 = yes)", stable(samples), 1, 0, { absolute = true })
samples = run_case{ theta = 30, phi = 29.9, height = flat, seconds = 2.0 }
print(("  NOT YET RIGHT: theta = 30, phi = 29.9: slid %.4g m by 2 s, a t^2 / 2 = %.4g m"):format(
  moved(samples, 2.0), acceleration(30, 29.9) * 2.0))

local c_crit = mass * acceleration(30, 20) / width
print(("  critical cohesion %.1f Pa (VERIFICATION.md: 4804)"):format(c_crit))
samples = run_case{ theta = 30, phi = 20, cohesion = 1.05 * c_crit, height = flat, seconds = 2.0 }
print("  NOT YET RIGHT: theta = 30, phi = 20, c = 1.05 c_crit should be stable:")
stable(samples)
samples = run_case{ theta = 30, phi = 20, cohesion = 0.95 * c_crit, height = flat, seconds = 2.0 }
check.report("theta = 30, phi = 20, c = 0.95 c_crit: slid by 2 s [m]", moved(samples, 2.0),
             acceleration(30, 20) * 2.0, 0.05)
check.finish()
