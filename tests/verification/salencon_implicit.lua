-- Issue 7, acceptance 1: VERIFICATION.md §2, the circular tunnel in an elastic-perfectly plastic
-- Mohr-Coulomb medium (Salençon 1969), solved by the implicit prepass (prepass{}).
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
local shapes = require "edem.shapes"

local EDGE = tonumber(arg and arg[1]) or 0.05
local a, R, P0, G, K, c, phi = 1.0, 40.0, 30e6, 2.8e9, 3.9e9, 3.45e6, 30.0
local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
local sphi = math.sin(math.rad(phi))
local Kp = (1 + sphi) / (1 - sphi)
local sc = 2 * c * math.cos(math.rad(phi)) / (1 - sphi)
local H = sc / (Kp - 1)
local Pcr = (2 * P0 - sc) / (1 + Kp)
local R0 = a * ((2 / (Kp + 1)) * (P0 + H) / H) ^ (1 / (Kp - 1))

-- Closed form, compression positive: radial and hoop stress, and inward wall displacement.
local function stresses(r)
  if r <= R0 then return H * (r / a) ^ (Kp - 1) - H, Kp * H * (r / a) ^ (Kp - 1) - H end
  return P0 - (P0 - Pcr) * (R0 / r) ^ 2, P0 + (P0 - Pcr) * (R0 / r) ^ 2
end

local function wall_displacement(psi)
  local spsi = math.sin(math.rad(psi))
  local Kpsi = (1 + spsi) / (1 - spsi)
  local A, r = H, a
  local C1 = (1 - nu) * (1 + Kp * Kpsi) - nu * (Kp + Kpsi)
  return r / (2 * G) * ((P0 - Pcr) * (R0 / r) ^ (1 + Kpsi)
    - A * C1 / (Kp + Kpsi) * ((R0 / a) ^ (Kp - 1) * (R0 / r) ^ (Kpsi + 1) - (r / a) ^ (Kp - 1))
    + (P0 + H) * (1 - 2 * nu) * ((R0 / r) ^ (Kpsi + 1) - 1))
end

local function build(psi)
  model{ title = ("Salencon, implicit, psi = %g"):format(psi) }
  block(shapes.quarter_plate{ hole = a, size = R, segments = 64 })
  zone{ edge = EDGE, far = 4.0, growth = 0.06, near = { shapes.sector{ r1 = a, from = 0, to = 90, segments = 32 } } }
  material{ "rock", model = "mohr", density = 2600, bulk = K, shear = G, cohesion = c,
            friction = phi, dilation = psi, tension = 1e9 }
  assign{ material = "rock" }
  insitu{ sxx = -P0, syy = -P0, szz = -P0 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "right", stress = "insitu" }
  boundary{ side = "top", stress = "insitu" }
end

-- R0, ring stress errors and the wall displacement of a prepass result.
local function measure(pre)
  local area = {}
  for z in zones() do area[z.id] = z.area end
  local yielded, worst, worst_at = 0, 0, ""
  local rings = { [1.25] = { 0, 0, 0 }, [1.5] = { 0, 0, 0 }, [2.0] = { 0, 0, 0 }, [3.0] = { 0, 0, 0 } }
  for _, z in ipairs(pre.zones) do
    local r = math.sqrt(z.x * z.x + z.y * z.y)
    if z.state:find("shear") then yielded = math.max(yielded, r) end
    local sr, st = stresses(r)
    local cx, sy = z.x / r, z.y / r
    local nsr = -(z.sxx * cx * cx + z.syy * sy * sy + 2 * z.sxy * cx * sy)
    local nst = -(z.sxx * sy * sy + z.syy * cx * cx - 2 * z.sxy * cx * sy)
    if r >= 1.2 * a and r <= 5 * a then
      for _, e in ipairs({ math.abs(nsr - sr), math.abs(nst - st) }) do
        if e / P0 > worst then worst, worst_at = e / P0, ("r = %.2f"):format(r) end
      end
    end
    for radius, sums in pairs(rings) do
      if math.abs(r - radius) <= 0.05 * a then
        local w = area[z.id]
        sums[1], sums[2], sums[3] = sums[1] + (nsr - sr) * w, sums[2] + (nst - st) * w, sums[3] + w
      end
    end
  end
  print(("    worst single zone, 1.2a <= r <= 5a: |stress error| / P0 = %.3f at %s"):format(worst, worst_at))
  local ring_error = {}
  for radius, sums in pairs(rings) do
    ring_error[radius] = math.max(math.abs(sums[1] / sums[3]), math.abs(sums[2] / sums[3])) / P0
  end
  local u = 0.5 * (-pre.gridpoints[gp_near(a, 0).id].ux - pre.gridpoints[gp_near(0, a).id].uy)
  return yielded, ring_error, u
end

local function run(psi, steps)
  build(psi)
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
    check.report("psi = 0: plastic radius R0 [m]", yielded, R0, 0.03)
    for _, radius in ipairs({ 1.25, 1.5, 2.0, 3.0 }) do
      check.report(("psi = 0: mean stress error / P0 over the ring r = %.2f a"):format(radius),
                   ring_error[radius], 0, 0.03, { absolute = true })
    end
    check.report("psi = 0: wall displacement [m]", u, wall_displacement(0), 0.05)
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
check.report("psi = 30: plastic radius R0 [m]", yielded, R0, 0.03)
for _, radius in ipairs({ 1.25, 1.5, 2.0, 3.0 }) do
  check.report(("psi = 30: mean stress error / P0 over the ring r = %.2f a"):format(radius),
               ring_error[radius], 0, 0.03, { absolute = true })
end
check.report("psi = 30: wall displacement [m]", u, wall_displacement(30), 0.08)
newton_log(pre)
check.finish()
