-- Mohr-Coulomb crack onset with potential cracks: the first crack in uniaxial compression,
-- triaxial compression and uniaxial tension, its stress and its mode.
--
-- Closed form (compression negative, s1 <= s3): a section breaks in shear when
--   (1 - sin phi) s1 - (1 + sin phi) s3 + 2 c cos phi < 0,
-- i.e. at an axial stress q = Kp sigma3 + UCS, UCS = 2 c cos phi / (1 - sin phi), and in tension
-- when s3 > sigma_t. Seed rock: c = 0.143 MPa, phi = 34 deg, sigma_t = 0.0546 MPa:
-- UCS = 0.53789 MPa, Kp = 3.5371; q(0.25 MPa) = 1.42217 MPa, q(0.5 MPa) = 2.30645 MPa.
--
-- Sample: plane strain, W = 1 m by H = 2 m of elastic-brittle rock (elastic zones, seed E and
-- nu; the potential cracks are judged by the seed's Mohr-Coulomb strength: crackseed{
-- material = "strength" }), two sets of potential cracks at 45 +- phi/2 from the axis (the
-- shear planes) 0.25 m apart, zones of edge 0.1 m. Smooth platens: the base fixed in y, its
-- centre in x; sides (and, confined, the top) under sigma3 from an isotropic in-situ state.
-- The top moves in steps, held and solved (ratio 1e-6) after each, of 5 % of the elastic
-- displacement to the expected onset up to 90 % of it, then slowly (1/400000 of it per cycle)
-- until the first crack. The stress at equilibrium is uniform to 6e-5, so every section reaches
-- the criterion at nearly the same load; the judgment every 10 cycles breaks the first at the
-- first judgment past it.
--
-- Measured: the platen stress (- the zones' mean syy; + in tension) at the judgment that broke
-- the first section, and the platen stress at the last equilibrium before it, which must lie
-- below the onset. The built-in criterion judges a section by the principal stresses at its
-- point, not by the tractions on its own plane, so the onset does not depend on the orientation
-- of the cracks; the uniaxial case is repeated with both sets turned by 15 and 30 degrees and
-- must give the same onset within 0.2 % (the meshes differ, and so does the small unevenness of
-- the stress while the top moves).
-- Judged at equilibrium (judge{ at = "equilibrium" }), the same four onsets twice: with the load
-- put on at once (the platen stress on a fresh sample, solved; the onset bisected between 90 and
-- 115 % of the closed form: none breaks below it, sections of the right mode above), and in steps
-- pushed at once and solved (the first crack's own record gives the stress of the equilibrium
-- that broke it). Under load control the broken sample finds no new equilibrium in tension; the
-- solve then stops at its max_cycles with the state kept.
-- Tolerance: 1 % on the onset. The stress is uniform, so a correct criterion meets the closed
-- form but for the load added between two judgments and the stress's small unevenness.
local check = require "edem.check"

local W, H, EDGE, SPACING = 1.0, 2.0, 0.1, 0.25
local ROCK = { young = 415.52e6, poisson = 0.136, density = 1505, cohesion = 0.143e6, friction = 34,
               tension = 0.0546e6 }
local RATIO = 1e-6

local sin_phi = math.sin(math.rad(ROCK.friction))
local UCS = 2 * ROCK.cohesion * math.cos(math.rad(ROCK.friction)) / (1 - sin_phi)
local KP = (1 + sin_phi) / (1 - sin_phi)

local function build(label, s3, turn, at)
  model{ title = label }
  block{ x = { -W / 2, W / 2 }, y = { 0, H } }
  local a = 45 + ROCK.friction / 2
  crackseed{ angles = { 90 - a + turn, 90 + a + turn }, spacing = SPACING, origin = { 0, H / 2 },
             material = "strength", after = "crack" }
  zone{ edge = EDGE }
  material{ "rock", young = ROCK.young, poisson = ROCK.poisson, density = ROCK.density }
  material{ "strength", model = "mohr", young = ROCK.young, poisson = ROCK.poisson,
            cohesion = ROCK.cohesion, friction = ROCK.friction, tension = ROCK.tension }
  assign{ material = "rock" }
  joint_material{ "crack", kn = 1880e6, ks = 1880e6, friction = 31.2 }
  if at == "equilibrium" then judge{ at = "equilibrium" } else judge{ every = 10 } end
  boundary{ side = "bottom", fix = "y" }
  local centre = gp_near(0, 0).position  -- a gridpoint of the base near its centre
  local d = 0.1 * EDGE
  boundary{ polygon = { { centre.x - d, -d }, { centre.x + d, -d }, { centre.x + d, d }, { centre.x - d, d } },
            fix = "x" }
  if s3 > 0 then
    insitu{ sxx = -s3, syy = -s3, szz = -s3 }
    boundary{ side = "left", stress = { -s3, 0, 0 } }
    boundary{ side = "right", stress = { -s3, 0, 0 } }
    boundary{ side = "top", stress = { 0, -s3, 0 } }
    if not solve{ ratio = RATIO }.converged then error(label .. ": confinement not solved") end
  end
end

local function platen_stress()
  local syy, area = 0, 0
  for z in zones() do syy, area = syy + z.syy * z.area, area + z.area end
  return syy / area
end

-- Moves the top by du (down when negative) at most `speed` per cycle, held and solved. Faster, the
-- stress under the platen runs ahead of the mean while the top moves and a section there breaks
-- early (at 20 times this speed: 0.33 MPa above the platen stress at sigma3 = 0.5 MPa).
local function step(du, speed)
  local n = math.max(10, math.ceil(math.abs(du) / speed))
  boundary{ side = "top", yvel = du / n }
  cycle(n)
  boundary{ side = "top", yvel = 0 }
  solve{ ratio = RATIO, max_cycles = 50000 }
end

-- The first crack: the platen stress (- the zones' mean syy, + in tension) at the judgment that
-- broke it, its mode, and the platen stress at the last equilibrium before it.
local function first_crack(label, s3, turn, onset, sign)
  build(label, s3, turn)
  local at_crack
  local watch = every(10, function()
    if info().cracks > 0 and not at_crack then at_crack = sign * platen_stress() end
  end)
  local reach = (onset - s3) * H / ROCK.young  -- about the displacement to the onset [m]
  local before, k = 0, 0
  while sign * platen_stress() < 0.9 * onset and info().cracks == 0 and k < 40 do
    before = sign * platen_stress()
    step(sign * 0.05 * reach, reach / 40000)
    k = k + 1
  end
  -- Then a slow push: the stress under the platen leads the mean by the speed times the
  -- cycles a load takes to spread (about 600 here), 0.1 % of the onset at this speed.
  before = sign * platen_stress()
  boundary{ side = "top", yvel = sign * reach / 400000 }
  for _ = 1, 100 do
    cycle(1000)
    if info().cracks > 0 then break end
  end
  cancel(watch)
  local c = cracks()()
  if not c then error(label .. ": no crack after " .. k .. " steps") end
  local n = 0
  for cr in cracks() do if cr.cycle == c.cycle then n = n + 1 end end
  print(("%s: first crack at cycle %d, %s, %d of %d sections at once; platen stress then %.6g Pa, "
         .. "at the last equilibrium before %.6g Pa"):format(label, c.cycle, c.mode, n, info().sections,
         at_crack, before))
  return at_crack, c.mode, before
end

local cases = {
  { label = "uniaxial compression", s3 = 0, onset = UCS, sign = -1, mode = "shear" },
  { label = "triaxial, sigma3 = 0.25 MPa", s3 = 0.25e6, onset = KP * 0.25e6 + UCS, sign = -1, mode = "shear" },
  { label = "triaxial, sigma3 = 0.5 MPa", s3 = 0.5e6, onset = KP * 0.5e6 + UCS, sign = -1, mode = "shear" },
  { label = "uniaxial tension", s3 = 0, onset = ROCK.tension, sign = 1, mode = "tension" },
}
local uniaxial
for _, case in ipairs(cases) do
  local q, mode, before = first_crack(case.label, case.s3, 0, case.onset, case.sign)
  check.report(case.label .. ": stress at the first crack [Pa]", q, case.onset, 0.01)
  check.report(case.label .. ": no crack in the steps to 90 % of it (1 = none)", before < case.onset and 1 or 0, 1, 0,
               { absolute = true })
  check.report(case.label .. ": mode " .. case.mode .. " (1 = right)", mode == case.mode and 1 or 0, 1, 0,
               { absolute = true })
  uniaxial = uniaxial or q
end
for _, turn in ipairs({ 15, 30 }) do
  local label = ("uniaxial compression, cracks turned %d deg"):format(turn)
  local q = first_crack(label, 0, turn, UCS, -1)
  check.report(label .. ": onset as unturned", q, uniaxial, 0.002)
end

-- Judged at equilibrium (judge{ at = "equilibrium" }): nothing is judged while the load comes on,
-- so how fast it comes on no longer matters.
-- Load in one step: the platen stress put on at once on a fresh sample and solved; the onset is
-- bisected between 90 % and 115 % of the closed form, to 0.1 % of it.
local function breaks_at_once(case, q)
  build(case.label, case.s3, 0, "equilibrium")
  boundary{ side = "top", stress = { 0, case.sign * q, 0 } }
  local r = solve{ ratio = RATIO, max_cycles = 5000 }
  local c = cracks()()
  return r.broke > 0, c and c.mode
end
-- Gradually: the top pushed in steps, each at once (10 cycles) and solved, of 5 % of the
-- displacement to the onset up to 90 % of it, then of 0.2 %; the first crack's own record gives the
-- stress of the equilibrium that broke it.
local function first_crack_at_equilibrium(case)
  build(case.label, case.s3, 0, "equilibrium")
  local reach = (case.onset - case.s3) * H / ROCK.young
  local pushed, size = 0, 0.05
  while not cracks()() and pushed < 1.1 * reach do
    if pushed >= 0.9 * reach then size = 0.002 end
    step(case.sign * size * reach, reach)
    pushed = pushed + size * reach
  end
  local c = cracks()()
  if not c then error(case.label .. ": no crack at equilibrium by 110 % of the onset") end
  return case.sign * c.syy, c.mode
end
for _, case in ipairs(cases) do
  local label = case.label .. ", judged at equilibrium"
  local lo, hi = 0.9 * case.onset, 1.15 * case.onset
  local broke_lo = breaks_at_once(case, lo)
  local broke_hi, mode = breaks_at_once(case, hi)
  for _ = 1, 8 do
    local mid = 0.5 * (lo + hi)
    if breaks_at_once(case, mid) then hi = mid else lo = mid end
  end
  print(("%s: load at once, none broke at %.6g Pa, sections broke at %.6g Pa"):format(label, lo, hi))
  check.report(label .. ", load at once: onset [Pa]", 0.5 * (lo + hi), case.onset, 0.01)
  check.report(label .. ", load at once: none at 90 %, " .. case.mode .. " at 115 % (1 = yes)",
               (not broke_lo and broke_hi and mode == case.mode) and 1 or 0, 1, 0, { absolute = true })
  local q, first_mode = first_crack_at_equilibrium(case)
  check.report(label .. ", in steps: stress at the first crack [Pa]", q, case.onset, 0.01)
  check.report(label .. ", in steps: mode " .. case.mode .. " (1 = right)", first_mode == case.mode and 1 or 0, 1, 0,
               { absolute = true })
end
check.finish()
