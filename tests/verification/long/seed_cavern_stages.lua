-- Issue 6, acceptance: the seed cavern (the 24 m x 48 m warhead of stdlib/edem/cavern.lua, crown
-- at y = 24) in the seed region (stdlib/edem/seed.lua: 200 m x 180 m, Case 3 joints, 60 deg at
-- 16, 12, 8 m, and the cross set at -30 deg every 16 m; Set P: elastic rock, Coulomb joints
-- kn = 83.9 MPa/m, ks = 3.60 MPa/m, phi = 31.2 deg, c = 0; gravity; roof H = 158 m deep, K0 = 0.6)
-- is excavated in the seed's 16 steps (arch centre, left, right, 13 benches), each solved to
-- equilibrium. Measured from the in-situ state (displacements reset after it is solved): the crown
-- settlement (the gridpoint of the rock left in place nearest to the crown), the contacts in state
-- "slip", the slip within the bolts' reach (contacts' slip records zeroed with reset{ "joint" }
-- there), the cracks (none expected: no crackseed{}) and the run time.
--   run(false): no support; must run to the end without an error.
--   run(true):  pattern 1 bolts (5 m long at 1.5 m spacing) laid on the walls each stage exposes,
--               halfway through that stage's release (below); must give a lower crown settlement
--               and fewer slipping contacts than run(false), and end in equilibrium.
-- Both at three releases 10 cycles apart (RELEASE - 10, RELEASE, RELEASE + 10), and the checks
-- must hold at each: a difference that one of them reverses is numerical detail, not the bolts
-- (session 23: at 1000 cycles both checks passed, at 990 and 1010 the slipping one failed;
-- session 24, contacts found again block by block (726543a): slipping 25 -> 26, 25 -> 25,
-- 25 -> 25, crown lower by 0.18-0.28 mm at each, every stage in equilibrium, with the bolts laid
-- once each stage was solved; session 25, slip records zeroed after the in-situ state, bolts
-- still laid after the solve: the same counts; no contact within 9 m of the cavern slips at the
-- end in either run, and the slip summed over the contacts within the bolts' 5 m of the outline
-- is 20.97 -> 20.80, 24.29 -> 19.98, 20.99 -> 19.80 m. Those contacts slide in the stage that
-- exposes them, before bolts laid after it can act.
-- Session 25, bolts laid halfway through each release (this version, 1 thread): crown
-- 0.593861 -> 0.593584, 0.593892 -> 0.593699, 0.593922 -> 0.593626 m; slipping 25 -> 18,
-- 25 -> 16, 25 -> 19. The contacts that no longer slip (release 1000, a trial copy listing them)
-- lie 10.7 to 85 m from the cavern, most on the two cross joints that meet the left wall at
-- y = 6.7 and -11.9 m, which the bolts cross there: read as the bolts pinning those persistent
-- joints at the wall (not traced further). The slip within 5 m goes both ways (20.97 -> 20.36, 24.29 -> 20.47, 20.99 -> 25.46 m),
-- so it is printed, not checked. Bench 9 (stage 12) stops at 40,000 cycles with bolts (below).
-- Laid at 0.4 and 0.6 of the release instead (a trial copy, bolted runs only): crown 0.593564,
-- 0.593561, 0.593611 and 0.593725, 0.593623, 0.593695 m; slipping 22, 19, 18 and 16, 21, 16:
-- below the runs without bolts in all nine, so the difference is not a knife edge of the half.)
-- Session 26 (3a59b5c: a contact keeps its edge, which ended a limit cycle at a joint crossing;
-- every stage without bolts now reaches equilibrium): crown 0.594235 -> 0.594031, 0.594573 ->
-- 0.594044, 0.594345 -> 0.593969 m; slip within 5 m 20.503 -> 20.053, 20.316 -> 20.035, 20.528 ->
-- 20.065 m, lower with bolts at each release now; slipping 31 -> 18, 27 -> 19, 19 -> 26: the
-- slipping check FAILS at release 1010. Without bolts the count now spreads from 19 to 31 over
-- the three releases (25 at each before: contacts of the limit cycle among them). At 1010 (a
-- trial copy listing them) the contacts slipping at the end lie 10.7 to 109 m from the outline,
-- mostly in pairs (both faces), at the friction limit; 17 of the 19 without bolts slip with
-- bolts too, and the bolted run adds three pairs 9 to 27 m below the floor, a pair 85 m to the
-- left and one contact at 10.7 m, where no bolt reaches. By this test's rule, a difference one
-- release reverses is numerical detail.
-- Label "long": ctest -L long -R seed_cavern_stages. Optional arguments for trying other settings:
--   edem run seed_cavern_stages.lua [edge near the cavern [m]] [release [cycles]] [ratio]
--                                   [fraction of the release before the bolts go in]
local check = require "edem.check"
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local rockbolts = require "edem.bolts"

