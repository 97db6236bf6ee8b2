-- A bar pulled in tension through a potential crack whose crack softens (a cohesive crack,
-- joint_material{ fracture_energy }): the energy it takes to break does not depend on the zones.
--
-- Hillerborg's cohesive crack, linear: past its tensile strength T the crack's traction falls
-- linearly with its opening w (past the elastic) to 0 at w_c = 2 G / T, G the fracture energy.
-- The section breaks at sigma_t = T (the rock's strength and the crack's are the same) and its
-- crack starts bonded, carrying the section's traction; as a penalty contact it is already open
-- by T / kn then, elastically, so the work the bar takes from the onset to its end is
--   W (G - T^2 / (2 kn))  per unit thickness (W the width),
-- whatever the zone size, and the elastic energy of the bar comes back as the load falls.
-- Pulled on at the top by u past the onset, the bar's stress on the falling branch is
--   sigma(u_p) = T (1 - u_p / (D - T H / E')),  D = w_c - T / kn,  E' = E / (1 - nu^2),
-- u_p the top's displacement past its value at the onset (the crack opens by D while the bar
-- gives back its elastic elongation T H / E').
--
-- Bar: W = 0.2 m by H = 1 m, elastic rock (seed E = 415.52 MPa, nu = 0.136) with one potential
-- crack across it at mid-height, judged by the seed strength (sigma_t = 0.0546 MPa); its crack
-- takes kn = ks = 1880 MPa/m, tension 0.0546 MPa, cohesion 0.143 MPa, friction 34 deg and
-- G = 20 J/m^2 (w_c = 0.73 mm). The base is fixed in y (its centre in x), the top pulled in
-- steps, each held and solved: to 90 % of the onset, then slowly until the crack forms, then in
-- steps of a tenth of the elastic elongation at the onset until the stress is gone.
-- Twice: zones of edge 0.05 m and 0.025 m.
-- Tolerances: onset 1 %; the work 1 %; the stress half way down the falling branch 1 % of T;
-- nothing carried at the end (1e-6 T) and every contact open. At 0.05 m the work is within 1e-4
-- (the trapezoid across the two kinks). At 0.025 m one edge along the crack is twice as long as
-- the others, and the contacts beside it take about a quarter less than the section's traction
-- when they are made (their share of its nodal force over their length): they open further
-- before their strength runs out: the work is 0.7 % more, and the stress half way down 0.5 % of
-- T higher.
local check = require "edem.check"

local W, H = 0.2, 1.0
local E, NU, TENSION = 415.52e6, 0.136, 0.0546e6
local KN, G = 1880e6, 20.0
local RATIO = 1e-7
local E_PLANE = E / (1 - NU * NU)

local function platen_stress()  -- the zones' mean syy, tension positive [Pa]
  local syy, area = 0, 0
  for z in zones() do syy, area = syy + z.syy * z.area, area + z.area end
  return syy / area
end
local function top() return gp_near(0, H).uy end

local function pull(edge)
  model{ title = ("cohesive crack, zones of %g m"):format(edge) }
  block{ x = { -W / 2, W / 2 }, y = { 0, H } }
  crackseed{ angle = 0, spacing = 10, origin = { 0, H / 2 }, material = "strength", after = "crack" }
  zone{ edge = edge }
  material{ "rock", young = E, poisson = NU, density = 1505 }
  material{ "strength", model = "mohr", young = E, poisson = NU, cohesion = 0.143e6, friction = 34,
            tension = TENSION }
  assign{ material = "rock" }
  joint_material{ "crack", kn = KN, ks = KN, friction = 34, cohesion = 0.143e6, tension = TENSION,
                  fracture_energy = G }
  judge{ every = 10 }
  boundary{ side = "bottom", fix = "y" }
  local base = gp_near(0, 0).position
  boundary{ polygon = { { base.x - 0.005, -0.005 }, { base.x + 0.005, -0.005 }, { base.x + 0.005, 0.005 },
                        { base.x - 0.005, 0.005 } }, fix = "x" }

  -- The work of the top on the bar per unit thickness, by the trapezoid over solved states.
  local work, last_u, last_s = 0, top(), platen_stress()
  local function record()
    local u, s = top(), platen_stress()
    work = work + 0.5 * (s + last_s) * W * (u - last_u)
    last_u, last_s = u, s
  end
  local function step(du, speed)
    local n = math.max(10, math.ceil(math.abs(du) / speed))
    boundary{ side = "top", yvel = du / n }
    cycle(n)
    boundary{ side = "top", yvel = 0 }
    solve{ ratio = RATIO, max_cycles = 200000 }
    record()
  end

  local reach = TENSION * H / E_PLANE  -- elongation at the onset [m]
  while platen_stress() < 0.9 * TENSION and info().cracks == 0 do step(0.05 * reach, reach / 40000) end
  local at_crack
  local watch = every(10, function() if info().cracks > 0 and not at_crack then at_crack = platen_stress() end end)
  while info().cracks == 0 do step(0.005 * reach, reach / 400000) end
  cancel(watch)
  local onset_u, onset_work = top(), work
  -- Down the falling branch; its stress half way down against the closed form.
  local D = 2 * G / TENSION - TENSION / KN
  local slope_u = D - TENSION * H / E_PLANE  -- u past the onset where sigma would reach 0
  local half = { u = 0, s = 0, expected = 0 }
  local bonded = 1
  while bonded > 0 do
    step(0.1 * reach, reach / 20000)
    local past = top() - onset_u
    if past < 0.5 * slope_u then
      half = { u = past, s = platen_stress(), expected = TENSION * (1 - past / slope_u) }
    end
    bonded = 0
    for c in contacts() do if c.state ~= "open" then bonded = bonded + 1 end end
  end
  step(reach, reach / 40000)  -- and on, open
  local open, all = 0, 0
  for c in contacts() do
    all = all + 1
    if c.state == "open" then open = open + 1 end
  end
  print(("zones of %g m: %d zones, %d sections; onset at %.6g Pa; half way down, %.4g mm past the "
         .. "onset: %.6g Pa (closed form %.6g); work %.6g J/m, %.6g of it to the onset (elastic %.6g)"):format(
         edge, info().zones, info().sections, at_crack, half.u * 1e3, half.s, half.expected, work, onset_work,
         0.5 * W * TENSION * TENSION * H / E_PLANE))
  return { onset = at_crack, work = work, half = half, final = platen_stress(), open = open, all = all,
           broken = info().cracks, sections = info().sections }
end

local expected_work = W * (G - TENSION * TENSION / (2 * KN))
for _, edge in ipairs({ 0.05, 0.025 }) do
  local r = pull(edge)
  local tag = ("zones %g m: "):format(edge)
  check.report(tag .. "stress at the crack [Pa]", r.onset, TENSION, 0.01)
  check.report(tag .. "every section broken (1 = yes)", r.broken == r.sections and 1 or 0, 1, 0, { absolute = true })
  check.report(tag .. "stress half way down the falling branch [Pa]", r.half.s, r.half.expected, 0.01 * TENSION,
               { absolute = true })
  check.report(tag .. "work to break the bar [J/m]", r.work, expected_work, 0.01)
  check.report(tag .. "stress once broken [Pa]", r.final, 0, 1e-6 * TENSION, { absolute = true })
  check.report(tag .. "contacts open (1 = every one)", (r.open > 0 and r.open == r.all) and 1 or 0, 1, 0,
               { absolute = true })
end
check.finish()
