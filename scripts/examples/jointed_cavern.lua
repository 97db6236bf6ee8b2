-- The main example: what EDEM is for, in about a minute. The seed paper's 24 m x 48 m warhead
-- cavern, its crown 158 m deep, in rock cut by the seed's Case 3 joints (60 deg at 16, 12 and 8 m
-- in turn, a cross set every 16 m), with the seed's consistent parameter set P (edem.seed). It is
-- the study of scripts/paper/case.lua made coarser: zones of 3 m at the cavern instead of 1.5, and
-- 6 excavation stages instead of the seed's 16 (the arch in its three steps, the 13 benches as 3).
--   1. Prepass: where does the intact rock yield as the cavern is dug? Mohr-Coulomb blocks on
--      slipping joints, dug stage by stage by the explicit solver (edem.yield_pass, the seed's way).
--   2. Potential cracks there (crackseed{ auto }), with the intact rock's strength.
--   3. The run: elastic blocks, Coulomb joints, the in-situ state; each stage dug, solved, its
--      potential cracks judged at equilibrium (those that fail break, in tension or in shear),
--      then bolted: 5 m bolts every 1.5 m on the walls it exposed (the seed's pattern 1).
-- Writes jointed_cavern.png (the new cracks by mode: tension red, shear blue) and
-- jointed_cavern_settlement.png and .csv (the rock's vertical displacement 10 m above the crown
-- after each stage: the seed's Figure 12).
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local rockbolts = require "edem.bolts"
local yield_pass = require "edem.yield_pass"

-- The region: 200 m x 180 m, joints, the stages cut in as regions, zoned, loaded (edem.seed).
local c = cavern.warhead{ benches = 3 }  -- arch centre, arch left, arch right, bench 1, 2, 3
local function build()
  seed.region{ case = 3, set = "P", depth = 158, regions = c.stages, near = { c.outline },
               edge = 3, far = 15, tolerance = 7e-4 }
end
local rock = seed.P.rock
local names = {}
for _, s in ipairs(c.stages) do names[#names + 1] = s.name end

-- 1. The prepass digs the model: build it again afterwards for the cracks.
build()
seed.intact("P")  -- Mohr-Coulomb: the prepass's rock, and the potential cracks' strength
local n = info()
print(("model: %d blocks, %d zones; prepass: digging its %d stages in Mohr-Coulomb rock"):format(
      n.blocks, n.zones, #names))
local pre = yield_pass.run{ stages = names, release = 100, max_cycles = 10000, damping = "local" }
build()
yield_pass.check(pre)
seed.intact("P")
local yielded = 0
for _, z in ipairs(pre.zones) do if z.state ~= "none" then yielded = yielded + 1 end end

-- 2. Potential cracks in the yielded zones, 4.8 m apart (a tenth of the cavern's height), judged
-- on each solved state; then the blocks elastic (seed.region{} gave the joints Set P's law).
judge{ at = "equilibrium" }
local groups = crackseed{ auto = pre, spacing = 4.8, material = "intact", similar = 45, min_angle = 30 }
material{ "rock", density = rock.density, young = rock.young, poisson = rock.poisson }
assign{ material = "rock" }
print(("prepass: %d zones yielded -> %d groups of potential cracks, %d sections; the run:"):format(
      yielded, #groups, info().sections))

-- 3. The in-situ state, displacements from there on.
solve{ ratio = 1e-6, max_cycles = 20000 }
reset{ "displacement", "velocity", "joint" }
set{ damping = "local", local_damping = 0.8 }
bolt_material{ "bolt", young = 190e9, area = 446e-6, density = 6083, yield_tension = 0.156e6,
               failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }

-- Rock that comes loose (loose at two checks in a row, 200 cycles apart) is mucked out, except
-- rock of a stage not dug yet.
local stage_of, dug_at = {}, {}
for k, name in ipairs(names) do stage_of[name] = k end
for b in blocks() do
  for _, name in ipairs(b.regions) do dug_at[b.id] = dug_at[b.id] or stage_of[name] end
end
local now, fallen, loose_before = 0, 0, {}
local mucking = every(200, function()
  local loose_now = {}
  for b in loose_blocks{} do
    loose_now[b.id] = true
    if loose_before[b.id] and (dug_at[b.id] or 0) <= now then excavate{ block = b.id }; fallen = fallen + 1 end
  end
  loose_before = loose_now
end)

local y10 = c.crown[2] + 10  -- the settlement line, 10 m above the crown
local series, bolts_laid = {}, 0
print("stage          cycles  cracks  tension  shear  bolts  crown uy [mm]")
for k, s in ipairs(c.stages) do
  now = k
  excavate{ region = s.name, release = 100 }
  local r = solve{ ratio = 1e-5, max_cycles = 10100 }
  -- Rock creeping on soft joints may settle no further: judge its state at ten times the ratio.
  if not r.converged then r.cycles = r.cycles + solve{ ratio = 1e-4, max_cycles = 20000 }.cycles end
  local _, laid = rockbolts.pattern{ surface = rockbolts.exposed(s, c.outline), spacing = 1.5, length = 5,
                                     segments = 10, material = "bolt", missing = "skip" }
  bolts_laid = bolts_laid + laid
  local crown = profile{ from = c.crown, to = { 0, y10 }, points = 2, quantity = "uy" }.value[1]
  local p = profile{ from = { -60, y10 }, to = { 60, y10 }, points = 41, quantity = "uy" }
  local name = s.name:gsub("^warhead_", "")
  series[k] = { name = "after " .. name, x = p.x, y = {} }
  for i, v in ipairs(p.value) do series[k].y[i] = 1000 * v end
  n = info()
  print(("%-13s %7d %7d %8d %6d %6d %14.0f"):format(name, r.cycles, n.cracks, n.tension_cracks,
        n.shear_cracks, bolts_laid, 1000 * crown))
end
cancel(mucking)

-- The pictures: the new cracks by mode (add "bolts" to show to draw the bolts by axial force),
-- and the settlement profile after each stage, drawn and as numbers.
plot{ file = "jointed_cavern.png", show = { "blocks", "joints", "cracks" }, window = { -45, 45, -40, 50 } }
chart{ file = "jointed_cavern_settlement.png", series = series, x_label = "x [m]", y_label = "uy [mm]",
       title = "Vertical displacement 10 m above the crown, after each stage" }
local csv = assert(io.open("jointed_cavern_settlement.csv", "w"))
csv:write("x_m")
for _, s in ipairs(series) do csv:write(",uy_mm_", (s.name:gsub("^after ", ""))) end
csv:write("\n")
for i, x in ipairs(series[1].x) do
  csv:write(("%.2f"):format(x))
  for _, s in ipairs(series) do csv:write((",%.1f"):format(s.y[i])) end
  csv:write("\n")
end
csv:close()
local lowest = math.huge
for _, v in ipairs(series[#series].y) do lowest = math.min(lowest, v) end
print(("%d cracks (%d tension, %d shear), %d bolts, %d loose blocks mucked out; 10 m above the crown "
       .. "the rock settles up to %.0f mm"):format(n.cracks, n.tension_cracks, n.shear_cracks, bolts_laid,
       fallen, -lowest))
print("wrote jointed_cavern.png (cracks by mode), jointed_cavern_settlement.png and .csv")
