-- The explicit cycle as a time integrator (central differences), in dynamic mode (real masses,
-- no damping).
--
-- A triangle (0,0) (1,0) (0,1), zoned, every gridpoint fixed but the top corner, which moves in
-- y only: one degree of freedom with k = sum over its zones of A (e1 c^2 + G b^2) (b, c: the
-- corner's shape function gradient, e1 = K + 4G/3) and the lumped mass m = sum rho A / 3,
-- both computed here from the zones' corners. An initial syy pushes it off equilibrium
-- (k u = the force of syy on the corner).
-- Checks: with a forced step at omega dt = 0.2 the period is the discrete leapfrog period
-- 2 pi dt / acos(1 - (omega dt)^2 / 2) within 0.01 %; a forced step of 1.05 x critical is caught
-- by the watchdog (the run stops with a message, no NaN is left); the automatic step is below
-- the critical 2 / omega (0.9 of it: the Gershgorin bound is exact for one degree of freedom).
local check = require "edem.check"

local young, poisson, density, syy = 1e9, 0.25, 3000, -1e6
local K = young / (3 * (1 - 2 * poisson))
local G = young / (2 * (1 + poisson))
local e1 = K + 4 * G / 3

local function one_dof()
  model{ title = "1-DOF" }
  block{ { 0, 0 }, { 1, 0 }, { 0, 1 } }
  zone{ edge = 10 }
  material{ "rock", model = "elastic", density = density, young = young, poisson = poisson }
  assign{ material = "rock" }
  boundary{ polygon = { { -1, -1 }, { 2, -1 }, { 2, 0.9 }, { -1, 0.9 } }, fix = "xy" }
  boundary{ side = "top", fix = "x" }
  insitu{ sxx = 0, syy = syy, sxy = 0, szz = 0 }
  set{ mode = "dynamic" }
end

-- k and m of the free corner, from the zones' corners (each zone is matched to the three
-- gridpoints whose centroid and area it has).
local function stiffness_and_mass()
  local points = {}
  for p in gridpoints() do points[#points + 1] = { p.x, p.y } end
  local k, m, force = 0, 0, 0
  for z in zones() do
    local found = false
    for i = 1, #points do
      for j = i + 1, #points do
        for l = j + 1, #points do
          local a, b, c = points[i], points[j], points[l]
          local cx, cy = (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3
          local area = 0.5 * ((b[1] - a[1]) * (c[2] - a[2]) - (c[1] - a[1]) * (b[2] - a[2]))
          if not found and math.abs(cx - z.x) < 1e-12 and math.abs(cy - z.y) < 1e-12
             and math.abs(math.abs(area) - z.area) < 1e-12 then
            found = true
            for _, corner in ipairs({ { a, b, c }, { b, c, a }, { c, a, b } }) do
              local p, q, r = corner[1], corner[2], corner[3]
              if p[1] == 0 and p[2] == 1 then
                local gx, gy = (q[2] - r[2]) / (2 * area), (r[1] - q[1]) / (2 * area)
                k = k + z.area * (e1 * gy * gy + G * gx * gx)
                m = m + density * z.area / 3
                force = force - z.area * syy * gy
              end
            end
          end
        end
      end
    end
    assert(found, "a zone's corners were not found")
  end
  return k, m, force
end

one_dof()
local k, m, force = stiffness_and_mass()
local equilibrium = force / k  -- where the corner comes to rest: k u = the initial force
local omega = math.sqrt(k / m)
local critical = 2 / omega
print(("  %d zones; the free corner: k = %.9g N/m, m = %.9g kg, critical step %.6g s"):format(
  info().zones, k, m, critical))

-- 1. The period at omega dt = 0.2, from the upward crossings of the equilibrium over ~100 periods.
-- (Measured every cycle from rest: the watchdog must not take the start for an instability.)
local step = 0.2 / omega
set{ step = step }
local top = gp_near(0, 1)
local crossings, previous = {}, top.uy - equilibrium
every(1, function()
  local now = gp_near(0, 1).uy - equilibrium
  if previous < 0 and now >= 0 then
    local t = info().time
    crossings[#crossings + 1] = t - step * now / (now - previous)
  end
  previous = now
end)
cycle(3200)
local measured = (crossings[#crossings] - crossings[1]) / (#crossings - 1)
local discrete = 2 * math.pi * step / math.acos(1 - 0.5 * 0.2 * 0.2)
print(("  %d periods; exact continuous period %.9g s"):format(#crossings - 1, 2 * math.pi / omega))
check.report("period at omega dt = 0.2 [s]", measured, discrete, 1e-4)

-- 2. A forced step of 1.05 x critical: the watchdog stops the run and names the cause.
one_dof()
set{ step = 1.05 * critical }
local ok, message = pcall(cycle, 100000)
print("  watchdog: " .. tostring(message))
check.report("forced step 1.05 x critical is stopped (1 = stopped)",
             (not ok and message:find("unstable") and message:find("forced time step")) and 1 or 0, 1, 0,
             { absolute = true })
-- |lambda| of lambda^2 - (2 - (omega dt)^2) lambda + 1 = 0 at omega dt = 2.1; energy grows as its square.
local b = 2 - 2.1 * 2.1
local lambda = math.abs((b - math.sqrt(b * b - 4)) / 2)
check.report("kinetic energy growth per cycle at 1.05 x critical", tonumber(message:match("%(([%d%.]+)x per cycle%)")),
             lambda * lambda, 0.01)
check.report("cycles before it stopped (below 200)", info().cycle < 200 and 1 or 0, 1, 0, { absolute = true })
local finite = true
for p in gridpoints() do
  for _, value in ipairs({ p.ux, p.uy, p.vx, p.vy }) do
    if value ~= value or math.abs(value) == math.huge then finite = false end
  end
end
check.report("every gridpoint value still finite (1 = yes)", finite and 1 or 0, 1, 0, { absolute = true })

-- 3. The automatic step: at most the critical one (0.9 of the Gershgorin bound, exact here).
one_dof()
cycle(1)
print(("  automatic step %.6g s, critical %.6g s"):format(info().step, critical))
check.report("automatic step / critical step (at most 1)", info().step / critical, 0.9, 1e-9)
check.finish()
