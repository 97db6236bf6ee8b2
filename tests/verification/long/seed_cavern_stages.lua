-- The seed cavern, bolted and not (the 24 m x 48 m warhead of stdlib/edem/cavern.lua, crown
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
-- must hold at each: which far-field contacts sit on the friction limit at the end can change
-- with a release 10 cycles longer or shorter, so a difference that one of the releases reverses
-- is numerical detail, not the bolts.
-- Measured with the defaults, without -> with bolts at the three releases: crown 0.518598 ->
-- 0.518573, 0.518593 -> 0.518547, 0.518645 -> 0.518687 m, so the crown check FAILS at release
-- 1010; slip within 5 m of the outline 22.025 -> 21.388, 21.945 -> 21.445, 21.889 -> 21.320 m
-- (printed, not checked); slipping 46 -> 45 at all three. By this test's rule the bolts' effect
-- on the crown, -0.025, -0.046 and +0.042 mm, is numerical detail: the model does not show that
-- pattern 1 holds the crown up. With Set P's persistent soft joints the roof moves with blocks
-- far larger than the 5 m bolts, and their yield force spread over 1.5 m (70 kPa) is small
-- against 4 MPa of overburden.
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
-- them, before the bolts could act.
local LAY_AT = tonumber(arg and arg[4]) or 0.5
-- Cuts passing within 1e-3 of the diagonal (0.27 m) of a vertex are bent through it. With the
-- default 1e-9 a cross joint passes 0.17 m above the arch's right foot (4, 16) and leaves a
-- 0.024 m2 sliver whose 0.17 m edges let the joint close (0.13 m at 11 MPa under kn = 83.9 MPa/m)
-- past the overlap watchdog's limit, half the shortest edge, in stage 2.
local TOLERANCE = 1e-3

-- Pattern 1: 5 m bolts at 1.5 m spacing (in the plane and out of it) normal to the permanent walls
-- a stage exposes (edem.bolts.exposed: the arch after the arch steps, the side walls after each
-- bench, the floor after the last), laid LAY_AT into that stage's release, 10 segments each. The
-- steel is the seed's (the seed paper, Jiang et al., §4.2: E = 190 GPa, A = 446 mm^2,
-- rho = 6083 kg/m^3, failure strain 3.5 %; its "yield strength 1.55 MPa" read as a yield force,
-- 0.156 MN = 446 mm^2 x ~350 MPa). Its grout values (compressive strength 180 MPa, shear modulus
-- 0.6 MN) do not read as cable inputs (bond stiffness in N/m/m, bond strength in N/m), so the
-- bond is the reference grout of tests/verification/bolt_pullout.lua (k_b = 50 MN/m/m,
-- s_b = 0.2 MN/m).
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
-- unbalanced-force ratio 1e-4, when let run on), as a wedge held by too little steel does. Such
-- stages are listed, not failed, with bolts or without; the run must end without an error, and
-- its last stage, where the measurements are made, in equilibrium.
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

-- No potential cracks here (no crackseed{}; the checks make sure none form): with cracks the two
-- runs would cut, and muck out, different blocks, and their slipping contacts could not be
-- compared one for one. The seed's cases with potential cracks are scripts/paper/case.lua's.
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
