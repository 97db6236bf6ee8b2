-- The main example: the seed paper's 200 m x 180 m region with the Case 3 joints (angle 60,
-- spacing 16/12/8 m in turn, and a cross set at right angles), the 24 m x 48 m warhead
-- cavern outline as a glued region, zoned finely near the cavern and coarsely far away.
-- Prints the model's counts and writes jointed_cavern.png.

model{ title = "Jointed cavern: Case 3 joints around a 24 m x 48 m warhead" }
block{ x = {-100, 100}, y = {-90, 90} }
jset{ angle = 60, spacing = {16, 12, 8} }   -- main set, dips towards -x
jset{ angle = -30, spacing = 16 }           -- cross set

-- Warhead outline centred on the origin: vertical walls, flat floor, circular arch whose
-- rise is `rise`; the roof (crown) is at y = height / 2.
local function warhead(width, height, rise, arc_segments)
  local half, top = width / 2, height / 2
  local radius = (half * half + rise * rise) / (2 * rise)
  local centre = top - radius
  local start = math.atan(top - rise - centre, half)
  local outline = { {-half, -top}, {half, -top} }
  for i = 0, arc_segments do
    local a = start + (math.pi - 2 * start) * i / arc_segments
    outline[#outline + 1] = { radius * math.cos(a), centre + radius * math.sin(a) }
  end
  return outline
end

region{ name = "cavern", polygon = warhead(24, 48, 8, 16) }
zone{ edge = 1.0, far = 8, near = "cavern" }

local counts = info()
print(("blocks %d, zones %d, gridpoints %d, joint edges %d, dropped cuts %d"):format(
  counts.blocks, counts.zones, counts.gridpoints, counts.joint_edges, counts.dropped_cuts))

local area = 0
for b in blocks() do area = area + b.area end
print(("block area %.9f m2 (region 36000 m2)"):format(area))

plot{ file = "jointed_cavern.png", show = { "zones", "blocks", "joints", "regions" } }
print("wrote jointed_cavern.png")
