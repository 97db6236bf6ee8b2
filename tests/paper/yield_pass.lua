-- edem.yield_pass (case.lua's jointed prepass): a jointed square with a hole dug in two stages
-- under a high in-situ stress. Its result has prepass{}'s form for crackseed{ auto }: every zone
-- once, a state per stage, the dug zones "excavated", rock beside the hole yielded; the model
-- built again passes yield_pass.check, one zoned otherwise does not; and crackseed{ auto } lays
-- cuts from it.
local yield_pass = require "edem.yield_pass"

local function build(edge)
  model{ title = "yield pass" }
  block{ x = {-20, 20}, y = {-20, 20} }
  jset{ angle = 60, spacing = 7 }
  region{ name = "top", polygon = { {-3, 0}, {3, 0}, {3, 3}, {-3, 3} } }
  region{ name = "bottom", polygon = { {-3, -3}, {3, -3}, {3, 0}, {-3, 0} } }
  zone{ edge = edge, near = { "top", "bottom" }, far = 4 }
  material{ "intact", model = "mohr", density = 2700, young = 7e9, poisson = 0.2, cohesion = 1e6,
            friction = 34, tension = 0.5e6 }
  assign{ material = "intact" }
  joint_material{ "joint", kn_law = "seed-cubic", stress_scale = 17.86, closure_scale = 400, ks = 3.6e6,
                  friction = 31 }
  jassign{ material = "joint" }
  insitu{ sxx = -12e6, syy = -12e6 }
  for _, side in ipairs{ "left", "right" } do boundary{ side = side, fix = "x" } end
  for _, side in ipairs{ "top", "bottom" } do boundary{ side = side, fix = "y" } end
end

build(1)
local zones_before = info().zones
local pass = yield_pass.run{ stages = { "top", "bottom" } }
assert(not pass.failure, "the pass stopped: " .. tostring(pass.failure))
assert(#pass.zones == zones_before, ("%d zones in the result, %d in the model"):format(#pass.zones, zones_before))
local dug, yielded = 0, 0
for _, z in ipairs(pass.zones) do
  assert(#z.states == 2, ("zone %d has %d states, not 2"):format(z.id, #z.states))
  assert(z.angle > -90 and z.angle <= 90, ("zone %d: angle %g"):format(z.id, z.angle))
  if z.states[2] == "excavated" then dug = dug + 1 elseif z.state ~= "none" then yielded = yielded + 1 end
end
print(("yield pass: %d zones, %d dug, %d yielded beside the hole, stages %d and %d cycles"):format(
  #pass.zones, dug, yielded, pass.stages[1].cycles, pass.stages[2].cycles))
assert(dug > 0 and yielded > 0, "the hole is dug and rock beside it yields")

build(1)
yield_pass.check(pass)
material{ "rock", density = 2700, young = 7e9, poisson = 0.2 }
local groups = crackseed{ auto = pass, spacing = 1.5, material = "intact" }
assert(#groups > 0 and info().sections > 0, "crackseed{ auto } lays cuts from the pass")
print(("crackseed: %d groups, %d sections"):format(#groups, info().sections))

build(1.5)
local ok, why = pcall(yield_pass.check, pass)
assert(not ok and tostring(why):find("build the model as before the pass", 1, true),
       "a model zoned otherwise is refused: " .. tostring(why))
print("yield_pass.check refuses a model zoned otherwise")
