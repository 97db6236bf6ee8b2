-- The prepass's restarts (prepass{ restarts }): where Newton fails on one load path, a finer path
-- from the stage's start gets through, and gives what a fine path from the first stage gives.
-- The scene is the paper study's at 212 m (scripts/paper/case.lua: Case 3, Set M's rock as
-- Mohr-Coulomb, joints tied, the warhead's 16 stages, 1.5 m zones at the cavern). In 2 load steps a
-- stage, Newton stops at bench 12 (stage 15) at load factor 0.625, where no step however small
-- converges: not a collapse, for the same rock completes every stage deeper down, at 262 m, and in
-- 10 steps a stage at 212 m too. With the restarts the stage is solved again in 4 steps.
-- Checks: with restarts every stage completes; the zones yielded over all stages agree with the
-- 10-step path's (intersection over union at least 0.95, counts within 2 %). The one-attempt
-- path's stop is printed, not checked: a better Newton may well get through it.
-- Run: cd stdlib && ../build/interp/edem ../tests/verification/long/prepass_load_path.lua
local check = require "edem.check"
local seed = require "edem.seed"
local cavern = require "edem.cavern"

local c = cavern.warhead{}
seed.region{ case = 3, set = "M", depth = 212, regions = c.stages, near = { c.outline }, edge = 1.5, far = 10,
             tolerance = 7e-4 }
local rock = seed.M.rock
material{ "intact", model = "mohr", density = rock.density, young = rock.young, poisson = rock.poisson,
          cohesion = rock.cohesion, friction = rock.friction, tension = rock.tension }
assign{ material = "intact" }
local names = {}
for _, s in ipairs(c.stages) do names[#names + 1] = s.name end

local function yielded_zones(pre)
  local set, count = {}, 0
  for _, z in ipairs(pre.zones) do
    if z.state ~= "none" then set[z.id], count = true, count + 1 end
  end
  return set, count
end

local once = prepass{ stages = names, joints = false, steps = 2, restarts = 0, on_failure = "keep", solver = "lu" }
local last = once.stages[#once.stages]
print(("one attempt a stage, 2 steps: %d of 16 stages complete, %s at load factor %.4g"):format(
  #once.stages - 2 + (once.failure and 0 or 1), last.name, last.reached))

local retried = prepass{ stages = names, joints = false, steps = 2, on_failure = "keep", solver = "lu" }
local complete, restarted = 0, {}
for i = 2, #retried.stages do
  local s = retried.stages[i]
  if s.reached == 1 and not s.failure then complete = complete + 1 end
  if s.restarts > 0 then restarted[#restarted + 1] = ("%s (%d)"):format(s.name, s.restarts) end
end
print("stages solved again from their start: " .. (#restarted > 0 and table.concat(restarted, ", ") or "none"))
check.report("stages complete with restarts, 2 steps a stage", complete, 16, 0, { absolute = true })

local fine = prepass{ stages = names, joints = false, steps = 10, on_failure = "keep", solver = "lu" }
local a, na = yielded_zones(retried)
local b, nb = yielded_zones(fine)
local both, either = 0, 0
for id in pairs(a) do
  if b[id] then both = both + 1 end
  either = either + 1
end
for id in pairs(b) do if not a[id] then either = either + 1 end end
check.report("zones yielded, 2 steps and restarts against 10 steps", na, nb, 0.02)
check.report("yielded zones, intersection over union (>= 0.95)", both / either, 1, 0.05, { absolute = true })
check.finish()
