-- Tutorial 2: reading the model from a script, and what happens when a command is wrong.
--
-- Layered rock: horizontal bedding every 4 m and vertical joints every 6 m, with two stage
-- outlines of an excavation as regions. The script reports the blocks of each stage, finds
-- the largest block, and shows that a rejected command changes nothing.

model{ title = "Tutorial 2: bedded rock with two excavation stages" }
block{ x = {0, 48}, y = {0, 32} }
jset{ angle = 0, spacing = 4, origin = {0, 2} }     -- bedding
jset{ angle = 90, spacing = 6, origin = {3, 0} }    -- vertical joints

local stages = {
  { name = "heading", polygon = {{18, 16}, {30, 16}, {30, 22}, {18, 22}} },
  { name = "bench", polygon = {{18, 10}, {30, 10}, {30, 16}, {18, 16}} },
}
for _, stage in ipairs(stages) do region(stage) end
zone{ edge = 0.75, far = 3, near = { "heading", "bench" } }

-- Area and block count per stage; `b.region` is the innermost region holding a block.
local per_stage = {}
for b in blocks() do
  if b.region then
    local s = per_stage[b.region] or { blocks = 0, area = 0 }
    s.blocks, s.area = s.blocks + 1, s.area + b.area
    per_stage[b.region] = s
  end
end
for _, stage in ipairs(stages) do
  local s = per_stage[stage.name]
  print(("%-8s %2d blocks, %6.2f m2"):format(stage.name, s.blocks, s.area))
  assert(math.abs(s.area - 72) < 1e-9, "each stage is 12 m x 6 m")
end

-- The largest block, its corners and its zones.
local largest
for b in blocks() do
  if not largest or b.area > largest.area then largest = b end
end
print(("largest block #%d: %.1f m2 at (%.1f, %.1f), %d corners, %d zones"):format(
  largest.id, largest.area, largest.x, largest.y, #largest.vertices, largest.zones))

-- Zones know their block and region.
local heading_zones = 0
for z in zones() do
  if z.region == "heading" then heading_zones = heading_zones + 1 end
end
assert(heading_zones > 0)

-- A wrong command stops a script with "FILE:LINE: command: what is wrong". Caught with
-- pcall, it returns that message, and the model is exactly as it was before.
local before = info()
local ok, message = pcall(jset, { angle = 45, spacing = 0 })
assert(not ok)
print("rejected: " .. message)
local after = info()
assert(after.joint_sets == before.joint_sets and after.blocks == before.blocks)

plot{ file = "reading_the_model.svg", show = { "regions", "zones", "joints" }, size = {960, 640} }
print("wrote reading_the_model.svg")
