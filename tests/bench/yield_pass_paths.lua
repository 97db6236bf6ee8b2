-- The jointed prepass of the seed's cavern (edem.yield_pass, as scripts/paper/case.lua runs it)
-- under several releases and dampings: what it costs, and how far the zones it finds yielded and
-- the potential cracks placed from them move with that numerical detail, against the first
-- variant's (tests/bench/RESULTS.md, "The jointed prepass: release and damping").
--
--   edem --threads 1 run tests/bench/yield_pass_paths.lua
--
-- Settings: case, set, depth (edem.seed.region's), variants (damping:release[:ratio[:stall]],
-- separated by commas; damping local, 0.8, or adaptive; release in cycles; ratio each stage is
-- solved to, 1e-5 if left out; stall, yield_pass's, 0 if left out; the first is the reference),
-- stages (how many of the 16 to dig), near (m: a section counts as placed where the reference has
-- one if their midpoints are this close),
-- min_work (J/m^3: a zone counts as yielded, for the comparison and for the cracks, only if its
-- plastic work reached this; 0: every zone that reached its strength).
local s = settings{ case = 3, set = "P", depth = 158, stages = 16, near = 1.0, min_work = 0,
                    variants = "local:10000,local:1,local:100,adaptive:100,adaptive:10000" }
local seed = require "edem.seed"
local cavern = require "edem.cavern"
local yield_pass = require "edem.yield_pass"

local variants = {}
for text in tostring(s.variants):gmatch("[^,]+") do
  local damping, release, ratio, stall = text:match("^(%a+):(%d+):?([%d.e+-]*):?(%d*)$")
  if not (damping == "local" or damping == "adaptive") then
    error(("variants: each is damping:release[:ratio[:stall]], damping local or adaptive, got %s")
          :format(text), 0)
  end
  ratio = ratio ~= "" and tonumber(ratio) or 1e-5
  if not (ratio and ratio > 0 and ratio < 1) then
    error(("variants: the ratio must be in (0, 1), got %s"):format(text), 0)
  end
  variants[#variants + 1] = { name = text, damping = damping, release = math.tointeger(tonumber(release)),
                              ratio = ratio, stall = stall ~= "" and math.tointeger(tonumber(stall)) or 0 }
end
if #variants == 0 then error("give variants, e.g. local:10000,adaptive:100", 0) end

local c = cavern.warhead{}
local names = {}
for k = 1, math.min(s.stages, #c.stages) do names[k] = c.stages[k].name end
local function build()
  seed.region{ case = s.case, set = s.set, depth = s.depth, regions = c.stages, near = { c.outline }, edge = 1.5,
               far = 10, tolerance = 7e-4 }
  seed.intact(s.set)
end

-- One variant: the prepass, then the model built again and the potential cracks placed as
-- case.lua places them. Returns the zones ever yielded (id -> true), the sections' midpoints and
-- lengths, and the counts.
local function run(v)
  build()
  local clock = os.clock()
  local pre = yield_pass.run{ stages = names, release = v.release, damping = v.damping, ratio = v.ratio,
                              stall = v.stall }
  local seconds = os.clock() - clock
  local cycles, short = 0, 0
  for _, st in ipairs(pre.stages) do
    cycles = cycles + st.cycles
    if not st.converged then short = short + 1 end
  end
  local yielded, count = {}, 0
  for _, z in ipairs(pre.zones) do
    if z.work < s.min_work then z.state = "none" end
    if z.state ~= "none" then yielded[z.id], count = true, count + 1 end
  end
  build()
  yield_pass.check(pre)
  local groups = crackseed{ auto = pre, spacing = 4.8, material = "intact", similar = 45, min_angle = 30 }
  local placed, length = {}, 0
  for sec in sections() do
    placed[#placed + 1] = { x = sec.x, y = sec.y, length = sec.length }
    length = length + sec.length
  end
  return { yielded = yielded, count = count, sections = placed, length = length, groups = #groups,
           cycles = cycles, short = short, seconds = seconds, failure = pre.failure }
end

-- Of a's crack length, the share whose sections have one of b's within `near` metres.
local function placed_alike(a, b)
  local alike = 0
  for _, p in ipairs(a.sections) do
    for _, q in ipairs(b.sections) do
      if (p.x - q.x) ^ 2 + (p.y - q.y) ^ 2 <= s.near ^ 2 then
        alike = alike + p.length
        break
      end
    end
  end
  return a.length > 0 and alike / a.length or 1
end

print(("%-22s %8s %6s %5s %8s %8s %6s %8s %9s %9s"):format("damping:release", "cycles", "short", "s", "yielded",
                                                             "shared", "groups", "sections", "length", "alike"))
local reference
for _, v in ipairs(variants) do
  local r = run(v)
  reference = reference or r  -- the first variant's
  local both, either = 0, 0
  for id in pairs(r.yielded) do
    either = either + 1
    if reference.yielded[id] then both = both + 1 end
  end
  for id in pairs(reference.yielded) do if not r.yielded[id] then either = either + 1 end end
  -- shared: zones yielded in both over those yielded in either (1 for the reference); alike:
  -- the crack length placed where the reference places it, the less of the two ways round.
  local alike = math.min(placed_alike(r, reference), placed_alike(reference, r))
  print(("%-22s %8d %6d %5.0f %8d %8.2f %6d %8d %9.1f %9.2f%s"):format(v.name, r.cycles, r.short, r.seconds, r.count,
    either > 0 and both / either or 1, r.groups, #r.sections, r.length, alike,
    r.failure and ("  stopped: " .. r.failure) or ""))
end