local EDGE = tonumber(arg and arg[1]) or 1.5      -- zone edge near the cavern [m]
local FAR = 10                                    -- zone edge far away [m]
local RELEASE = tonumber(arg and arg[2]) or 1000  -- cycles over which each stage's pull comes off
local RATIO = tonumber(arg and arg[3]) or 1e-5    -- equilibrium: unbalanced-force ratio per stage
local MAX_CYCLES = 40000                          -- per stage (see the note on run(false) below)
-- When a stage's bolts go in: after this fraction of its release. A plane-strain model has no
-- advancing face; support installed near the face sees only the load left once the face has
-- passed, so 2D codes release part of the load before the support is laid and the rest after it
-- (the convergence-confinement method; a half is the usual middle value, and this test's
-- only one). Laid after the stage is solved (fraction 1), bolts see only the later stages'
-- load, and the contacts near the walls have done all their sliding in the stage that exposed
-- them: the count of slipping contacts does not go down (session 24's numbers below).
local LAY_AT = tonumber(arg and arg[4]) or 0.5
-- Cuts passing within 1e-3 of the diagonal (0.27 m) of a vertex are bent through it. With the
-- default 1e-9 a cross joint passes 0.17 m above the arch's right foot (4, 16) and leaves a
-- 0.024 m2 sliver whose 0.17 m edges let the joint close (0.13 m at 11 MPa under kn = 83.9 MPa/m)
-- past the overlap watchdog's limit, half the shortest edge, in stage 2.
local TOLERANCE = 1e-3

-- Pattern 1: 5 m bolts at 1.5 m spacing (in the plane and out of it) normal to the permanent walls
-- a stage exposes (edem.bolts.exposed: the arch after the arch steps, the side walls after each
-- bench, the floor after the last), laid LAY_AT into that stage's release, 10 segments each. The steel is
-- the seed's (VERIFICATION.md S.3: E = 190 GPa, A = 446 mm^2, rho = 6083 kg/m^3, yield force
-- 0.156 MN, failure strain 3.5 %); its grout values do not read as cable inputs, so the bond is
-- VERIFICATION.md §7a's reference grout (k_b = 50 MN/m/m, s_b = 0.2 MN/m).
local function install_bolts(c, stage)
  if stage == 1 then
    bolt_material{ "pattern1", young = 190e9, area = 446e-6, density = 6083, yield_tension = 0.156e6,
                   failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
  end
  local _, count = rockbolts.pattern{ surface = rockbolts.exposed(c.stages[stage], c.outline), spacing = 1.5,
                                      length = 5, segments = 10, material = "pattern1" }
  return count
end

-- The blocks inside the cavern (any of its stages).
local function cavern_blocks(c)
  local names, inside = {}, {}
  for _, s in ipairs(c.stages) do names[s.name] = true end
  for b in blocks() do
    for _, r in ipairs(b.regions) do
      if names[r] then inside[b.id] = true end
    end
  end
  return inside
end

-- The gridpoints of the rock left in place nearest to the crown (several when joints meet there;
-- their settlement is averaged), as a list of ids.
local function crown_gridpoints(c)
  local inside = cavern_blocks(c)
  local best, ids = math.huge, {}
  for g in gridpoints() do
    if not inside[g.block] then
      local d = math.sqrt((g.x - c.crown[1]) ^ 2 + (g.y - c.crown[2]) ^ 2)
      if d < best - 1e-9 then best, ids = d, { g.id }
      elseif d <= best + 1e-9 then ids[#ids + 1] = g.id end
    end
  end
  return ids, best
end

-- Downward displacement of those gridpoints since the in-situ state [m], averaged.
local function settlement(ids)
  local want, sum = {}, 0
  for _, id in ipairs(ids) do want[id] = true end
  for g in gridpoints() do
    if want[g.id] then sum = sum - g.uy end
  end
  return sum / #ids
end

-- Distance from (x, y) to the closed polygon `outline` [m].
local function distance_to(outline, x, y)
  local best = math.huge
  for i, a in ipairs(outline) do
    local b = outline[i % #outline + 1]
    local dx, dy = b[1] - a[1], b[2] - a[2]
    local t = math.max(0, math.min(1, ((x - a[1]) * dx + (y - a[2]) * dy) / (dx * dx + dy * dy)))
    best = math.min(best, math.sqrt((a[1] + t * dx - x) ^ 2 + (a[2] + t * dy - y) ^ 2))
  end
  return best
end

-- Contacts slipping now (state "slip"), those that have slipped since the in-situ state (slip > 0;
-- reset{ "joint" } zeroes the records there), and the slip [m] summed over the contacts within
-- REACH of the cavern's outline, where the bolts are.
local REACH = 5  -- [m], the bolts' length
local function slipping(outline)
  local now, ever, near = 0, 0, 0
  for c in contacts() do
    if c.state == "slip" then now = now + 1 end
    if c.slip > 0 then ever = ever + 1 end
    if distance_to(outline, c.x, c.y) <= REACH then near = near + c.slip end
  end
  return now, ever, near
end

-- Blocks falling into the opening (moved down more than FALLEN on average) are taken out while
-- they fall, every MUCK cycles, as a fallen block is mucked out (excavate{ block }); their number
-- is reported. Left in, a wedge sliding out of the wall lands on the bench below, and the impact
-- of a fall in static mode (its masses scaled for equilibrium, not for motion) closes the soft
-- Set P joint at the bench's corner past the overlap watchdog's limit.
local FALLEN = 1.0  -- [m]
local MUCK = 200    -- [cycles]
local function muck_out()
  local drop, count = {}, {}
  for g in gridpoints() do
    drop[g.block] = (drop[g.block] or 0) - g.uy
    count[g.block] = (count[g.block] or 0) + 1
  end
  local gone = {}
  for z in zones() do if z.excavated then gone[z.block] = true end end
  local n = 0
  for block, d in pairs(drop) do
    if not gone[block] and d / count[block] > FALLEN then
      excavate{ block = block }
      n = n + 1
    end
  end
  return n
end

-- Builds the model from scratch, excavates the 16 stages, solves each; returns the measurements.
local function run(bolted, release)
  local label = (bolted and "pattern 1 bolts" or "no support") .. (", release %d"):format(release)
  local clock0, wall0 = os.clock(), os.time()
  local c = cavern.warhead{}
  local n = seed.region{ regions = c.stages, near = { c.outline }, edge = EDGE, far = FAR,
                         tolerance = TOLERANCE }
  print(("%s: %d blocks, %d zones, %d gridpoints (edge %g m near the cavern, %g m far)"):format(
    label, n.blocks, n.zones, n.gridpoints, EDGE, FAR))
  local r = solve{ ratio = 1e-6, max_cycles = 20000 }
  if not r.converged then error(("%s: the in-situ state did not converge (ratio %.3g)"):format(label, r.ratio)) end
  reset{ "displacement", "velocity", "joint" }
  local crown, off = crown_gridpoints(c)
  print(("  crown: %d gridpoint(s) %.3g m from (%g, %g)"):format(#crown, off, c.crown[1], c.crown[2]))
  print(("  %5s %-20s %7s %9s %12s %6s %8s %8s"):format("stage", "name", "cycles", "ratio",
                                                      "crown [m]", "slip", "slipped", "cpu [s]"))
  local out = { label = label, unconverged = {}, cycles = 0, fallen = 0 }
  local mucking = every(MUCK, function() out.fallen = out.fallen + muck_out() end)
  for i, s in ipairs(c.stages) do
    excavate{ region = s.name, release = release }
    local early = bolted and math.floor(LAY_AT * release + 0.5) or nil  -- cycles before the bolts
    if early and early >= release then early = nil end
    local ok, result = pcall(function()
      if early then
        cycle(early)
        out.bolts = (out.bolts or 0) + install_bolts(c, i)
      end
      return solve{ ratio = RATIO, max_cycles = MAX_CYCLES }
    end)
    if not ok then
      print(("  stage %d (%s) failed after %.1f s cpu:"):format(i, s.name, os.clock() - clock0))
      error(result, 0)
    end
    if not result.converged then out.unconverged[#out.unconverged + 1] = i end
    out.cycles = out.cycles + result.cycles + (early or 0)
    if bolted and not early then out.bolts = (out.bolts or 0) + install_bolts(c, i) end
    local now, ever = slipping(c.outline)
    print(("  %5d %-20s %7d %9.2e %12.5f %6d %8d %8.1f%s"):format(i, s.name, result.cycles,
      result.ratio, settlement(crown), now, ever, os.clock() - clock0,
      result.converged and "" or "  NOT CONVERGED"))
  end
  cancel(mucking)
  if bolted then  -- how the bolts fared
    local yielded, broken, cut, removed, largest, n, crossing = 0, 0, 0, 0, 0, 0, 0
    for b in bolts() do
      n = n + 1
      local near = { x = b.head.x + 0.05 * (b.tip.x - b.head.x), y = b.head.y + 0.05 * (b.tip.y - b.head.y) }
      local head, tip = zone_at(near.x, near.y), zone_at(b.tip.x, b.tip.y)  -- just in from the wall
      if head and tip and head.block ~= tip.block then crossing = crossing + 1 end
      if b.yielded > 0 then yielded = yielded + 1 end
      if b.broken > 0 then broken = broken + 1 end
      if b.removed then
        removed = removed + 1
      else
        for _, s in ipairs(b.segments) do
          if s.state == "removed" then cut = cut + 1; break end
        end
      end
      largest = math.max(largest, b.max_force)
    end
    print(("  bolts: %d laid, %d crossing a joint, %d with a yielded segment, %d broken, %d cut where "
           .. "their rock was mucked out, %d out of service; largest force %.4g N/m"):format(n, crossing,
           yielded, broken, cut, removed, largest))
  end
  out.settlement = settlement(crown)
  out.slipping, out.slipped, out.slip_near = slipping(c.outline)
  out.cracks = info().cracks
  out.cpu = os.clock() - clock0
  out.wall = os.time() - wall0
  print(("%s: %d stages, %d cycles, crown settlement %.4f m, %d contacts slipping (%d have "
         .. "slipped; %.3f m of slip within %g m of the cavern), %d blocks fallen, %d bolts, %d cracks, "
         .. "%.1f s cpu, %d s wall"):format(label, stage(), out.cycles, out.settlement, out.slipping,
    out.slipped, out.slip_near, REACH, out.fallen or 0, out.bolts or 0, out.cracks, out.cpu, out.wall))
  return out
end

-- Without support a stage may stop at MAX_CYCLES short of equilibrium: the wedge on the right wall
-- between the 60 deg joint from (12, 5.2) and a cross joint from (12, 11.8) (9.5 m2, its apex
-- 2.9 m into the rock) is free to slide into the cavern on the 60 deg joint (phi = 31.2 deg, c = 0)
-- once the benches below it are gone, as the seed's UDEC run shows the right wall collapsing (its
-- Figure 8c). With bolts laid halfway through the release that wedge does not fall at bench 9
-- (stage 12): it hangs on bolts that have yielded and creeps (0.2 mm/s after 150,000 cycles, the
-- unbalanced-force ratio 1e-4; session 25, a trial copy), as a wedge held by too little steel
-- does. Such stages are listed, not failed, with bolts or without; the run must end without an
-- error, and its last stage, where the measurements are made, in equilibrium.
local plains = {}
for _, release in ipairs({ RELEASE - 10, RELEASE, RELEASE + 10 }) do
  local plain = run(false, release)
  print(("%s: stages stopped short of equilibrium: %s"):format(plain.label,
    #plain.unconverged > 0 and table.concat(plain.unconverged, ", ") or "none"))
  check.report(plain.label .. ": cracks (no crackseed)", plain.cracks, 0, 0, { absolute = true })
  check.report(plain.label .. ": last stage short of equilibrium (1 = yes)",
               plain.unconverged[#plain.unconverged] == stage() and 1 or 0, 0, 0, { absolute = true })
  plains[release] = plain
end

-- Measured 2026-11-22 (edge 1.5 m, 2 threads): no support 0.6566 m, 8 slipping, 3 blocks fallen,
-- 10 s wall; pattern 1 (87 bolts: 7 yielded, 7 broken, 19 gone with fallen blocks) 0.6567 m,
-- 11 slipping, 3 fallen, stages 6 and 12 short of equilibrium (blocks creeping on yielded bolts),
-- 27 s wall. The bolts do not lower the crown's settlement: with Set P's persistent soft joints
-- the roof moves with blocks far larger than their 5 m, and their yield force spread over 1.5 m
-- (70 kPa) is small against 4 MPa of overburden. These checks fail.
-- Measured 2026-11-22 (session 22, cc04051: tips carry over their overlap), same settings: no
-- support 0.5938 m, 27 slipping (655 have slipped), 3 fallen, 11 s wall; pattern 1 0.5937 m, 25
-- slipping (652), 3 fallen, every stage at equilibrium, 9 s wall. The checks pass now, by 0.1 mm
-- and two contacts: margins of the size that went the other way before, so no evidence that the
-- bolts lower either (see above).
-- Measured 2026-11-23 (session 23, ac4fd4d, before the three releases): at 990 cycles no support
-- 0.5938 m, 24 slipping; pattern 1 0.5937 m, 26 slipping. At 1010 cycles no support 0.5938 m, 26
-- slipping; pattern 1 0.5937 m, 28 slipping, two stages short of equilibrium. The slipping check
-- fails at both and the settlement differs by 0.1 mm at all three: the pass at 1000 was chance.
-- With the three releases (f0d8d36 and after; 1 thread, 167 s): crown 0.593824, 0.593837,
-- 0.593849 m without bolts against 0.593704, 0.593682, 0.593704 m with them: 0.12 to 0.16 mm
-- lower in each pair, five times the spread among the releases (25 um), so the bolts do lower the
-- crown, by 0.02 %. Slipping contacts 24 -> 26, 27 -> 25, 26 -> 28, and those that have slipped
-- 647 -> 649, 655 -> 652, 655 -> 649: neither goes one way in every pair.
-- Where they slip (release 1000, a trial copy printing every contact in state "slip" at the end):
-- the same 25 to 27 places with bolts or without, all at least 9 m from the cavern (the nearest
-- at (-22.8, -23.6), 11 m left of the wall's foot, and (-6.4, -33.0), 9 m under the floor; the
-- rest 20 to 95 m away on the persistent joints), beyond the 5 m bolts: which of them sit on the
-- limit at the end is the numerical detail that flips the count.
-- Tried 2026-11-22 (session 10, a trial script, not this one): the paper's listed values (Set M:
-- rho 1505, E 415.5 MPa, nu 0.136; strength c 0.143 MPa, phi 34, sigma_t 0.0546 MPa; joints
-- kn_law "seed-cubic", ks 80.7 MPa/m, phi 31.2) with elastic blocks and potential cracks by hand
-- at 4.8 m (H/10): crackseed{ angles {118, 0} } beside the cavern (x -30..30, y -34..18) and
-- {0, 90} above it (y 18..44), origin {1.3, 0.7}, tolerance 1e-3. Crown settlement with bolts /
-- without: 0.27 / 0.64 m after stage 3, 0.42 / 0.67 (fallen, 4 / 121 blocks) after stage 9 -
-- the bolts hold the cracked roof. But the roof caves in, with or without bolts depending on
-- how fallen blocks are mucked out (every 200 cycles over 1 m: the bolted run stopped at stage
-- 10 on a block landing on the floor; every 50 cycles over 0.5 m: the bolted roof fell at stage
-- 7), and slipping contacts are then counted on different blocks. With Mohr-Coulomb zones as
-- well, the column above caved to the top boundary in both runs. A fair comparison wants the
-- potential cracks where the rock yields (issue 7's prepass) and a fall criterion that does not
-- take out blocks that bolts still hold.
-- Tried 2026-11-22 (session 12, trial scripts, not this one), potential cracks placed by
-- prepass{ joints = false } + crackseed{ auto } (strength of the rock's own set), elastic blocks:
--   Set P as here: the no-support run stops at stage 14 on the overlap watchdog (a soft joint closing
--     0.126 m at 10.5 MPa against a 0.25 m edge of a block cut by the cracks); model tolerance 1e-5
--     fails at stage 2 (the arch-foot sliver above), 1e-3 in crackseed (outlines near a joint).
--   Set P with the joints' listed stiffness (kn 1880, ks 80.7 MPa/m), tolerance 7e-4: all 16 stages
--     both ways; crown 0.06284 m without support, 0.06279 m with pattern 1, 39 slipping contacts
--     either way, 16 blocks fallen either way (they fall in the stage that frees them, before its
--     bolts go in). The crown's settlement here is the rock mass's elastic response (bolts' yield
--     force over 1.5 m x 1.5 m is 69 kPa against 4 MPa): bolts cannot move it, in any code.
--   Set M (as above), similar = 45 (15 and 30 fail: a shear set 2 deg off the 60 deg joints),
--     4,838 zones yielded, 2,259 sections: bolts keep every block in place (0 fallen against 8)
--     and fewer cracks (298 against 440 after stage 11); crown 0.231 against 0.291 m after stage
--     11 but 0.215 against 0.213 m after stage 10. Both runs stop in stage 12 on the overlap
--     watchdog at the left wall (-12, -11.5), normal stress 0.6-1 GPa. That one was the contact
--     law's (a wall gridpoint beside a heaved floor's corner pressed in by the far extension of
--     the floor's edge line; fixed in engine/contact/contact_force.hpp). After the fix stage 12
--     still stops: at (-28, 3.6) a gridpoint that has moved 2.4 m meets a crack face at 0.3 GPa
--     (no support), and at (-16.4, 1.4) at 2.3 GPa (bolts): the left wall collapses.
--   Set P with listed stiffness, bolts laid 500 cycles into each stage's 1,000-cycle release
--     (before the rock has relaxed): crown 0.0628 m either way, 38 against 39 slipping.
-- Tried 2026-11-22 (session 13; scripts/paper/case.lua does these steps): Set M, auto cracks,
--   blocks mucked out once any of their gridpoints has moved 1 m. Both runs still stop in stage
--   12, not at the cavern: at (38.9, 51.1), 233 MPa on a contact 2.9 mm long (a block corner whose
--   half-edges face the other block almost square: tiny projected length), and with bolts at
--   (-38.0, 4.4), 337 MPa. A floor on the contact length (a quarter of the half-edges' span; an
--   experiment, not kept) moves the no-support stop to a block whose shortest edge is 7 cm; the
--   bolted run then passes stage 12's solve. The auto-crack groups' outlines follow zone edges
--   and leave strips of zone-sized triangles along the walls and joints (scripts/paper/case.lua's
--   crack picture): those small blocks and short edges are what stops the runs.
-- So the trend wants a scene where the roof loosens but does not collapse; not found yet.
for _, release in ipairs({ RELEASE - 10, RELEASE, RELEASE + 10 }) do
  local plain, bolted = plains[release], run(true, release)
  local label = bolted.label
  print(("%s: stages stopped short of equilibrium: %s"):format(label,
    #bolted.unconverged > 0 and table.concat(bolted.unconverged, ", ") or "none"))
  check.report(label .. ": last stage short of equilibrium (1 = yes)",
               bolted.unconverged[#bolted.unconverged] == stage() and 1 or 0, 0, 0, { absolute = true })
  check.report(label .. ": cracks (no crackseed)", bolted.cracks, 0, 0, { absolute = true })
  check.report(label .. ": crown settlement lower than without (1 = yes)",
               bolted.settlement < plain.settlement and 1 or 0, 1, 0, { absolute = true })
  check.report(label .. ": fewer slipping contacts than without (1 = yes)",
               bolted.slipping < plain.slipping and 1 or 0, 1, 0, { absolute = true })
  print(("release %d: crown settlement %.6f m -> %.6f m with bolts, slipping contacts %d -> %d (have "
         .. "slipped %d -> %d), slip within %g m %.3f -> %.3f m"):format(release, plain.settlement,
    bolted.settlement, plain.slipping, bolted.slipping, plain.slipped, bolted.slipped, REACH,
    plain.slip_near, bolted.slip_near))
end
check.finish()
