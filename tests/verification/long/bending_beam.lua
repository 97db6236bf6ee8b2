-- A beam in three-point bending through a row of potential cracks whose cracks soften (cohesive,
-- joint_material{ fracture_energy }), judged at equilibrium (judge{ at = "equilibrium" }): its
-- load-deflection curve should not depend on how finely the deflection is applied.
--
-- Beam: S = 0.8 m span, D = 0.2 m deep, 0.9 m long, plane strain, zones of 0.01 m; elastic rock
-- (seed E = 415.52 MPa, nu = 0.136); one potential crack across the depth at mid-span, judged by the
-- seed strength (tension 0.0546 MPa, cohesion 0.143 MPa, friction 34 deg); its crack takes kn = ks
-- = 1880 MPa/m, the same strength and G = 20 J/m^2. The characteristic length E G / T^2 = 2.8 m is
-- 14 times the depth: the crack grows stably over much of the depth, and the peak lies well above
-- the load of the first crack, P_cr = 2 T D^2 / (3 S) (beam theory).
-- The supports are gridpoints of the bottom at x = +-S/2 (fixed in y; the left one in x too); a pad
-- 0.04 m wide on the top at mid-span is pushed down, in increments each pushed in 10 cycles, held
-- and solved to 1e-5, to eight times the deflection of P_cr: in 10 increments and in 1,000. The
-- load is the supports' reaction.
--
-- Checks: the load at each of the 10 deflections against the 1,000 increments' load at the same
-- deflection, within 2 % of the peak (the same states, whatever the steps to them); the two peaks
-- within 2 % of each other; the peak well above P_cr, and passed (the last load 5 % below it).
-- Two neighbouring sections that fail on one state would soften together, where on a fine path
-- the lower one softens and the upper one, broken later, unloads: judged at equilibrium the worst
-- of them breaks and the other is judged again (judge{ neighbours = "wait" }, the default there).
-- The crack grows a section at a time, and the fine path's load rises between breaks and drops
-- at each: a saw tooth whose teeth are as high as a section is long (0.0125 m sections, zones of
-- 0.02 m: 3 % teeth, and the 10 increments, which sample it at ten deflections only, peak 2.1 %
-- under the 1,000; 0.006 m sections: 1.3 %, of which 0.8 % is the sampling: printed as the 1,000
-- increments' own load where the 10 peaked). A crack judged past its strength starts at its law's
-- peak, not softened already (engine/contact/detect.cpp, cap_at_peak).
-- Label "long" (about nine minutes): ctest -L long -R bending_beam.
local check = require "edem.check"

local S, D, LENGTH = 0.8, 0.2, 0.9
local E, NU, TENSION = 415.52e6, 0.136, 0.0546e6
local KN, G = 1880e6, 20.0
local EDGE = 0.01
local RATIO = 1e-5
local PAD = { { -0.02 - 1e-4, D - 1e-4 }, { 0.02 + 1e-4, D - 1e-4 }, { 0.02 + 1e-4, D + 1e-4 }, { -0.02 - 1e-4, D + 1e-4 } }
local P_CR = 2 * TENSION * D * D / (3 * S)

local function around(x, y)
  local h = 1e-4
  return { { x - h, y - h }, { x + h, y - h }, { x + h, y + h }, { x - h, y + h } }
end

local function build(label)
  model{ title = label }
  block{ x = { -LENGTH / 2, LENGTH / 2 }, y = { 0, D } }
  crackseed{ angle = 90, spacing = 10, origin = { 0, D / 2 }, material = "strength", after = "crack" }
  zone{ edge = EDGE }
  material{ "rock", young = E, poisson = NU, density = 1505 }
  material{ "strength", model = "mohr", young = E, poisson = NU, cohesion = 0.143e6, friction = 34,
            tension = TENSION }
  assign{ material = "rock" }
  joint_material{ "crack", kn = KN, ks = KN, friction = 34, cohesion = 0.143e6, tension = TENSION,
                  fracture_energy = G }
  judge{ at = "equilibrium" }
  local left, right = gp_near(-S / 2, 0).position, gp_near(S / 2, 0).position
  boundary{ polygon = around(left.x, left.y), fix = "xy" }
  boundary{ polygon = around(right.x, right.y), fix = "y" }
  boundary{ polygon = PAD, fix = "y" }
end

-- The supports' reaction [N/m].
local function load()
  local p = 0
  for g in gridpoints() do
    if g.fixed_y and g.y < 0.5 * D then p = p - g.fy end
  end
  return p
end

-- Pushes the pad down by du at once (in 10 cycles), then holds it and solves.
local function step(du)
  boundary{ polygon = PAD, yvel = -du / 10 }
  cycle(10)
  boundary{ polygon = PAD, yvel = 0 }
  local r = solve{ ratio = RATIO, max_cycles = 100000 }
  if not r.converged then error(("the beam found no equilibrium at a deflection step of %g m"):format(du)) end
end

-- The loads after each of n increments to the deflection `reach`.
local function run(n, reach)
  local started = os.clock()
  build(("three-point bending, %d increments"):format(n))
  local loads = {}
  for k = 1, n do
    step(reach / n)
    loads[k] = load()
  end
  local peak = 0
  for _, p in ipairs(loads) do peak = math.max(peak, p) end
  print(("%d increments (%.0f s): %d zones, %d sections, %d broken; peak %.6g N/m (%.4f P_cr)"):format(
    n, os.clock() - started, info().zones, info().sections, info().cracks, peak, peak / P_CR))
  return loads, peak
end

-- The deflection at P_cr, from the stiffness of a small first step.
build("three-point bending, stiffness")
local probe = 1e-6
step(probe)
local stiffness = load() / probe
local reach = 8 * P_CR / stiffness
local beam_theory = 48 * E / (1 - NU * NU) * (D ^ 3 / 12) / S ^ 3
print(("stiffness %.6g N/m per m (beam theory, bending only: %.6g); P_cr %.6g N/m at %.4g mm"):format(
  stiffness, beam_theory, P_CR, 1e3 * reach / 8))

local coarse, coarse_peak = run(10, reach)
local fine, fine_peak = run(1000, reach)
local worst, at, coarse_at_peak = 0, 0, 1
for k = 1, 10 do
  local difference = math.abs(coarse[k] - fine[100 * k])
  print(("  deflection %.4f mm: %.6g N/m in 10 increments, %.6g N/m in 1000"):format(
    1e3 * reach * k / 10, coarse[k], fine[100 * k]))
  if difference > worst then worst, at = difference, k end
  if coarse[k] == coarse_peak then coarse_at_peak = k end
end
print(("largest difference at the same deflection: %.4g N/m at step %d of 10 (%.3g of the peak)"):format(
  worst, at, worst / fine_peak))
print(("peak in 10 increments %.6g N/m, in 1000 %.6g N/m (%.2f %% apart); the 1000 increments' load where the "
       .. "10 peaked %.6g N/m (%.2f %% below their own peak)"):format(coarse_peak, fine_peak,
       100 * (fine_peak - coarse_peak) / fine_peak, fine[100 * coarse_at_peak],
       100 * (fine_peak - fine[100 * coarse_at_peak]) / fine_peak))
check.report("load at the same deflection, worst of 10, over the peak", worst / fine_peak, 0, 0.02,
             { absolute = true })
check.report("peak in 10 increments against the peak in 1000", coarse_peak, fine_peak, 0.02)
check.report("cracked past its first crack: peak over P_cr above 1.2 (1 = yes)",
             fine_peak > 1.2 * P_CR and 1 or 0, 1, 0, { absolute = true })
check.report("peak passed: last load 5 % below it (1 = yes)", fine[1000] < 0.95 * fine_peak and 1 or 0, 1, 0,
             { absolute = true })
check.finish()
