-- Jaeger's single plane of weakness (Jaeger 1960; Jaeger, Cook & Zimmerman 2007, §4.7).
--
-- A sample with one through-going joint of dip beta' (the angle between sigma1, vertical, and the
-- joint's normal) slips on the joint when (compression positive, mu = tan phi_j)
--   sigma1 - sigma3 = 2 (c_j + mu sigma3) / ((1 - mu cot beta') sin 2 beta'),  phi_j < beta' < 90,
-- and fails through the intact rock (Mohr-Coulomb) at sigma1 = Kp sigma3 + UCS; its strength is
-- the smaller of the two. Cases:
--   (b) the seed materials, sigma3 = 0.5 MPa: intact c = 0.143 MPa, phi = 34, E = 415.52 MPa,
--       nu = 0.136; joint c_j = 0, phi_j = 31.2, kn = ks = 1880 MPa/m (the seed's kn; see below
--       for the seed's ks); beta' = 30, 40, 45, 50, 60.6, 70, 80 (intact 2.3065 MPa governs at
--       30, 40 and 80);
--   (a) Itasca's ubiquitous-joint UCS problem, sigma3 = 0: c = 2 kPa, phi = 40, tension 2.4 kPa,
--       c_j = 2 kPa, phi_j = 30; beta (from sigma1 to the PLANE) = 10 .. 60, beta' = 90 - beta
--       (intact 8.578 kPa governs at beta = 10, 45, 50, 60). E = 10 MPa, nu = 0.2 (the strength
--       does not depend on them); joint kn = ks = 1 GPa/m, 25 times E over the zone size.
-- The closed form is printed next to tabulated values: Itasca's for (a), worked by hand for (b)
-- (table_a, table_b below).
--
-- Sample: plane strain, W = 1 m by H = 3.5 m, the joint through the centre; tan(beta') W/2 < H/2
-- up to beta' = 74, so the joint leaves through the sides and the upper block is free to slide
-- under smooth platens. At beta' = 80 it leaves through the platens: both blocks are held by
-- both platens and cannot slide along it (kinematically locked), so the intact rock governs,
-- which is also the closed form's answer there (joint 2.482 MPa, 13.02 kPa). Smooth platens:
-- the base fixed in y, one point at its centre fixed in x, the top moved down; sides under
-- sigma3. For (b) the sample starts at the isotropic state, insitu sxx = syy = szz = -sigma3
-- (szz too: plane strain Mohr-Coulomb uses all three principal stresses, and an szz left at
-- nu (sxx + syy) would be the minor one and fail the rock at about 1.6 MPa), top under sigma3.
--
-- Loading: the top moves down in steps of 5 % of the elastic displacement at the intact
-- strength; after each step it is held and the model solved (ratio 1e-6), and
-- sigma1 = - area-weighted mean of the zones' syy (equilibrium makes it the platen stress) is
-- taken at equilibrium, so the peak does not depend on a loading rate. Driving the top at a
-- constant speed instead overshoots the peak by the resistance of the damping to the sliding
-- block: measured at beta' = 45 (b) with the seed's ks, peak 2.233 MPa at 2e-6 m/cycle, 2.102
-- at 5e-7 (expected 2.036). Each step moves the top at 1/40000 of that displacement per cycle:
-- four times faster, the sudden start of sliding shakes the (a) samples and zones far from the
-- joint yield (19 % of the area at zone edge 0.125 m). The run stops four steps after the secant stiffness has fallen below a fifth of the
-- elastic one (the peak passed, or the plateau reached).
--
-- Mode, from the state at the end of the run:
--   slip share = (mean joint slip since the confinement, length-weighted) sin(beta') / (platen
--                displacement beyond the elastic line): the part of the inelastic shortening
--                that the joint's slip explains, about 1 when the joint slides, 0 when it holds;
--   yielded    = area fraction of zones that yield or have yielded (state not "elastic").
-- Joint slip: slip share > 0.5 and yielded < 0.1. Intact: slip share < 0.1 and yielded > 0.25.
-- Anything else is "mixed" and counts as the wrong mode.
--
-- Tolerances: peak sigma1 within 2 % of min(joint, intact), and the mode right, for every case.
-- The stress is homogeneous, so what limits the accuracy is only this (measured):
--   * geometry: contacts act along the joint's current direction, which the elastic strain
--     turns (0.12 deg at beta' = 45 with the seed's E, strain 0.4 %), and the side loads act on
--     the sides' original lengths, while the zones keep the original geometry. The joint-slip
--     peaks of (b) come out 0.2 .. 0.9 % high, most at 45 deg, where the strength changes by
--     4 % per degree; with E, kn and ks ten times larger the error at 45 is 0.1 %, with a
--     hundred times 0.02 %. The strains of (a) are smaller: within 0.1 %.
--   * joint stiffness: with the seed's ks = 80.7 MPa/m the joint shears 10 mm elastically
--     before it slips; the stress around the joint's ends is then far from uniform, the rock
--     yields there first and the intact plateau at beta' = 30, 40 comes 1.1 % low, still
--     rising after twice the elastic shortening. With ks = kn it is within 0.1 %. In (a),
--     ks = kn = 1 GPa/m for the same reason: with the seed's kn / E and ks / E the ends of the
--     beta' = 80 joint, held by both platens, open and the rock fails at half its strength.
--   * brittle joints: the (a) joint keeps its cohesion once it slips (residual_cohesion =
--     cohesion), as Itasca's ubiquitous joints do, so that the peak is a plateau the 5 % steps
--     find. With EDEM's default (residual 0) the joint's ends, where it meets the free sides,
--     slip first, lose their cohesion and the joint unzips: measured with 0.3 % steps (and a
--     tensile strength of 1 Pa: with none, the contacts of the unstressed joint open from
--     round-off in the first cycle and lose their cohesion at once), peaks 1.4 % (zone edge
--     0.25 m) and 1.0 % (0.125 m) low at beta = 30, 0.9 % at 35; 3 .. 4 % with the seed's
--     kn / E and ks / E.
--   * the intact plateau: within 0.3 % below Kp sigma3 + UCS.
--   * zone edge 0.25 m: with 0.125 m the peaks of (b) and of the joint-slip cases of (a) agree
--     within 0.1 %, but the uniaxial intact cases of (a) come lower: the non-associated plastic
--     flow localises and the plateau wanders (-0.9 % without any joint), and at beta' = 80 the
--     joint's upper end, where its normal stress is only 3 % of sigma1, opens (no tensile
--     strength) and the rock around it yields first: -2.9 %.
local check = require "edem.check"

local W, H = 1.0, 3.5
local EDGE = 0.25   -- zone edge [m]
local RATIO = 1e-6  -- unbalanced-force ratio at each held step

local function intact_strength(rock, s3)
  local s = math.sin(math.rad(rock.friction))
  return (1 + s) / (1 - s) * s3 + 2 * rock.cohesion * math.cos(math.rad(rock.friction)) / (1 - s)
end

local function joint_strength(joint, s3, beta)
  if beta <= joint.friction or beta >= 90 then return math.huge end
  local mu = math.tan(math.rad(joint.friction))
  return s3 + 2 * (joint.cohesion + mu * s3) / ((1 - mu / math.tan(math.rad(beta))) * math.sin(math.rad(2 * beta)))
end

-- Builds the sample, confines it and returns the reference state for the measurements.
local function build(case)
  model{ title = case.label }
  block{ x = { -W / 2, W / 2 }, y = { 0, H } }
  jset{ angle = case.beta, spacing = 100, origin = { 0, H / 2 } }  -- dip beta', through the centre
  zone{ edge = EDGE }
  local r, j = case.rock, case.joint
  material{ "rock", model = "mohr", density = r.density, young = r.young, poisson = r.poisson,
            cohesion = r.cohesion, friction = r.friction, tension = r.tension }
  assign{ material = "rock" }
  joint_material{ "joint", kn = j.kn, ks = j.ks, friction = j.friction, cohesion = j.cohesion,
                  residual_cohesion = j.cohesion }
  jassign{ material = "joint" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ polygon = { { -0.01, -0.01 }, { 0.01, -0.01 }, { 0.01, 0.01 }, { -0.01, 0.01 } }, fix = "x" }
  local s3 = case.s3
  if s3 > 0 then
    insitu{ sxx = -s3, syy = -s3, szz = -s3 }
    boundary{ side = "left", stress = { -s3, 0, 0 } }
    boundary{ side = "right", stress = { -s3, 0, 0 } }
    boundary{ side = "top", stress = { 0, -s3, 0 } }
    local r = solve{ ratio = RATIO }
    if not r.converged then error(case.label .. ": confinement not solved") end
  end
  local slip0 = {}
  for c in contacts() do slip0[c.id] = c.slip end
  return { slip0 = slip0, top0 = gp_near(0, H).uy }
end

-- sigma1 (compression positive), the top's displacement, the joint's mean slip since the
-- confinement and the area fraction of yielded zones.
local function measure(base)
  local syy, area, yielded = 0, 0, 0
  for z in zones() do
    syy, area = syy + z.syy * z.area, area + z.area
    if z.state ~= "elastic" then yielded = yielded + z.area end
  end
  local slip, length = 0, 0
  for c in contacts() do
    slip = slip + (c.slip - (base.slip0[c.id] or 0)) * c.length
    length = length + c.length
  end
  return { s1 = -syy / area, u = base.top0 - gp_near(0, H).uy, slip = length > 0 and slip / length or 0,
           yielded = yielded / area }
end

-- Moves the top down by du (at most `speed` per cycle), holds it and solves; returns whether
-- the model came to equilibrium.
local function step(du, speed)
  local n = math.max(10, math.ceil(du / speed))
  boundary{ side = "top", yvel = -du / n }
  cycle(n)
  boundary{ side = "top", yvel = 0 }
  return solve{ ratio = RATIO, max_cycles = 100000 }.converged
end

local function run_case(case)
  local u_scale = (intact_strength(case.rock, case.s3) - case.s3) * H / case.rock.young
  local du, speed = 0.05 * u_scale, u_scale / 40000  -- [m], [m per cycle]
  local base = build(case)
  local first = measure(base)
  local prev, peak, k1, soft = first, first, nil, 0
  local last = first
  for _ = 1, 100 do
    if not step(du, speed) then  -- no equilibrium: the sample has collapsed
      print(("  %s: no equilibrium after u = %.4g mm: stopped"):format(case.label, last.u * 1e3))
      last = measure(base)
      break
    end
    last = measure(base)
    local k = (last.s1 - prev.s1) / (last.u - prev.u)
    k1 = k1 or k
    if last.s1 > peak.s1 then peak = last end
    if k < 0.2 * k1 then soft = soft + 1 end
    if soft >= 4 then break end
    prev = last
  end
  -- mode measures at the end of the run
  local inelastic = last.u - first.u - (last.s1 - first.s1) / k1
  local share = last.slip * math.sin(math.rad(case.beta)) / inelastic
  local mode = (share > 0.5 and last.yielded < 0.1) and "joint"
               or (share < 0.1 and last.yielded > 0.25) and "intact" or "mixed"
  return peak, { share = share, yielded = last.yielded, slip = last.slip, inelastic = inelastic, mode = mode }
end

local function run(label, rock, joint, s3, beta, table_value, unit, scale)
  local started = os.clock()
  local intact = intact_strength(rock, s3)
  local slip = joint_strength(joint, s3, beta)
  local expected = math.min(intact, slip)
  local expected_mode = slip < intact and "joint" or "intact"
  local peak, mode = run_case{ label = label, rock = rock, joint = joint, s3 = s3, beta = beta }
  print(("%s: joint %s %s (tabulated %s), intact %.5g; peak %.5g at u = %.4g mm"):format(
    label, slip < math.huge and ("%.5g"):format(slip / scale) or "inf", unit,
    table_value and ("%.5g"):format(table_value) or "-", intact / scale, peak.s1 / scale, peak.u * 1e3))
  print(("  mode %s (expected %s): slip share %.3f (slip %.3g mm, inelastic shortening %.3g mm), yielded %.3f; %.1f s"):format(
    mode.mode, expected_mode, mode.share, mode.slip * 1e3, mode.inelastic * 1e3, mode.yielded, os.clock() - started))
  check.report(label .. ": peak sigma1 [Pa]", peak.s1, expected, 0.02)
  check.report(label .. ": mode " .. expected_mode .. " (1 = right)", mode.mode == expected_mode and 1 or 0, 1, 0,
               { absolute = true })
end

local started = os.clock()

-- (b) the seed materials, sigma3 = 0.5 MPa.
local rock_b = { density = 1505, young = 415.52e6, poisson = 0.136, cohesion = 0.143e6, friction = 34,
                 tension = 0.0546e6 }
local joint_b = { kn = 1880e6, ks = 1880e6, friction = 31.2, cohesion = 0 }
local table_b = { [40] = 2.710, [45] = 2.0356, [50] = 1.750, [60.6] = 1.5750, [70] = 1.709, [80] = 2.482 }
for _, beta in ipairs({ 30, 40, 45, 50, 60.6, 70, 80 }) do
  run(("(b) beta' = %g"):format(beta), rock_b, joint_b, 0.5e6, beta, table_b[beta], "MPa", 1e6)
end

-- (a) Itasca, uniaxial; beta is measured from sigma1 to the joint's plane.
local rock_a = { density = 2000, young = 10e6, poisson = 0.2, cohesion = 2e3, friction = 40, tension = 2.4e3 }
local joint_a = { kn = 1e9, ks = 1e9, friction = 30, cohesion = 2e3 }
local table_a = { [10] = 13.02, [20] = 7.879, [30] = 6.928, [35] = 7.145, [40] = 7.879, [45] = 9.464, [50] = 13.02 }
for _, beta in ipairs({ 10, 20, 30, 35, 40, 45, 50, 60 }) do
  run(("(a) beta = %g (beta' = %g)"):format(beta, 90 - beta), rock_a, joint_a, 0, 90 - beta, table_a[beta], "kPa", 1e3)
end

print(("%.1f s"):format(os.clock() - started))
check.finish()
