-- edem.shapes: polygons for blocks, regions and zoning targets.
--
--   local shapes = require "edem.shapes"
--   shapes.circle{ radius = 5, segments = 64 }                      -- centre {0, 0}
--   shapes.sector{ r0 = 1, r1 = 3, from = 0, to = 90, segments = 16 }  -- ring piece (r0 = 0: pie)
--   shapes.quarter_plate{ hole = 1, size = 20, segments = 64 }       -- [0, size]^2 minus a quarter disc
--   shapes.contains(polygon, x, y)                                   -- is (x, y) inside polygon?
--   shapes.distance_to(polygon, x, y)                                -- to its nearest edge [m]
--
-- Angles in degrees, counter-clockwise from +x; every polygon counter-clockwise.
local shapes = {}

local function centre_of(t) return t.centre or { 0, 0 } end

local function arc(points, c, r, from, to, segments)
  for i = 0, segments do
    local t = math.rad(from + (to - from) * i / segments)
    points[#points + 1] = { c[1] + r * math.cos(t), c[2] + r * math.sin(t) }
  end
end

function shapes.circle(t)
  local c, r, n = centre_of(t), assert(t.radius, "circle needs radius"), t.segments or 64
  local points = {}
  for i = 0, n - 1 do
    local a = 2 * math.pi * i / n
    points[#points + 1] = { c[1] + r * math.cos(a), c[2] + r * math.sin(a) }
  end
  return points
end

function shapes.sector(t)
  local c, n = centre_of(t), t.segments or 16
  local r0, r1 = t.r0 or 0, assert(t.r1, "sector needs r1")
  local points = {}
  if r0 == 0 then points[1] = { c[1], c[2] } end
  arc(points, c, r1, t.from, t.to, n)
  if r0 > 0 then
    local inner = {}
    arc(inner, c, r0, t.from, t.to, n)
    for i = #inner, 1, -1 do points[#points + 1] = inner[i] end
  end
  return points
end

function shapes.quarter_plate(t)
  local a, size, n = assert(t.hole, "quarter_plate needs hole"), assert(t.size), t.segments or 64
  local points = { { a, 0 }, { size, 0 }, { size, size }, { 0, size } }
  local hole = {}
  arc(hole, { 0, 0 }, a, 0, 90, n)
  for i = #hole, 2, -1 do points[#points + 1] = hole[i] end  -- (0, a) down to just above (a, 0)
  return points
end

-- Even-odd rule, so either winding and concave polygons work; a point on an edge may go either way.
function shapes.contains(polygon, x, y)
  local odd = false
  for i, a in ipairs(polygon) do
    local b = polygon[i % #polygon + 1]
    if (a[2] > y) ~= (b[2] > y) and x < a[1] + (y - a[2]) * (b[1] - a[1]) / (b[2] - a[2]) then
      odd = not odd
    end
  end
  return odd
end

-- Distance from (x, y) to the polygon's outline (its nearest edge), inside or outside it.
function shapes.distance_to(polygon, x, y)
  local best = math.huge
  for i, a in ipairs(polygon) do
    local b = polygon[i % #polygon + 1]
    local dx, dy = b[1] - a[1], b[2] - a[2]
    local length2 = dx * dx + dy * dy
    local t = length2 > 0 and ((x - a[1]) * dx + (y - a[2]) * dy) / length2 or 0
    t = math.max(0, math.min(1, t))
    best = math.min(best, math.sqrt((a[1] + t * dx - x) ^ 2 + (a[2] + t * dy - y) ^ 2))
  end
  return best
end

return shapes
