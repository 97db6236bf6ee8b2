-- Speed against accuracy, implicit prepass against the explicit solver: two charts and a table
-- for tests/bench/RESULTS.md.
--   1. Salencon (stdlib/edem/salencon.lua, psi = 0) over mesh sizes: the relative error of the wall
--      displacement against the run time. Implicit: prepass{ steps = 1 } (1, 10 and 100 steps agree
--      within 0.3 %: tests/verification/salencon_implicit.lua). Explicit: solve{} from the same
--      state to a ratio of 1e-5 and of 1e-6.
--   2. The seed cavern's 16 stages (tests/verification/prepass_seed_cavern.lua's model: Set P rock,
--      Mohr-Coulomb, bonded stiff joints) over mesh sizes: seconds per stage to a converged state
--      against the number of zones. Implicit: prepass{ joints = true, steps = 2 }. Explicit:
--      excavate{ release = 2000 }, solve{ ratio = 1e-5 } a stage.
-- Times are CPU seconds (os.clock) and the prepass's own clock; run with OMP_NUM_THREADS=1 so that
-- both are one core's.
-- Run: cd stdlib && OMP_NUM_THREADS=1 ../build/interp/edem ../tests/bench/speed_accuracy.lua [DIR] [quick]
--   DIR: where the two PNGs go (default .); quick: the two coarsest meshes of each only
local salencon = require "edem.salencon"
local seed = require "edem.seed"
local cavern = require "edem.cavern"

local dir = arg[1] or "."
local quick = arg[2] == "quick"
local function pick(list) return quick and { list[1], list[2] } or list end
local function wall_error()
  local a = salencon.a
  local u = 0.5 * (-gp_near(a, 0).ux - gp_near(0, a).uy)
  local expected = salencon.wall_displacement(0)
  return math.abs(u - expected) / expected
end

-- 1. Salencon.
local implicit, explicit5, explicit6 = { x = {}, y = {} }, { x = {}, y = {} }, { x = {}, y = {} }
print("Salencon, psi = 0: edge [m], zones, then seconds and relative wall-displacement error")
for _, edge in ipairs(pick({ 0.2, 0.1, 0.05, 0.035, 0.025 })) do
  salencon.build{ psi = 0, edge = edge }
  local zones = info().zones
  local pre = prepass{ steps = 1 }
  local a = salencon.a
  local side, crown
  for _, g in ipairs(pre.gridpoints) do
    if g.id == gp_near(a, 0).id then side = g end
    if g.id == gp_near(0, a).id then crown = g end
  end
  local expected = salencon.wall_displacement(0)
  local e_implicit = math.abs(0.5 * (-side.ux - crown.uy) - expected) / expected
  table.insert(implicit.x, pre.seconds)
  table.insert(implicit.y, e_implicit)
  local clock = os.clock()
  local r5 = solve{ ratio = 1e-5, max_cycles = 1000000 }
  local t5, e5 = os.clock() - clock, wall_error()
  local r6 = solve{ ratio = 1e-6, max_cycles = 1000000 }
  local t6, e6 = os.clock() - clock, wall_error()
  if not (r5.converged and r6.converged) then error(("explicit, edge %g: did not converge"):format(edge)) end
  table.insert(explicit5.x, t5)
  table.insert(explicit5.y, e5)
  table.insert(explicit6.x, t6)
  table.insert(explicit6.y, e6)
  print(("  %5.3f %6d  implicit %7.2f s %.4f | explicit 1e-5 %7.2f s %.4f (%d cycles) | 1e-6 %7.2f s %.4f (%d cycles)"):format(
    edge, zones, pre.seconds, e_implicit, t5, e5, r5.cycles, t6, e6, r5.cycles + r6.cycles))
end
implicit.name = "implicit prepass (1 load step)"
explicit5.name = "explicit, to ratio 1e-5"
explicit6.name = "explicit, to ratio 1e-6"
chart{ file = dir .. "/speed_salencon.png", title = "Salencon tunnel, psi = 0: wall displacement over mesh sizes",
       x_label = "run time [s, one core]", y_label = "relative error of the wall displacement", log = { "x", "y" },
       series = { implicit, explicit5, explicit6 } }

-- 2. The seed cavern, 16 stages.
local c = cavern.warhead{}
local stages = {}
for _, s in ipairs(c.stages) do stages[#stages + 1] = s.name end
local function build(edge)
  local n = seed.region{ regions = c.stages, near = { c.outline }, edge = edge, far = 10, tolerance = 1e-5 }
  seed.elastoplastic{}
  return n.zones
end
local per_implicit, per_explicit = { x = {}, y = {} }, { x = {}, y = {} }
print("seed cavern, 16 stages: edge [m], zones, seconds per stage, plastic zones, Newton iterations / cycles")
for _, edge in ipairs(pick({ 3, 2, 1.5, 1.0 })) do
  local count = build(edge)
  local pre = prepass{ stages = stages, joints = true, steps = 2 }
  local iterations, plastic = 0, 0
  for i = 2, #pre.stages do iterations = iterations + pre.stages[i].iterations end
  for _, z in ipairs(pre.zones) do
    if z.state ~= "none" and z.states[#z.states] ~= "excavated" then plastic = plastic + 1 end
  end
  local stage_seconds = 0
  for i = 2, #pre.stages do stage_seconds = stage_seconds + pre.stages[i].seconds end
  build(edge)
  solve{ ratio = 1e-6, max_cycles = 40000 }
  local clock, cycles = os.clock(), 0
  for _, s in ipairs(c.stages) do
    excavate{ region = s.name, release = 2000 }
    local r = solve{ ratio = 1e-5, max_cycles = 200000 }
    if not r.converged then error(("explicit, edge %g: stage %s did not converge"):format(edge, s.name)) end
    cycles = cycles + r.cycles
  end
  local explicit_seconds = os.clock() - clock
  local explicit_plastic = 0
  for z in zones() do if not z.excavated and z.state ~= "elastic" then explicit_plastic = explicit_plastic + 1 end end
  table.insert(per_implicit.x, count)
  table.insert(per_implicit.y, stage_seconds / #stages)
  table.insert(per_explicit.x, count)
  table.insert(per_explicit.y, explicit_seconds / #stages)
  print(("  %4.2f %6d  implicit %7.3f s/stage (%d plastic, %d iterations) | explicit %7.3f s/stage (%d plastic, %d cycles)"):format(
    edge, count, stage_seconds / #stages, plastic, iterations, explicit_seconds / #stages, explicit_plastic, cycles))
end
per_implicit.name = "implicit prepass (2 load steps a stage)"
per_explicit.name = "explicit, to ratio 1e-5 a stage"
chart{ file = dir .. "/speed_seed_cavern.png", title = "Seed cavern, 16 stages: time to a converged state",
       x_label = "zones", y_label = "seconds per stage [one core]", log = { "x", "y" },
       series = { per_implicit, per_explicit } }
print("wrote " .. dir .. "/speed_salencon.png and " .. dir .. "/speed_seed_cavern.png")
