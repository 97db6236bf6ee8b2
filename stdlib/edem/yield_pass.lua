-- edem.yield_pass: where a jointed rock mass yields as it is excavated, found by the explicit
-- solver itself: Mohr-Coulomb blocks and Coulomb joints that slip and open, each stage dug,
-- released and solved to its ratio in turn, rock that comes loose mucked out. This is UDEC's
-- elastoplastic analysis of the jointed mass, the seed's way of finding where potential cracks
-- belong. prepass{ joints = true } poses the same problem to Newton's method, which has no answer
-- once a block is free to fall out of the roof; here the block falls and is mucked out.
--
--   local pass = require("edem.yield_pass").run{ stages = { "arch", "bench1" } }
--   model{} ... (the same model built again)
--   crackseed{ auto = pass, spacing = 4.8 }
--
-- Call it on the model as it stands before the excavation: zones of a Mohr-Coulomb material,
-- jointed contacts with their joint material, loads and boundaries. It solves the in-situ state
-- first. It changes the model (it digs it): build the same model again (model{} and the same
-- commands) before placing cracks from the result; yield_pass.check(result) then stops the script
-- unless the model built again has the zones the pass ran on.
--
-- Keys (defaults in brackets):
--   stages      region names excavated in turn (required)
--   release     cycles over which a stage's load comes off [100]
--   ratio       a stage is solved to this ratio [1e-5]
--   max_cycles  cycles after the release before a stage is left short of its ratio [40000]
--   stall       a stage's solve ends short of its ratio once it has not fallen a tenth below its
--               lowest in this many cycles (solve{ stall }) [0: never]
--   damping     "local" (0.8) or "adaptive": the stages' damping, set after the in-situ solve
--               [the model's]
--   muck        true: every 200 cycles, blocks loose at two checks in a row (loose_blocks{}) are
--               mucked out, except rock of a stage not yet dug [true]
--   after_stage function(k, name): called after each stage is solved (e.g. to plot{} the
--               "plastic" layer, the seed's Figure 8) [none]
-- Returns, in prepass{}'s form for crackseed{ auto }: zones (id, x, y, state: none, shear,
-- tension or shear+tension, ever yielded; states: the same after each stage, "excavated" once
-- dug; angle: the most compressive principal stress's direction from +x at the end, in (-90, 90]
-- degrees; work: the plastic work done in it per unit volume [J/m^3] up to the last stage it was
-- in place), stages (name, cycles, ratio, converged), fallen (blocks mucked out), failure (where a
-- stage stopped on an error: the pass ends there, as prepass{ on_failure = "keep" }), seconds.
local yield_pass = {}

local function yield_name(state)
  local shear, tension = state:find("shear", 1, true), state:find("tension", 1, true)
  if shear and tension then return "shear+tension" end
  return shear and "shear" or tension and "tension" or "none"
end

-- The most compressive principal stress's direction from +x (compression negative), as prepass{}.
local function principal_angle(z)
  local angle = 0.5 * math.deg(math.atan(2 * z.sxy, z.sxx - z.syy)) + 90
  if angle > 90 then angle = angle - 180 end
  return angle
end

function yield_pass.run(t)
  assert(type(t) == "table" and type(t.stages) == "table" and #t.stages > 0,
         "yield_pass.run: give stages, the region names excavated in turn")
  local release, ratio, max_cycles = t.release or 100, t.ratio or 1e-5, t.max_cycles or 40000
  local started = os.clock()
  local stage_of = {}
  for k, name in ipairs(t.stages) do stage_of[name] = k end
  local dug_at = {}  -- block id -> the stage that digs it
  for b in blocks() do
    for _, name in ipairs(b.regions) do
      if stage_of[name] then dug_at[b.id] = stage_of[name] end
    end
  end

  local result = { zones = {}, stages = {}, fallen = 0 }
  local index = {}  -- zone id -> its entry in result.zones
  for z in zones() do
    local entry = { id = z.id, x = z.x, y = z.y, state = "none", states = {} }
    result.zones[#result.zones + 1] = entry
    index[z.id] = entry
  end

  solve{ ratio = 1e-6, max_cycles = 20000 }
  reset{ "displacement", "velocity", "joint" }
  if t.damping == "local" then
    set{ damping = "local", local_damping = 0.8 }
  elseif t.damping ~= nil then
    set{ damping = t.damping }
  end

  local now, mucked, loose_before = 0, {}, {}
  local function muck_out()
    local loose_now = {}
    for b in loose_blocks{} do
      loose_now[b.id] = true
      local later = dug_at[b.id] and dug_at[b.id] > now
      if loose_before[b.id] and not later then
        excavate{ block = b.id }
        mucked[b.id] = true
        result.fallen = result.fallen + 1
      end
    end
    loose_before = loose_now
  end
  local mucking = (t.muck ~= false) and every(200, muck_out) or nil

  for k, name in ipairs(t.stages) do
    now = k
    local ok, r = pcall(function()
      local dug, why = pcall(excavate, { region = name, release = release })
      if not dug and not tostring(why):find("was excavated already", 1, true) then error(why, 0) end
      return solve{ ratio = ratio, max_cycles = release + max_cycles, stall = t.stall or 0 }
    end)
    if not ok then
      result.failure = ("%s: %s"):format(name, (tostring(r):gsub("^.-cycle %d+: ", "")))
      break
    end
    result.stages[k] = { name = name, cycles = r.cycles, ratio = r.ratio, converged = r.converged }
    for z in zones() do
      local entry = index[z.id]
      local dug = z.excavated and not mucked[z.block]
      entry.states[k] = dug and "excavated" or yield_name(z.state)
      if not dug then
        entry.state = entry.states[k] ~= "none" and entry.states[k] or entry.state
        entry.angle = principal_angle(z)
        entry.work = z.plastic_work
      end
    end
    if t.after_stage then t.after_stage(k, name) end
  end
  if mucking then cancel(mucking) end
  for _, entry in ipairs(result.zones) do entry.angle, entry.work = entry.angle or 0, entry.work or 0 end
  result.seconds = os.clock() - started
  return result
end

-- Stops the script unless the present model's zones are those `result` was found on: the same
-- count, and each zone's centroid where it was (crackseed{ auto } places cracks by zone number).
function yield_pass.check(result)
  local k = 0
  for z in zones() do
    k = k + 1
    local entry = result.zones[k]
    if not entry or entry.id ~= z.id or math.abs(entry.x - z.x) + math.abs(entry.y - z.y) > 1e-9 then
      error(("yield_pass.check: zone %d is not where the pass found it: build the model as before the pass")
            :format(z.id), 2)
    end
  end
  if k ~= #result.zones then
    error(("yield_pass.check: %d zones, the pass ran on %d: build the model as before the pass")
          :format(k, #result.zones), 2)
  end
end

return yield_pass
