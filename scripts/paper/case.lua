-- The seed paper's study, one case per run: the 24 m x 48 m warhead cavern in the seed's
-- 200 m x 180 m jointed region, dug in its 16 steps, with or without bolts.
--
--   edem --set case=3 --set depth=158 --set bolts=none run scripts/paper/case.lua
--
-- Settings (--set KEY=VALUE; defaults in brackets):
--   case      1, 2 or 3: the seed's joint patterns (edem.seed.cases) [3]
--   depth     m from the ground to the crown [158]
--   bolts     none, 1 (5 m bolts at 1.5 m on the rock each step exposes) or 2 (pattern 1, and 15 m
--             bolts between them on the seed's weak sidewalls: upper right A, lower left B) [none]
--   bolt_at   solved (a step's bolts laid once it is solved) or dug (as soon as its rock is out,
--             before its load comes off, so that they act on what the step loosens) [solved]
--   set       P (the prototype), S (P with joint stiffness x 17.86 only) or M (the seed's listed
--             values unscaled): edem.seed [P]
--   rock      elastic (the seed's: the rock between the potential cracks does not fail) or mohr
--             (Mohr-Coulomb with the set's strength, as in the prepass) in the steps [elastic]
--   prepass   jointed (the seed's: Mohr-Coulomb blocks and slipping joints dug by the explicit
--             solver, edem.yield_pass) or continuum (prepass{}, joints tied) [jointed]
--   judge     equilibrium (cracks judged on each step's solved state, in rounds until none
--             breaks) or cycles (every 10 cycles while the rock moves, the seed's way) [equilibrium]
--   release   cycles over which a step's load comes off [0: 100 judged at equilibrium, else 20000]
--   release_offset  cycles added to release [0]
--   damping   adaptive (viscous, 2 omega: rock with no equilibrium slides out and falls, as it does
--             undamped) or local (Itasca's, 0.8: holds such rock creeping) in the steps [adaptive]
--   prepass_damping  the same choice for the jointed prepass, kept apart so that where the
--             potential cracks go does not change with the steps' damping [local]
--   prepass_release  cycles over which each of the jointed prepass's steps is released: near its slow limit, where
--             the potential cracks no longer move with it (tests/bench/yield_pass_paths.lua) [3000]
--   prepass_stall  the jointed prepass's stall (as stall, for its steps) [0: never]
--   edge, far m: zone size at the cavern and far from it [1.5, 10]
--   stages    how many of the 16 steps to dig [16]
--   step_cycles  cycles a step is solved for once its load is off; judged at equilibrium, a step
--             short of its ratio is solved as long again under adaptive damping (rock with no
--             equilibrium falls), and then judged at ten times the ratio if still short [40000]
--   stall     cycles without the ratio falling a tenth after which a step's solve ends short of
--             its ratio, the rock moving on with no equilibrium near (solve{ stall }) [0: never]
--   settle    a step's state at its ratio (1e-5) solved on to this one under adaptive damping
--             before it is judged (solve{ settle }) [0: not]
--   balance   a step's state counts only once no body is more out of balance than this share of
--             the forces on it (solve{ balance }) [0: not asked]
--   similar   deg: crackseed{ auto }'s grouping angle [45]
--   min_angle deg: crackseed{ auto }'s sharpest corner of a cut with a joint [30; 0: every cut]
--   origin_x, origin_y  m: a point every group's cuts pass through (a group none of them
--             crosses: its centroid) [centroid: each group's own]
--   by_mode   true: crackseed{ auto }'s groups keep to one failure mode [false]
--   muck      loose (blocks held by nothing, rock that fell), moved (moved 1 m) or opening (moved
--             1 m into the opening) are mucked out every 200 cycles [loose]
--   first     left or right: the half of the arch dug first [left]
--   mirror    true: the joints mirrored about x = 0 (with first = right, the mirror image) [false]
--   judge_most  at most this many sections break at a judgment [0: all that fail]
--   neighbours  wait (of failing sections that touch, the worst breaks and the others are judged
--             again on the state that leaves: the count does not move with the release or the
--             damping) or break (all that fail at once, as the seed's method) [wait]
--   judge_radius  m: a section's stress also from its blocks' zones within this distance [0]
--   tolerance model{}'s geometric tolerance [7e-4]
--   fracture_energy, shear_fracture_energy  J/m^2: broken sections soften as cohesive cracks
--             instead of becoming joints at once [0, 0]
--   table     CSV file the result row is appended to, and NAME_steps.csv a row a step; also the
--             run's result{}, which edem sweep gathers [case_results.csv]
--   threads   recorded in the table [OMP_NUM_THREADS, else default]
--   strict    true: a step stopped by an error fails the script [false]
--   save_after  a checkpoint CASE_stepN.h5 after step N (for restore(), sections_left.lua); 0:
--             the in-situ state, before step 1 (tests/bench/release_paths.lua) [-1: none]
-- Steps: the region with the case's joints and the cavern's steps cut as regions; the prepass
-- (jointed: over the steps the run digs; continuum: over all 16); potential cracks where it
-- yielded (crackseed{ auto }, 4.8 m apart, a tenth of the cavern's height, with the set's intact
-- strength); then elastic rock, the set's joints and the potential cracks, the in-situ state
-- solved, displacements reset, and each step dug, solved to a ratio of 1e-5 and bolted. Blocks
-- that come loose are mucked out every 200 cycles.
-- Writes: the result row (cracks, crown and walls, the settlement 5 m above the crown, bolts
-- broken or at half their yield, steps short of their ratio, where a step stopped, the energy
-- balance's error so far) and pictures:
-- CASE_prepass_arch.png, CASE_prepass_step9.png, CASE_prepass.png (the seed's Figure 8),
-- CASE_cracks.png (Figures 9 and 11), CASE_profile.png and .csv (Figure 12: the settlement 10 m
-- above the crown; figure12.lua draws three runs together).
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local rockbolts = require "edem.bolts"
local yield_pass = require "edem.yield_pass"
local shapes = require "edem.shapes"
local loose = require "edem.loose"

local given = settings{
  case = 3, depth = 158, bolts = "none", bolt_at = "solved", set = "P", prepass = "jointed",
  judge = "equilibrium", release = 0, release_offset = 0, damping = "adaptive", prepass_damping = "local",
  prepass_release = 3000, prepass_stall = 0,
  edge = 1.5, far = 10, stages = 16, step_cycles = 40000, stall = 0, settle = 0, balance = 0, rock = "elastic",
  similar = 45, min_angle = 30, origin_x = "centroid", origin_y = "centroid",
  by_mode = false, muck = "loose", first = "left", mirror = false, judge_most = 0, judge_radius = 0,
  neighbours = "wait",
  tolerance = 7e-4, fracture_energy = 0, shear_fracture_energy = 0, table = "case_results.csv",
  threads = os.getenv("OMP_NUM_THREADS") or "default", strict = false, save_after = -1,
}
-- One of `choices`, or an error naming the setting.
local function one_of(key, choices)
  for _, c in ipairs(choices) do if given[key] == c then return given[key] end end
  local list = table.concat(choices, ", ", 1, #choices - 1) .. " or " .. choices[#choices]
  error(("%s must be %s, got %s"):format(key, list, given[key]), 0)
end
local CASE, DEPTH, BOLTS = given.case, given.depth, one_of("bolts", { "none", "1", "2" })
local SET, EDGE, FAR = one_of("set", { "P", "S", "M" }), given.edge, given.far
local JUDGE_AT = one_of("judge", { "equilibrium", "cycles" })
local ROCK = one_of("rock", { "elastic", "mohr" })
local STAGES, RELEASE_OFFSET = given.stages, given.release_offset
local RELEASE = (given.release ~= 0 and given.release or (JUDGE_AT == "equilibrium" and 100 or 20000)) + RELEASE_OFFSET
if not (math.type(RELEASE) == "integer" and RELEASE >= 1) then
  error(("release + release_offset must be a whole number of cycles >= 1, got %s"):format(RELEASE), 0)
end
if not (math.type(given.step_cycles) == "integer" and given.step_cycles >= 1) then
  error(("step_cycles must be a whole number of cycles >= 1, got %s"):format(given.step_cycles), 0)
end
for _, key in ipairs{ "stall", "prepass_stall" } do
  if not (math.type(given[key]) == "integer" and given[key] >= 0) then
    error(("%s must be a whole number of cycles >= 0, got %s"):format(key, given[key]), 0)
  end
end
if not (type(given.settle) == "number" and given.settle >= 0 and given.settle < 1e-5) then
  error(("settle must be 0 or a ratio below 1e-5, got %s"):format(given.settle), 0)
end
if not (type(given.balance) == "number" and given.balance >= 0 and given.balance < 1) then
  error(("balance must be in [0, 1), got %s"):format(given.balance), 0)
end
if not (math.type(given.prepass_release) == "integer" and given.prepass_release >= 1) then
  error(("prepass_release must be a whole number of cycles >= 1, got %s"):format(given.prepass_release), 0)
end
if not (math.type(given.save_after) == "integer" and given.save_after >= -1) then
  error(("save_after must be a step number (0: the in-situ state, -1: none), got %s"):format(given.save_after), 0)
end
local SIMILAR, TOLERANCE, MIN_ANGLE = given.similar, given.tolerance, given.min_angle
local JUDGE_MOST, JUDGE_RADIUS = given.judge_most, given.judge_radius
local NEIGHBOURS = one_of("neighbours", { "wait", "break" })
local FRACTURE_ENERGY, SHEAR_FRACTURE_ENERGY = given.fracture_energy, given.shear_fracture_energy
for _, key in ipairs{ "fracture_energy", "shear_fracture_energy" } do
  if given[key] < 0 then error(("%s must be a number >= 0 (J/m^2), got %s"):format(key, given[key]), 0) end
end
local COHESIVE = FRACTURE_ENERGY > 0 or SHEAR_FRACTURE_ENERGY > 0
local MUCK = one_of("muck", { "loose", "moved", "opening" })
local DAMPING = one_of("damping", { "adaptive", "local" })
local PREPASS_DAMPING = one_of("prepass_damping", { "adaptive", "local" })
local FIRST = one_of("first", { "left", "right" })
local BOLT_AT = one_of("bolt_at", { "solved", "dug" })
local MIRROR, BY_MODE = given.mirror, given.by_mode
local ORIGIN_X, ORIGIN_Y  -- nil: each group's centroid
if (given.origin_x == "centroid") ~= (given.origin_y == "centroid") then
  error("give origin_x and origin_y together, or neither", 0)
end
if given.origin_x ~= "centroid" then
  for _, key in ipairs{ "origin_x", "origin_y" } do
    if tonumber(given[key]) == nil then error(("%s must be a number (m), got %s"):format(key, given[key]), 0) end
  end
  ORIGIN_X, ORIGIN_Y = tonumber(given.origin_x), tonumber(given.origin_y)
end
local ORIGIN = ORIGIN_X and { ORIGIN_X, ORIGIN_Y } or nil
local PREPASS = one_of("prepass", { "jointed", "continuum" })
local TABLE = given.table
local STEPS_TABLE = TABLE:gsub("%.csv$", "") .. "_steps.csv"  -- a row after each step
-- The result row's columns. A table that exists already is appended to, so it must have them,
-- or its rows would not line up under its header (a table an older case.lua wrote).
local columns = { "case", "set", "depth", "bolts", "release", "steps", "cracks", "tension", "shear", "left",
                  "right", "left_mean_y_m", "right_mean_y_m", "crown_settlement_m", "settlement_5m_above_crown_m",
                  "left_wall_m", "right_wall_m", "convergence_m", "left_wall_5m_m", "right_wall_5m_m",
                  "left_wall_15m_m", "right_wall_15m_m", "profile_left_m", "profile_right_m", "slipping",
                  "slipped", "fallen", "bolts_laid", "bolts_skipped", "bolts_broken", "bolts_over_half_yield",
                  "cuts_left_out", "threads", "seconds", "prepass_stopped", "unconverged", "stopped",
                  "points_fallen", "edge_m", "far_m", "first", "muck", "damping", "mirror", "crack_length_m",
                  "origin_x_m", "origin_y_m", "judge", "judgments", "prepass", "bolt_at", "prepass_damping",
                  "unconverged_why", "rock", "energy_error_J_m", "energy_error_share",
                  "left_wall_5m_settlement_m", "right_wall_5m_settlement_m", "prepass_release" }
for _, file in ipairs{ TABLE, STEPS_TABLE } do
  local existing = io.open(file, "r")
  if existing then
    local header = existing:read("l")
    existing:close()
    if header ~= table.concat(columns, ",") then
      error(("table has other columns than case.lua writes: give another table or move it away, got %s")
            :format(file), 0)
    end
  end
end
-- For the table only: the threads it ran on, as the caller set them (edem --threads N --set threads=N).
local THREADS = given.threads
local tag = ("case%d_%s_h%g_%s"):format(CASE, SET, DEPTH, BOLTS == "none" and "none" or "pattern" .. BOLTS)
-- Runs that differ only in a nudged release keep their pictures apart.
if RELEASE_OFFSET ~= 0 then tag = tag .. ("_release%d"):format(RELEASE) end
if FIRST == "right" then tag = tag .. "_right_first" end
if MIRROR then tag = tag .. "_mirror" end
if COHESIVE then tag = tag .. "_cohesive" end
if JUDGE_RADIUS ~= 0 then tag = tag .. "_radius" end
if ORIGIN then tag = tag .. ("_origin%g_%g"):format(ORIGIN_X, ORIGIN_Y) end
if PREPASS == "continuum" then tag = tag .. "_continuum" end
if BOLT_AT == "dug" then tag = tag .. "_bolted_when_dug" end
if ROCK == "mohr" then tag = tag .. "_mohr" end
local started = os.time()

local c = cavern.warhead{}
if FIRST == "right" then
  assert(c.stages[2].name:match("arch_left$") and c.stages[3].name:match("arch_right$"))
  c.stages[2], c.stages[3] = c.stages[3], c.stages[2]
end
local function build_region()
  seed.region{ case = CASE, set = SET, depth = DEPTH, regions = c.stages, near = { c.outline }, edge = EDGE,
               far = FAR, tolerance = TOLERANCE, mirror = MIRROR }
end
build_region()
local rock = seed[SET].rock

-- 1. Where the rock mass yields as it is dug: Mohr-Coulomb rock of the set over all the steps.
seed.intact(SET)
local names = {}
for _, s in ipairs(c.stages) do names[#names + 1] = s.name end
local WINDOW = { -60, 60, -50, 60 }
local pre, prepass_note
if PREPASS == "jointed" then
  -- The seed's: the jointed mass, its joints slipping and opening, dug by the explicit solver
  -- (edem.yield_pass), over the steps the run digs, with pictures after the arch, after step 9 and
  -- after the last step (the seed's Figure 8); then the same model built again, undug, for the
  -- cracks.
  local dug = {}
  for k = 1, math.min(STAGES, #names) do dug[k] = names[k] end
  local pictures = { [3] = "_prepass_arch.png", [9] = "_prepass_step9.png", [#dug] = "_prepass.png" }
  pre = yield_pass.run{ stages = dug, release = given.prepass_release, damping = PREPASS_DAMPING,
                       stall = given.prepass_stall,
                       after_stage = function(k)
    if pictures[k] then plot{ file = tag .. pictures[k], show = { "plastic", "blocks" }, window = WINDOW } end
  end }
  prepass_note = pre.failure and ("stopped in " .. pre.failure:sub(1, 160):gsub('"', "'")) or "complete"
  build_region()
  yield_pass.check(pre)
  seed.intact(SET)
else
  -- The rock mass as one continuum, joints tied, by the implicit prepass (Newton). Where Newton
  -- fails on the stage's load path and the four finer ones it tries after it (4, 8, 16 and 32
  -- steps), it ends at that step and the cracks go where it yielded so far. Its linear solves use
  -- Eigen's SparseLU ("lu"), whose answer does not depend on the CPU's kernels, as UMFPACK's
  -- OpenBLAS kernels do: the cracks' ends, and so the whole run, are the same on any machine.
  pre = prepass{ stages = names, joints = false, steps = 2, restarts = 4, on_failure = "keep", solver = "lu" }
  prepass_note = "complete"
  if pre.failure then
    local last = pre.stages[#pre.stages]
    prepass_note = ("%s at load factor %.3g"):format(last.name, last.reached)
  end
  plot{ file = tag .. "_prepass.png", show = { "prepass", "joints" }, window = WINDOW }
end
if prepass_note ~= "complete" then
  print(("%s: the prepass stopped short (%s): cracks placed from the zones yielded so far"):format(tag, prepass_note))
end
local yielded = 0
for _, z in ipairs(pre.zones) do if z.state ~= "none" then yielded = yielded + 1 end end

-- 2. Potential cracks there, then the discontinuum.
judge{ at = JUDGE_AT, most = JUDGE_MOST, radius = JUDGE_RADIUS, neighbours = NEIGHBOURS }
if COHESIVE then
  local joint = seed[SET].joint
  joint_material{ "cohesive", kn = joint.kn, kn_law = joint.kn_law, stress_scale = joint.stress_scale,
                  closure_scale = joint.closure_scale, ks = joint.ks, friction = rock.friction,
                  cohesion = rock.cohesion, tension = rock.tension, residual_friction = joint.friction,
                  fracture_energy = FRACTURE_ENERGY, shear_fracture_energy = SHEAR_FRACTURE_ENERGY }
end
local groups = crackseed{ auto = pre, spacing = 4.8, material = "intact", similar = SIMILAR, min_angle = MIN_ANGLE,
                          origin = ORIGIN, by_mode = BY_MODE, after = COHESIVE and "cohesive" or nil }
if ROCK == "mohr" then
  material{ "rock", model = "mohr", density = rock.density, young = rock.young, poisson = rock.poisson,
            cohesion = rock.cohesion, friction = rock.friction, tension = rock.tension }
else
  material{ "rock", density = rock.density, young = rock.young, poisson = rock.poisson }
end
assign{ material = "rock" }
local n = info()
print(("%s: %d zones yielded in the prepass, %d crack groups, %d sections (%d crack pieces left out, %d cut back "
       .. "from corners under %g deg); %d blocks, %d zones; %d features snapped, %d sliver spots kept, shortest "
       .. "block edge %.3f of the zone edge"):format(tag, yielded, #groups, n.sections, n.cuts_left_out,
       n.cuts_cut_back, MIN_ANGLE, n.blocks, n.zones, n.snapped, n.slivers_kept, n.shortest_edge))
-- Where the cracks can come from, by side of the cavern's axis (x < 0 left): the zones yielded in
-- the prepass, and the potential cracks within 2, 5 and 10 m of the outline.
do
  local zones_by_side = { 0, 0 }
  for _, z in ipairs(pre.zones) do
    if z.state ~= "none" and z.x ~= 0 then
      local side = z.x < 0 and 1 or 2
      zones_by_side[side] = zones_by_side[side] + 1
    end
  end
  local bands = { 2, 5, 10 }
  local near = { { 0, 0 }, { 0, 0 }, { 0, 0 } }
  for sec in sections() do
    local d = shapes.distance_to(c.outline, sec.x, sec.y)
    for i, band in ipairs(bands) do
      if d <= band then
        local side = sec.x < 0 and 1 or 2
        near[i][side] = near[i][side] + sec.length
      end
    end
  end
  print(("%s: zones yielded in the prepass, left / right of the axis: %d / %d; potential cracks within "
         .. "2, 5 and 10 m of the outline, left / right: %.1f / %.1f, %.1f / %.1f, %.1f / %.1f m"):format(
         tag, zones_by_side[1], zones_by_side[2], near[1][1], near[1][2], near[2][1], near[2][2], near[3][1],
         near[3][2]))
end
local r = solve{ ratio = 1e-6, max_cycles = 20000 }
reset{ "displacement", "velocity", "joint" }  -- displacements and joint slip from the in-situ state
energy{ reset = true }  -- the energy balance of the excavation, from the in-situ state
-- Local damping takes the same share of every node's force whatever the motion's frequency. The
-- adaptive damping, c = 2 omega, is critical for one frequency, the whole opening's slow
-- convergence, and leaves quicker motion (a breaking section's ring, a sliding block) damped less.
local function steps_damping()
  if DAMPING == "local" then set{ damping = "local", local_damping = 0.8 } end
end
steps_damping()
if given.save_after == 0 then save(("%s_step0.h5"):format(tag)) end

-- Measuring points, in the rock left in place: the gridpoint nearest to the crown, and those
-- nearest to the side walls at y = 0.
local in_cavern = {}    -- block id -> true: rock of one of the steps
local dug_at_step = {}  -- block id -> the step that digs it
do
  local stage_of = {}
  for k, s in ipairs(c.stages) do stage_of[s.name] = k end
  for b in blocks() do
    for _, name in ipairs(b.regions) do
      if stage_of[name] then in_cavern[b.id], dug_at_step[b.id] = true, stage_of[name] end
    end
  end
end
local function rock_gridpoint_near(x, y)
  local best, found = math.huge, nil
  for g in gridpoints() do
    local d = (g.x - x) ^ 2 + (g.y - y) ^ 2
    if not in_cavern[g.block] and d < best then best, found = d, g end
  end
  return found
end
local crown = rock_gridpoint_near(c.crown[1], c.crown[2])
-- The rock 5 m above the crown, as far up as pattern 1's bolts reach: the crown's settlement less
-- this point's is what the bolted part of the roof stretches; the rest is the roof as a whole
-- coming down, which 5 m bolts cannot hold.
local above_crown = rock_gridpoint_near(c.crown[1], c.crown[2] + 5)
-- Each side wall's points at the springline (y = 0) and halfway down the benches (y = -12), on
-- its face and 5 m behind it. The face's blocks are the ones that loosen and fall, and a point
-- that falls with its block measures nothing from then on; 5 m in, as far as pattern 1's bolts
-- reach and as far as the crown's second point sits above it, is the rock mass beyond the skin.
-- 15 m in, as far as pattern 2's long bolts reach, where the seed finds the loosened rock deepest,
-- is read where the points 5 m in settle nothing, their blocks fallen (trends.lua).
-- suffix: of the row's columns and the names in points_fallen; behind: m behind the face, the
-- faces at x = -12 and 12 m (the cavern 24 m wide).
local walls = { { suffix = "", behind = 0 }, { suffix = "_5m", behind = 5 }, { suffix = "_15m", behind = 15 } }
for _, w in ipairs(walls) do
  local x = 12 + w.behind
  w.left = { rock_gridpoint_near(-x, 0), rock_gridpoint_near(-x, -12) }
  w.right = { rock_gridpoint_near(x, 0), rock_gridpoint_near(x, -12) }
end
-- The mean of a displacement component (key: "ux" or "uy") over some gridpoints [m].
local function mean_of(points, key)
  local want, sum = {}, 0
  for _, p in ipairs(points) do want[p.id] = true end
  for g in gridpoints() do if want[g.id] then sum = sum + g[key] end end
  return sum / #points
end
-- How far the left and the right wall have moved into the opening at one of `walls`' depths, the
-- mean of each wall's two points [m].
local function wall_moves(w) return mean_of(w.left, "ux"), -mean_of(w.right, "ux") end
-- How far they have come down there [m]: a wall that slides down its joints comes down as it
-- moves in, one pushed out across them does not.
local function wall_settlements(w) return -mean_of(w.left, "uy"), -mean_of(w.right, "uy") end
-- The seed's Figure 12: the vertical displacement along a line 10 m above the crown. Its two
-- halves' mean settlements, left and right of the axis (the point on it left out), say which side
-- comes down more, which is what the seed reads off its Figure 12 [m].
local PROFILE_LINE = { from = { -60, c.crown[2] + 10 }, to = { 60, c.crown[2] + 10 }, points = 61 }
local function profile_halves()
  local p = profile{ from = PROFILE_LINE.from, to = PROFILE_LINE.to, points = PROFILE_LINE.points, quantity = "uy" }
  local sums, counts = { 0, 0 }, { 0, 0 }
  for i, x in ipairs(p.x) do
    if x ~= 0 then
      local side = x < 0 and 1 or 2
      sums[side], counts[side] = sums[side] - p.value[i], counts[side] + 1
    end
  end
  return sums[1] / counts[1], sums[2] / counts[2]
end
local function settlement(point)
  point = point or crown
  for g in gridpoints() do if g.id == point.id then return -g.uy end end
end

-- Mucking out: blocks come loose (muck = "loose"), or whose gridpoints have moved more than 1 m; with
-- muck = "opening" only those of them whose centre has moved into the opening dug so far.
local fallen = 0
local mucked = {}   -- block id -> true: the blocks mucked out so far
local step_now = 0  -- the step being excavated
local function in_opening(x, y)
  for k = 1, math.min(step_now, #c.stages) do
    if shapes.contains(c.stages[k].polygon, x, y) then return true end
  end
  return false
end
-- Of the blocks given, those whose centre (at rest, moved by its gridpoints' mean displacement)
-- lies in the opening.
local function in_the_opening(moved)
  if #moved == 0 then return moved end
  local sum = {}
  for _, b in ipairs(moved) do sum[b.id] = { 0, 0, 0 } end
  for g in gridpoints() do
    local t = sum[g.block]
    if t then t[1], t[2], t[3] = t[1] + g.ux, t[2] + g.uy, t[3] + 1 end
  end
  local taken = {}
  for _, b in ipairs(moved) do
    local t = sum[b.id]
    if in_opening(b.x + t[1] / t[3], b.y + t[2] / t[3]) then taken[#taken + 1] = b end
  end
  return taken
end
-- Judged at equilibrium, what is mucked out must not depend on the release any more than what
-- breaks: a loose block goes only if it was loose at the check before too, 200 cycles earlier (a
-- block a step's transient lifts off its seat for a moment has not fallen), and rock of a step not
-- yet dug stays for its step (a step's load coming off over 100 cycles can leave the next bench
-- down loose for a moment; taken then, it would leave the step after nothing to dig).
local stays_loose = loose.tracker()
local function muck_out()
  local moved = {}
  if MUCK == "loose" then
    moved = stays_loose(function(b, before)
      local later = dug_at_step[b.id] and dug_at_step[b.id] > step_now
      return JUDGE_AT ~= "equilibrium" or (before and not later)
    end)
  else
    for b in moved_blocks(1.0) do moved[#moved + 1] = b end
  end
  if MUCK == "opening" then moved = in_the_opening(moved) end
  for _, b in ipairs(moved) do
    excavate{ block = b.id }
    fallen = fallen + 1
    mucked[b.id] = true
  end
end
local mucking = every(200, muck_out)
-- The measuring points whose block has fallen: mucked out, or moved more than 1 m into the
-- opening dug so far (fallen onto the floor and held there, as muck = "opening" would take it;
-- a face block that bulged in by half its thickness has not). A gridpoint of rock that is gone
-- keeps the displacement it had, and one on a block on the floor rides down with it as the
-- benches below are dug, so what the row gives for it is not a measurement of the rock mass;
-- the row names them (column points_fallen), and trends.lua does not judge on them but for the
-- walls, where it takes such a value as the least the wall moved.
local function points_fallen()
  local names = {}
  local moved = {}
  for b in moved_blocks(1.0) do moved[#moved + 1] = b end
  local on_the_floor = {}  -- block id -> true
  for _, b in ipairs(in_the_opening(moved)) do on_the_floor[b.id] = true end
  local function fell(block) return mucked[block] or on_the_floor[block] end
  local function check(name, points)
    for _, g in ipairs(points) do
      if fell(g.block) then names[#names + 1] = name; return end
    end
  end
  check("crown", { crown })
  check("5m_above_crown", { above_crown })
  for _, w in ipairs(walls) do
    check("left_wall" .. w.suffix, w.left)
    check("right_wall" .. w.suffix, w.right)
  end
  return table.concat(names, " ")
end

local BOLT_YIELD, BOLT_SPACING = 0.156e6, 1.5  -- N per bolt; m out of the plane
if BOLTS ~= "none" then
  bolt_material{ "bolt", young = 190e9, area = 446e-6, density = 6083, yield_tension = BOLT_YIELD,
                 failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = BOLT_SPACING }
end
-- How hard the bolts work: those with a segment that broke (also one cut away with its rock since),
-- and those whose most loaded segment carries half the yield force or more now (bolts() gives
-- forces per metre out of the plane).
local function bolt_loads()
  local broken, loaded = 0, 0
  for b in bolts() do
    if b.broken > 0 then broken = broken + 1 end
    if b.max_force >= 0.5 * BOLT_YIELD / BOLT_SPACING then loaded = loaded + 1 end
  end
  return broken, loaded
end
-- Pattern 2's weak zones, the seed's words for Figure 11: the upper right sidewall (A: y from 0
-- to the springline) and the lower left sidewall (B: y below -8), the sidewalls only, not the
-- arch or the floor. Right is the side the joints dip towards, so the mirror image has them
-- mirrored.
local half_width, springline, floor = 0, -math.huge, math.huge
for _, p in ipairs(c.outline) do
  half_width, floor = math.max(half_width, math.abs(p[1])), math.min(floor, p[2])
end
for _, p in ipairs(c.outline) do
  if math.abs(p[1]) >= half_width - 1e-6 then springline = math.max(springline, p[2]) end
end
local function weak(x, y)
  if math.abs(x) < half_width - 1e-6 then return false end  -- not on a sidewall
  local towards_dip = (MIRROR and -x or x) > 0
  if towards_dip then return y >= 0 and y <= springline end
  return y <= -8 and y > floor + 1e-6
end
local laid, skipped = 0, 0
local function bolt_step(s)
  local surface = rockbolts.exposed(s, c.outline)
  local _, count, missed = rockbolts.pattern{ surface = surface, spacing = 1.5, length = 5, segments = 10,
                                              material = "bolt", missing = "skip" }
  laid, skipped = laid + count, skipped + missed
  if BOLTS == "2" then
    local _, more, missed2 = rockbolts.pattern{ surface = surface, spacing = 1.5, first = 1.5, length = 15,
                                                segments = 20, material = "bolt", where = weak, missing = "skip" }
    laid, skipped = laid + more, skipped + missed2
  end
end

local done, stopped = 0, ""  -- steps done; where the run stopped, if it did
local judgments = 0          -- states judged at equilibrium (judge = equilibrium), all steps
local unconverged = {}       -- steps whose solve reached max_cycles short of the ratio
local unconverged_why = {}   -- for each of them, what still moved at its end (still_moving)

-- The result row: after each step into TABLE's _steps file, and at the end into TABLE.
local function result_row()
  local r = { tension = 0, shear = 0, left = 0, right = 0, length = 0 }
  local left_y, right_y = 0, 0
  for k in cracks() do
    r.length = r.length + k.length
    if k.mode == "tension" then r.tension = r.tension + 1 else r.shear = r.shear + 1 end
    if k.x < 0 then
      r.left, left_y = r.left + 1, left_y + k.y
    else
      r.right, right_y = r.right + 1, right_y + k.y
    end
  end
  r.left_mean_y = r.left > 0 and left_y / r.left or 0
  r.right_mean_y = r.right > 0 and right_y / r.right or 0
  r.slipping, r.slipped = 0, 0
  for k in contacts() do
    if k.state == "slip" then r.slipping = r.slipping + 1 end
    if k.slip > 0 then r.slipped = r.slipped + 1 end
  end
  r.left_moves, r.right_moves = wall_moves(walls[1])
  r.left_moves_5m, r.right_moves_5m = wall_moves(walls[2])
  r.left_moves_15m, r.right_moves_15m = wall_moves(walls[3])
  r.left_settles_5m, r.right_settles_5m = wall_settlements(walls[2])
  r.profile_left, r.profile_right = profile_halves()
  r.bolts_broken, r.bolts_loaded = bolt_loads()
  r.seconds = os.time() - started
  r.energy = energy()  -- the balance since the excavation began: what the method made so far
  local row = { CASE, SET, DEPTH, BOLTS, RELEASE, done, r.tension + r.shear, r.tension, r.shear, r.left, r.right,
                ("%.3f"):format(r.left_mean_y), ("%.3f"):format(r.right_mean_y), ("%.5f"):format(settlement()),
                ("%.5f"):format(settlement(above_crown)), ("%.5f"):format(r.left_moves),
                ("%.5f"):format(r.right_moves), ("%.5f"):format(r.left_moves + r.right_moves),
                ("%.5f"):format(r.left_moves_5m), ("%.5f"):format(r.right_moves_5m),
                ("%.5f"):format(r.left_moves_15m), ("%.5f"):format(r.right_moves_15m),
                ("%.5f"):format(r.profile_left), ("%.5f"):format(r.profile_right), r.slipping,
                r.slipped, fallen, laid, skipped, r.bolts_broken, r.bolts_loaded, info().cuts_left_out, THREADS,
                r.seconds,
                prepass_note == "complete" and '""' or ('"' .. prepass_note .. '"'),
                '"' .. table.concat(unconverged, " ") .. '"',
                '"' .. stopped:gsub('"', "'") .. '"', '"' .. points_fallen() .. '"', EDGE, FAR, FIRST, MUCK,
                DAMPING, MIRROR, ("%.2f"):format(r.length), ORIGIN_X or "", ORIGIN_Y or "", JUDGE_AT, judgments,
                PREPASS, BOLT_AT, PREPASS_DAMPING,
                '"' .. table.concat(unconverged_why, "; "):gsub('"', "'") .. '"', ROCK,
                ("%.4g"):format(r.energy.error), ("%.3g"):format(r.energy.relative_error),
                ("%.5f"):format(r.left_settles_5m), ("%.5f"):format(r.right_settles_5m), given.prepass_release }
  local named = {}  -- for result{}: each column's value, unquoted
  for i, v in ipairs(row) do
    row[i] = tostring(v)
    named[columns[i]] = row[i]:match('^"(.*)"$') or row[i]
  end
  named.seconds = nil  -- edem sweep times each run itself
  return r, table.concat(row, ","), named
end
local function append_row(file, line)
  local existing = io.open(file, "r")
  local out = assert(io.open(file, "a"))
  if not existing then out:write(table.concat(columns, ","), "\n") else existing:close() end
  out:write(line, "\n")
  out:close()
end

-- Why a step stopped short of its ratio, as measured: where the rock still moves fastest (the
-- static run's speed) and how many contacts slip within 5 m of it, against the whole model's.
local function still_moving()
  local dug = {}  -- blocks dug or mucked out: their gridpoints are no longer cycled
  for b in blocks() do if b.excavated then dug[b.id] = true end end
  local fastest, at = 0, nil
  for g in gridpoints() do
    local v = math.sqrt(g.vx ^ 2 + g.vy ^ 2)
    if not dug[g.block] and v > fastest then fastest, at = v, g end
  end
  if not at then return "nothing moves" end
  local near, all = 0, 0
  for k in contacts() do
    if k.state == "slip" then
      all = all + 1
      if (k.x - at.x) ^ 2 + (k.y - at.y) ^ 2 <= 25 then near = near + 1 end
    end
  end
  return ("still moving: fastest at (%.1f, %.1f) in block %d, %.2g m/s, %d of the %d slipping contacts "
          .. "within 5 m of it"):format(at.x, at.y, at.block, fastest, near, all)
end

print(("  %5s %-20s %7s %9s %10s %7s %6s %6s %6s"):format("step", "name", "cycles", "ratio", "crown [m]", "cracks",
                                                       "judged", "fallen", "time"))
for i, s in ipairs(c.stages) do
  if i > STAGES then break end
  step_now = i
  -- Rock of a later step may have been mucked out already, all of it: then there is nothing left
  -- to excavate, and the step is only solved.
  local ok_excavate, why = pcall(excavate, { region = s.name, release = RELEASE })
  if not ok_excavate and not tostring(why):find("was excavated already", 1, true) then error(why, 0) end
  if BOLTS ~= "none" and BOLT_AT == "dug" then bolt_step(s) end
  -- The ratio is judged once the load is off: step_cycles from there.
  local ok, result = pcall(solve, { ratio = 1e-5, max_cycles = RELEASE + given.step_cycles, stall = given.stall,
                                    settle = given.settle, balance = given.balance })
  -- Judged at equilibrium, a step short of its ratio has not been judged. Rock with no equilibrium
  -- near (blocks sliding out of a wall, which local damping holds creeping) is solved on under
  -- adaptive damping, which lets it fall, to the same ratio: a state judged short of it would load
  -- the sections nearby as far as the creep has gone when the cycles run out. Rock still short
  -- after that, creeping on soft joints, settles no further: judged at ten times the ratio.
  if ok and not result.converged and JUDGE_AT == "equilibrium" then
    if DAMPING == "local" then set{ damping = "adaptive" } end
    for _, ratio in ipairs{ 1e-5, 1e-4 } do
      local again
      ok, again = pcall(solve, { ratio = ratio, max_cycles = given.step_cycles, stall = given.stall,
                                 balance = given.balance })
      if not ok then result = again; break end
      result.cycles, result.judgments = result.cycles + again.cycles, result.judgments + again.judgments
      result.converged, result.ratio = ratio == 1e-5 and again.converged, again.ratio
      if again.converged then break end
    end
    steps_damping()
  end
  if not ok then
    local why = tostring(result):gsub("^.-cycle %d+: ", "")
    print(("  stopped at step %d: %s"):format(i, why))  -- whole: the table keeps its first 160 characters
    stopped = ("step %d: %s"):format(i, why:sub(1, 160))
    break
  end
  if not result.converged then unconverged[#unconverged + 1] = i end
  judgments = judgments + result.judgments
  if BOLTS ~= "none" and BOLT_AT == "solved" then bolt_step(s) end
  done = i
  print(("  %5d %-20s %7d %9.2e %10.4f %7d %6d %6d %6d%s"):format(i, s.name, result.cycles, result.ratio,
    settlement(), info().cracks, result.judgments, fallen, os.time() - started,
    result.converged and "" or "  NOT CONVERGED"))
  if not result.converged then
    local why = still_moving()
    unconverged_why[#unconverged_why + 1] = ("step %d %s"):format(i, why)
    print(("        step %d short of its ratio, %s"):format(i, why))
  end
  append_row(STEPS_TABLE, select(2, result_row()))
  if i == given.save_after then save(("%s_step%d.h5"):format(tag, i)) end
end
cancel(mucking)

local r, line, named = result_row()
append_row(TABLE, line)
result(named)
local fell = points_fallen()
print(("%s: %d steps, %d cracks (%d tension, %d shear; %d left, %d right), crown %.4f m, walls in %.4f (left) "
       .. "and %.4f m (right), 5 m behind their faces %.4f and %.4f m (down %.4f and %.4f m), 15 m behind %.4f "
       .. "and %.4f m, "
       .. "10 m above the crown left / right half %.4f / %.4f m, %d contacts slipping, %d fallen, "
       .. "%d bolts (%d skipped, %d broken), %d s%s"):format(
  tag, done, r.tension + r.shear, r.tension, r.shear, r.left, r.right, settlement(), r.left_moves, r.right_moves,
  r.left_moves_5m, r.right_moves_5m, r.left_settles_5m, r.right_settles_5m, r.left_moves_15m, r.right_moves_15m,
  r.profile_left, r.profile_right, r.slipping, fallen, laid, skipped, r.bolts_broken, r.seconds,
  stopped ~= "" and ("; stopped at " .. stopped) or "")
  .. (#unconverged > 0 and ("; short of equilibrium after step " .. table.concat(unconverged, ", ")) or "")
  .. (fell ~= "" and ("; measuring points whose blocks fell (mucked out, or onto the floor): " .. fell) or ""))

-- Where the cracks came from: the potential crack by distance from the outline, the length broken
-- against the length placed.
do
  local broken = {}
  for k in cracks() do broken[k.section] = true end
  local bands = { { 0, 2 }, { 2, 5 }, { 5, 10 }, { 10, 20 }, { 20, math.huge } }
  local placed, split = {}, {}
  for i = 1, #bands do placed[i], split[i] = 0, 0 end
  for sec in sections() do
    local d = shapes.distance_to(c.outline, sec.x, sec.y)
    for i, band in ipairs(bands) do
      if d >= band[1] and d < band[2] then
        placed[i] = placed[i] + sec.length
        if broken[sec.id] then split[i] = split[i] + sec.length end
      end
    end
  end
  local parts = {}
  for i, band in ipairs(bands) do
    parts[i] = ("%s m %.0f / %.0f"):format(band[2] < math.huge and ("%g-%g"):format(band[1], band[2])
                                            or ("beyond %g"):format(band[1]), split[i], placed[i])
  end
  print(("%s: potential crack broken / placed by distance from the outline [m]: %s"):format(
    tag, table.concat(parts, ", ")))
end

do
  local e = energy()
  print(("%s: energy balance of the excavation [J/m]: gravity %.4g, boundary %.4g, loads taken off %.4g, "
         .. "prestress %.4g, dug out %.4g; stored %.4g; slip %.4g, plastic %.4g, bonds %.4g, damping %.4g, bolts %.4g; "
         .. "error %.3g (%.2g %% of the largest term, %.4g; arising in the zones %.3g, the contacts %.3g "
         .. "(%.3g of it where contacts started anew on another face), the bolts %.3g)"):format(
    tag, e.gravity, e.boundary, e.release, e.prestress, e.excavated, e.kinetic + e.strain + e.contact + e.bolt,
    e.slip, e.plastic, e.bond, e.damping, e.bolt_plastic, e.error, 100 * e.relative_error, e.largest,
    e.zone_error, e.contact_error, e.restarted, e.bolt_error))
end
plot{ file = tag .. "_cracks.png", show = { "blocks", "cracks", "bolts" }, window = { -50, 50, -40, 50 } }
local final_profile = profile{ from = PROFILE_LINE.from, to = PROFILE_LINE.to, quantity = "uy",
                               points = PROFILE_LINE.points, file = tag .. "_profile.png",
                               title = tag .. ": vertical displacement 10 m above the crown" }
-- The same as numbers, for figure12.lua's chart of the runs with and without bolts (study.sh).
do
  local f = assert(io.open(tag .. "_profile.csv", "w"))
  f:write("x_m,uy_m\n")
  for i, x in ipairs(final_profile.x) do f:write(("%.3f,%.6f\n"):format(x, final_profile.value[i])) end
  f:close()
end
if given.strict and stopped ~= "" then error("stopped at " .. stopped, 0) end
