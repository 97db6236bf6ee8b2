-- The implicit prepass through the seed cavern's 16 stages (tests/bench/RESULTS.md, issue 7):
-- the seed region (Set P, Case 3 joints tied shut: joints = false), Mohr-Coulomb rock, the
-- warhead of edem.cavern; seconds and Newton iterations per stage. JOINTS=1 in the environment:
-- joints as interface elements instead, with Set P's joints (no static state: the run stops at
-- stage 3 or 4, tests/verification/prepass_seed_cavern.lua tells why); JOINTS=bonded: as interface
-- elements, bonded and stiff (kn = ks = 5e11 Pa/m), the model of that verification script.
-- Run: cd stdlib && ../build/interp/edem ../tests/bench/prepass_seed_cavern.lua EDGE STEPS SOLVER [PICTURE.png]
--   EDGE: zone edge at the cavern [m] (1.5: ~7k zones; 0.5: ~50k), STEPS: load steps per stage
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local edge, steps, solver = tonumber(arg[1]) or 1.5, tonumber(arg[2]) or 5, arg[3] or "umfpack"
local c = cavern.warhead{}
local n = seed.region{ regions = c.stages, near = { c.outline }, edge = edge, far = 10, tolerance = 1e-3 }
seed.elastoplastic{ bonded = os.getenv("JOINTS") == "bonded" }
local names = {}
for _, s in ipairs(c.stages) do names[#names + 1] = s.name end
local joints = os.getenv("JOINTS") == "1" or os.getenv("JOINTS") == "bonded"
local pre = prepass{ stages = names, joints = joints, steps = steps, solver = solver }
local yielded, iterations = 0, 0
for _, z in ipairs(pre.zones) do if z.state ~= "none" then yielded = yielded + 1 end end
for i, s in ipairs(pre.stages) do
  iterations = iterations + s.iterations
  print(("%2d %-22s %4d iterations %2d cut-backs %7.2f s"):format(i - 1, s.name, s.iterations, s.cutbacks, s.seconds))
end
print(("%d zones, edge %g m, %d steps a stage, %s: %d iterations, %d zones yielded, %.2f s"):format(
  n.zones, edge, steps, solver, iterations, yielded, pre.seconds))
if arg[4] then plot{ file = arg[4], show = { "prepass", "joints" } } print("wrote " .. arg[4]) end
