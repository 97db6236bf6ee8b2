-- The circular tunnel in an elastic-perfectly plastic Mohr-Coulomb medium (Salençon 1969;
-- stdlib/edem/salencon.lua), solved by the implicit prepass (prepass{}).
--
-- The explicit test's model (tests/verification/salencon.lua): quarter model, a = 1 m, outer
-- boundary at 40 a loaded with P0 = 30 MPa, rollers on the axes, Pi = 0; G = 2.8 GPa, K = 3.9 GPa,
-- c = 3.45 MPa, phi = 30 deg, psi = 0 and 30 deg; zones EDGE at the wall. The in-situ stress is
-- the prepass's start; the wall's out-of-balance force (P0 on a traction-free wall) comes off in
-- load steps. Checks: plastic radius R0 (3 %), mean stress error over rings of zones at r = 1.25,
-- 1.5, 2 and 3 a (3 % of P0), wall displacement (5 % for psi = 0, 8 % for psi = 30); with psi = 0,
-- the answers in 1, 10 and 100 load steps agree within 1 %; Newton's residual falls
-- quadratically near the solution: the last load step's residuals are printed, and the check is
-- that the last ratio r(k+1) / r(k)^2 stays bounded (quadratic) where the residual goes below 1e-4.
local check = require "edem.check"
local salencon = require "edem.salencon"

local EDGE = tonumber(arg and arg[1]) or 0.05

-- R0, ring stress errors and the wall displacement of a prepass result.
local function measure(pre)
  local area = {}
  for z in zones() do area[z.id] = z.area end
  local yielded, ring_error, worst, worst_at = salencon.measure(pre.zones, area)
  print(("    worst single zone, 1.2a <= r <= 5a: |stress error| / P0 = %.3f at %s"):format(worst, worst_at))
  local a = salencon.a
  local u = 0.5 * (-pre.gridpoints[gp_near(a, 0).id].ux - pre.gridpoints[gp_near(0, a).id].uy)
  return yielded, ring_error, u
end

local function run(psi, steps)
  salencon.build{ psi = psi, edge = EDGE }
  local pre = prepass{ steps = steps }
  local s = pre.stages[1]
  print(("  psi = %g, %d load steps: %d zones, %d Newton iterations, %d cut-backs, %.2f s"):format(
    psi, steps, info().zones, s.iterations, s.cutbacks, s.seconds))
  return pre
end

-- Newton near the solution: the residuals of the last load step, and whether they fall
-- quadratically once below 1e-4 of the force scale (r(k+1) <= C r(k)^2 with C bounded).
local function newton_log(pre)
  local steps = pre.stages[1].steps
  local last = steps[#steps].residuals
  local text = {}
  for _, r in ipairs(last) do text[#text + 1] = ("%.2e"):format(r) end
  print("    last load step, |out-of-balance| / force scale per Newton iterate: " .. table.concat(text, "  "))
  local worst = 0
  for _, step in ipairs(steps) do
    local r = step.residuals
    for k = 1, #r - 1 do
      if r[k] < 1e-4 and r[k + 1] > 1e-13 then worst = math.max(worst, r[k + 1] / r[k] ^ 2) end
    end
  end
  return worst
end

local displacement = {}
for _, steps in ipairs({ 1, 10, 100 }) do
  local pre = run(0, steps)
  local yielded, ring_error, u = measure(pre)
  displacement[steps] = u
  if steps == 10 then
    check.report("psi = 0: plastic radius R0 [m]", yielded, salencon.R0, 0.03)
    for _, radius in ipairs({ 1.25, 1.5, 2.0, 3.0 }) do
      check.report(("psi = 0: mean stress error / P0 over the ring r = %.2f a"):format(radius),
                   ring_error[radius], 0, 0.03, { absolute = true })
    end
    check.report("psi = 0: wall displacement [m]", u, salencon.wall_displacement(0), 0.05)
    -- Quadratic: r(k+1) / r(k)^2 bounded. Linear convergence at rate q would give q / r(k), which
    -- grows past 1e3 as r(k) falls below 1e-4; quadratic keeps it at the tangent's constant.
    check.report("psi = 0: Newton, largest r(k+1) / r(k)^2 below r = 1e-4 (quadratic: bounded)",
                 newton_log(pre), 0, 1e3, { absolute = true })
  end
end
check.report("psi = 0: wall displacement, 1 load step against 10", displacement[1], displacement[10], 0.01)
check.report("psi = 0: wall displacement, 100 load steps against 10", displacement[100], displacement[10], 0.01)

local pre = run(30, 10)
local yielded, ring_error, u = measure(pre)
check.report("psi = 30: plastic radius R0 [m]", yielded, salencon.R0, 0.03)
for _, radius in ipairs({ 1.25, 1.5, 2.0, 3.0 }) do
  check.report(("psi = 30: mean stress error / P0 over the ring r = %.2f a"):format(radius),
               ring_error[radius], 0, 0.03, { absolute = true })
end
check.report("psi = 30: wall displacement [m]", u, salencon.wall_displacement(30), 0.08)
newton_log(pre)
check.finish()
