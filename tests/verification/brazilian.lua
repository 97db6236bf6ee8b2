-- The Brazilian disc, with potential cracks.
--
-- Closed form: a disc of diameter D under a diametral load P (per unit thickness) has a
-- uniform tension 2P/(pi D) across its loaded diameter (Hertz, point loads); it splits when that
-- reaches sigma_t: F = pi D sigma_t / 2 = 85 765 N/m for D = 1 m and the seed's sigma_t =
-- 0.0546 MPa. Loaded over arcs of 2 alpha, the centre's tension is a little lower (Hondros:
-- (sin 2 alpha - alpha) / alpha of it for a uniform pressure, 0.977 at 2 alpha = 15 deg), and
-- the compression near the arcs is spread enough that the rock does not crush there first
-- (2 alpha = 10-15 deg, the usual range).
--
-- Disc: D = 1 m, a 120-gon, elastic rock (seed E = 415.52 MPa, nu = 0.136), zones of edge
-- D / 40; potential cracks in two sets, vertical and horizontal, D / 20 apart, one set on the
-- loaded diameter, judged every 10 cycles by the seed strength (c = 0.143 MPa, phi = 34 deg,
-- sigma_t = 0.0546 MPa). Curved rigid jaws over arcs of 2 alpha = 15 deg at the top and the
-- bottom, smooth (the disc's gridpoints under them are held in y only; the loaded diameter's two
-- ends in x, as symmetry holds them): the bottom one fixed,
-- the top one pushed down in steps, each a slow push then held and solved (ratio 1e-6); the
-- load is the bottom jaw's reaction at equilibrium (a load read while the jaw moves lags the
-- stress inside: the damping that takes the disc to equilibrium drags on it). Steps of 20 % of
-- the displacement expected at F up to 80 %, then of 1 % until the disc has split (tension
-- cracks over 90 % of the loaded diameter), its load has fallen below half the peak, or 30 steps
-- after the first crack. Under the jaws' even displacement the load gathers at their ends and the
-- centre's tension is 0.953 of 2P/(pi D) (measured, elastic), so the disc should split at about
-- F / 0.953 = 1.05 F; it does at 1.04 F with either criterion.
--
-- Judged at equilibrium (judge{ at = "equilibrium" }, criterion (i)): the same steps, each pushed at
-- once and solved, and the load in one step: the jaw pushed at once to a displacement on a fresh
-- disc, the least that cracks it bisected; the peak load so found against F and against the steps'.
--
-- Two criteria, since the seed's "principal stresses acting on each potential crack" (its §2.3)
-- reads either way: (i) the built-in one on the principal stresses at a section's point, whatever
-- the section's direction; (ii) a Lua criterion on the tractions on the section's own plane
-- (tension when sn > sigma_t, shear when |tau| > c - sn tan phi).
--
-- Checks, for each: the peak load within 10 % of F (DEM and bonded-particle Brazilian tests
-- land within 5-20 % of it, the peak depending on the loading arcs and the mesh); the first crack
-- (the sections broken at the first judgment that broke any) in tension, its sections within
-- D / 10 of the loaded diameter and D / 4 of the centre (the tension along the loaded diameter
-- is within 3 % of its centre value out to a quarter of D from it, so which of those breaks first
-- is the mesh's choice); under (ii) every first section lies along the diameter (vertical); and
-- the disc split: when the load has dropped, tension cracks run along the diameter over at least
-- 90 % of D.
local check = require "edem.check"

local R, EDGE, ALPHA = 0.5, 0.025, 7.5
local E, NU = 415.52e6, 0.136
local ROCK = { cohesion = 0.143e6, friction = 34, tension = 0.0546e6 }
local F = math.pi * 2 * R * ROCK.tension / 2
local RATIO = 1e-6

-- The jaws: the disc's boundary gridpoints within alpha of the vertical, above and below.
local HALF = R * math.sin(math.rad(ALPHA)) + 1e-3
local LOW = R * math.cos(math.rad(ALPHA)) - 1e-3
local TOP = { { -HALF, LOW }, { HALF, LOW }, { HALF, R + 0.01 }, { -HALF, R + 0.01 } }
local BOTTOM = { { -HALF, -LOW }, { -HALF, -R - 0.01 }, { HALF, -R - 0.01 }, { HALF, -LOW } }

local function build(label, criterion, at)
  model{ title = label }
  local outline = {}
  -- Vertices at 1.5 + 3 k deg: the jaws' ends (at 90 +- 7.5 deg) are vertices, and no vertex
  -- lies on a cut's line where it would only touch the disc.
  for k = 0, 119 do
    local t = math.rad(1.5 + 3 * k)
    outline[#outline + 1] = { R * math.cos(t), R * math.sin(t) }
  end
  block(outline)
  crackseed{ angles = { 0, 90 }, spacing = 2 * EDGE, origin = { 0, 0 }, material = "strength", after = "crack" }
  zone{ edge = EDGE }
  material{ "rock", young = E, poisson = NU, density = 2650 }
  material{ "strength", model = "mohr", young = E, poisson = NU, cohesion = ROCK.cohesion, friction = ROCK.friction,
            tension = ROCK.tension }
  assign{ material = "rock" }
  joint_material{ "crack", kn = 100e9, ks = 100e9, friction = 31.2 }
  if at == "equilibrium" then
    judge{ at = "equilibrium", criterion = criterion }
  else
    judge{ every = 10, criterion = criterion }
  end
  boundary{ polygon = BOTTOM, fix = "y" }
  -- The loaded diameter's ends held in x too, as symmetry holds them: with only one, the disc
  -- rocks about it on the top jaw's arc, a mode soft enough that the solves crawl to their ratio.
  local tip = 1e-3
  boundary{ polygon = { { -tip, -R - tip }, { tip, -R - tip }, { tip, -LOW }, { -tip, -LOW } }, fix = "x" }
  boundary{ polygon = TOP, fix = "y" }
  boundary{ polygon = { { -tip, LOW }, { tip, LOW }, { tip, R + tip }, { -tip, R + tip } }, fix = "x" }
end

-- The bottom jaw's reaction [N/m]: the vertical force of its gridpoints, each node once (the
-- two faces of an intact potential crack share one).
local function load()
  local seen, p = {}, 0
  for g in gridpoints() do
    if g.fixed_y and g.y < 0 then
      local key = ("%.12g %.12g"):format(g.x, g.y)
      if not seen[key] then seen[key], p = true, p - g.fy end
    end
  end
  return p
end

-- Pushes the top jaw down by du, slowly, then holds it and solves.
local function step(du, speed)
  local n = math.max(10, math.ceil(du / speed))
  boundary{ polygon = TOP, yvel = -du / n }
  cycle(n)
  boundary{ polygon = TOP, yvel = 0 }
  return solve{ ratio = RATIO, max_cycles = 10000 }
end

-- The length of the tension cracks on the loaded diameter [m].
local function split_length()
  local length = 0
  for c in cracks() do
    if c.angle == 90 and math.abs(c.x) < 1e-9 and c.mode == "tension" then length = length + c.length end
  end
  return length
end

-- The displacement at F, from the stiffness of a first small step.
local function reach_of_F()
  local probe = 1e-5
  step(probe, probe / 200)
  return probe * F / load(), probe
end

-- Judged every 10 cycles the jaw must move slowly (a load read while it moves lags the stress
-- inside); judged at equilibrium it moves each step at once (in 10 cycles).
local function run(label, criterion, at)
  local started = os.clock()
  build(label, criterion, at)
  local slow = at ~= "equilibrium"
  local reach, pushed = reach_of_F()
  local peak, at_peak, before = 0, 0, 0
  for k = 1, 4 do
    step(0.2 * k * reach - pushed, slow and reach / 4000 or reach)
    pushed = 0.2 * k * reach
  end
  local steps, cracked = 0, nil
  while steps < 60 do
    local p = load()
    if info().cracks == 0 then before = p end
    if p > peak then peak, at_peak = p, pushed end
    cracked = cracked or (info().cracks > 0 and steps)
    if cracked and (p < 0.5 * peak or split_length() >= 0.9 * 2 * R or steps - cracked >= 30) then break end
    step(0.01 * reach, slow and reach / 40000 or reach)
    pushed, steps = pushed + 0.01 * reach, steps + 1
  end
  -- The first crack: the sections broken at the first judgment that broke any.
  local first, cycle0 = {}, nil
  for c in cracks() do
    cycle0 = cycle0 or c.cycle
    if c.cycle == cycle0 then first[#first + 1] = c end
  end
  local tension, near_axis, near_centre, vertical = 0, 0, 0, 0
  for _, c in ipairs(first) do
    if c.mode == "tension" then tension = tension + 1 end
    if math.abs(c.x) <= 0.1 * 2 * R then near_axis = near_axis + 1 end
    if math.sqrt(c.x ^ 2 + c.y ^ 2) <= 0.25 * 2 * R then near_centre = near_centre + 1 end
    if c.angle == 90 and math.abs(c.x) < 1e-9 then vertical = vertical + 1 end
  end
  local split, after = split_length(), load()
  print(("%s (%.0f s): %d zones, %d sections; load at the last equilibrium without cracks %.6g N/m, peak %.6g N/m "
         .. "(%.4f F) at %.4g mm; first crack at cycle %d: %d sections (%d tension), the first at (%.3f, %.3f) "
         .. "angle %g; after %d steps %d cracks (%d tension, %d shear), %.3f m of them on the diameter, load %.6g N/m")
        :format(label, os.clock() - started, info().zones, info().sections, before, peak, peak / F, at_peak * 1e3, cycle0 or -1,
                #first, tension, first[1] and first[1].x or 0, first[1] and first[1].y or 0,
                first[1] and first[1].angle or 0, steps, info().cracks, info().tension_cracks,
                info().shear_cracks, split, after))
  return { peak = peak, first = first, tension = tension, near_axis = near_axis, near_centre = near_centre,
           vertical = vertical, split = split }
end

-- Criterion (ii): the tractions on the section's plane.
local function traction_criterion(s)
  if s.sn > s.tension then return "tension" end
  if math.abs(s.tau) > s.cohesion - s.sn * math.tan(math.rad(s.friction)) then return "shear" end
  return nil
end

local gradual_peak
for _, case in ipairs({ { "principal stresses (i)", nil }, { "tractions on the plane (ii)", traction_criterion },
                        { "judged at equilibrium (i)", nil, "equilibrium" } }) do
  local r = run(case[1], case[2], case[3])
  if case[3] then gradual_peak = r.peak end
  local n = #r.first
  check.report(case[1] .. ": peak load [N/m]", r.peak, F, 0.10)
  check.report(case[1] .. ": first crack's sections in tension", r.tension, n, 0, { absolute = true })
  check.report(case[1] .. ": ... within D/10 of the loaded diameter", r.near_axis, n, 0, { absolute = true })
  check.report(case[1] .. ": ... within D/4 of the centre", r.near_centre, n, 0, { absolute = true })
  if case[2] then
    check.report(case[1] .. ": ... on the loaded diameter", r.vertical, n, 0, { absolute = true })
  end
  check.report(case[1] .. ": split along the diameter [m] (at least 0.9 D)", math.min(r.split, 0.9 * 2 * R),
               0.9 * 2 * R, 1e-9)
end

-- Judged at equilibrium, the jaw pushed at once to a displacement on a fresh disc and solved: the
-- least displacement that cracks it, bisected to 0.3 % of the reach between 80 and 120 %, and the
-- load at the largest that does not (the peak with the load in one step) against F and against
-- the peak in 1 % steps above.
build("judged at equilibrium, at once", nil, "equilibrium")
local reach = reach_of_F()
local function cracks_at_once(d)
  build("judged at equilibrium, at once", nil, "equilibrium")
  -- Cracks come only from a state solved to its ratio, but a state that is not says nothing. The
  -- first judgment decides: a cascade of breaks after it is cut short at 20,000 cycles.
  if not step(d * reach, reach).converged and info().cracks == 0 and
     not solve{ ratio = RATIO, max_cycles = 20000 }.converged and info().cracks == 0 then
    error(("the disc pushed at once to %.4f of the reach of F found no equilibrium"):format(d))
  end
  return info().cracks > 0, load()
end
local lo, hi = 0.8, 1.2
local cracked_lo, peak = cracks_at_once(lo)
local cracked_hi = cracks_at_once(hi)
for _ = 1, 7 do
  local mid = 0.5 * (lo + hi)
  local cracked, p = cracks_at_once(mid)
  if cracked then hi = mid else lo, peak = mid, p end
end
print(("judged at equilibrium, jaw pushed at once: no crack at %.4f of the reach of F (load %.6g N/m), cracks at "
       .. "%.4f"):format(lo, peak, hi))
check.report("judged at equilibrium, at once: no crack at 0.8, cracks at 1.2 of the reach (1 = yes)",
             (not cracked_lo and cracked_hi) and 1 or 0, 1, 0, { absolute = true })
check.report("judged at equilibrium, at once: peak load [N/m]", peak, F, 0.10)
check.report("judged at equilibrium: peak at once against in 1 % steps", peak, gradual_peak, 0.01)
check.finish()
