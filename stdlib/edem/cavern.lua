-- edem.cavern: excavation outlines and their stages, ready for region{}.
--
--   local cavern = require "edem.cavern"
--   local c = cavern.warhead{ width = 24, height = 48, benches = 13 }  -- the seed's powerhouse
--   for _, s in ipairs(c.stages) do region(s) end   -- a region per stage, in excavation order
--   zone{ edge = 2, far = 10, near = { c.outline } }
--   -- ... materials, in-situ stress, boundaries; then excavate stage by stage:
--   for _, s in ipairs(c.stages) do excavate{ region = s.name, release = 2000 }; solve{} end
--
--   cavern.warhead{ width = 24, height = 48, arch_height = 8, heading = 8, benches = 13 }
--   cavern.circle{ radius = 5, stages = 2 }                        -- top heading + bench
--   cavern.circle{ radius = 5, stages = 4, split = "sectors" }     -- quadrants
--   cavern.horseshoe{ width = 10, stages = 3 }                     -- heading, bench, invert
--   cavern.horseshoe{ width = 10, height = 12, form = "flat", stages = 3 }
--   cavern.rectangle{ width = 20, height = 30, stages = 4 }        -- heading + 3 benches
--
-- Every function returns
--   { outline = polygon, stages = { { name = ..., polygon = ... }, ... },
--     crown = {x, y}, invert = {x, y} }
-- outline: the whole excavation; stages: its pieces in excavation order, each table exactly
-- { name, polygon } so that region(stage) takes it; crown and invert: the highest and the lowest
-- point on the vertical axis (the floor's centre for flat floors). Every polygon is
-- counter-clockwise. The stages tile the outline: they do not overlap, their areas add up to its
-- area, and two stages share the same corner points (identical numbers) all along their common
-- edge, so their region{} cuts coincide; a corner where one stage's edges meet in the middle of
-- another's edge is a corner of that edge too (collinear corners are fine for region{}).
--
-- Common keys:
--   centre   {x, y}  the centre of the shape's bounding box, half-way between invert and crown
--                    (default {0, 0}): the circle's centre, the centre of the classic horseshoe's
--                    semicircular top, and for the seed's 48 m warhead the point 24 m above the
--                    floor, so that {0, 0} puts its crown at y = 24 as edem.seed and
--                    scripts/examples/jointed_cavern.lua do.
--   segments n       the curved part of the outline is cut into chords none longer than 1/n of
--                    its length (and none spanning more than 45 degrees); every arc between two
--                    stage corners gets a whole number of them, so there can be a few more than
--                    n. Default: 64 per full turn of arc, as edem.shapes.circle.
--   name     string  prefix of the stage names (default: the shape's name); the stages are
--                    NAME_heading, NAME_bench_01, ... or as listed below.
-- Lengths in m. A wrong key or value stops the script at the caller's line:
-- "cavern.warhead: arch_height = 13: must be at most width / 2 = 12 ...".
--
-- Shapes:
--   warhead{ width = 24, height = 48, arch_height = width / 3, heading = width / 3,
--            benches = 13, centre, segments, name = "warhead" }
--     Vertical side walls from a flat floor up to the springline, arch_height below the crown,
--     and a circular arch from springline corner to springline corner through the crown
--     (radius (width^2 / 4 + arch_height^2) / (2 arch_height); a semicircle at the largest
--     arch_height allowed, width / 2). Default arch_height width / 3: the 8 m rise over the
--     24 m span (radius 13 m) that scripts/examples/jointed_cavern.lua and tests/scenes.hpp
--     already use (the seed's text gives the cavern's width and height only). The defaults
--     give the seed paper's cavern and its 16 steps (its Figure 7):
--     NAME_arch_centre (the central strip `heading` wide, from the springline to the arch),
--     NAME_arch_left, NAME_arch_right, then NAME_bench_01 ... NAME_bench_13 of equal height
--     from the springline down to the floor.
--   circle{ radius, stages = 1, split = "benches", centre, segments, name = "circle" }
--     stages = 1: NAME_full. split = "benches": NAME_heading and NAME_bench_01 ... of equal
--     height, top-down (stages = 2: top heading and bench, split at the horizontal diameter).
--     split = "sectors": NAME_sector_01 ... of equal angle, the first from the crown
--     counter-clockwise (stages = 4: quadrants, top-left first).
--   horseshoe{ width, stages = 1, form = "classic", centre, segments, name = "horseshoe" }
--     The classic (standard) horseshoe: a semicircular top of radius r = width / 2, sides of
--     radius 2 r centred on the springline at the opposite wall, an invert of radius 2 r centred
--     at the crown; as high as wide (area 0.8293 width^2). Stages: 1: NAME_full; 2: NAME_heading
--     (above the springline) and NAME_bench_01; 3 or more: NAME_heading, benches of equal height
--     down to where the sides meet the invert, and NAME_invert.
--   horseshoe{ width, height, form = "flat", stages = 1, ... }
--     A semicircular arch of radius width / 2 on vertical walls, flat floor (height > width / 2).
--     Stages: 1: NAME_full; n: NAME_heading (above the springline) and n - 1 benches of equal
--     height.
--   rectangle{ width, height, stages = 1, centre, name = "rectangle" }
--     Stages: 1: NAME_full; n: NAME_heading and n - 1 benches, all of equal height.
local cavern = {}

local pi = math.pi

-- Reading and checking the arguments -----------------------------------------------------------

local args = require "edem.args"
local show = args.show

-- Reads t against spec (edem.args); errors are blamed on the caller of the public function.
local function read(fn, t, spec) return args.read("cavern", fn, t, spec) end

-- Geometry ---------------------------------------------------------------------------------------
--
-- A shape is built in coordinates centred on its bounding box, from its right half: a chain of
-- legs from the invert point on the axis up to the crown on the axis, each leg straight or an
-- arc, ending on a given point. Stage corners on the outline are leg ends, given exactly (a
-- bench level's y is the level itself). The left half is the mirror image, so the outline is
-- symmetric to the last bit, and the stages are cut from the outline ring by its own points.

local function arc_leg(to, c, r, a0, a1) return { to = to, c = c, r = r, a0 = a0, a1 = a1 } end

-- Chords per arc leg: none longer than 1/segments of all the curved length (both halves), none
-- spanning more than 45 degrees. `segments` nil: 64 per full turn of arc.
local function chord_counts(legs, segments)
  local length, turn = 0, 0
  for _, leg in ipairs(legs) do
    if leg.r then
      length = length + 2 * leg.r * (leg.a1 - leg.a0)
      turn = turn + 2 * (leg.a1 - leg.a0)
    end
  end
  local n = segments or math.max(1, math.ceil(64 * turn / (2 * pi) - 1e-9))
  for _, leg in ipairs(legs) do
    if leg.r then
      local sweep = leg.a1 - leg.a0
      leg.n = math.max(1, math.ceil(n * leg.r * sweep / length - 1e-9),
                       math.ceil(sweep / (pi / 4) - 1e-9))
    end
  end
end

-- The outline ring, counter-clockwise from the invert point, and the mirror image of each
-- right-half point (the two axis points are their own).
local function build_ring(invert, legs, segments)
  chord_counts(legs, segments)
  local right = { invert }
  for _, leg in ipairs(legs) do
    if leg.r then
      for i = 1, leg.n - 1 do
        local a = leg.a0 + (leg.a1 - leg.a0) * i / leg.n
        right[#right + 1] = { leg.c[1] + leg.r * math.cos(a), leg.c[2] + leg.r * math.sin(a) }
      end
    end
    right[#right + 1] = leg.to
  end
  local crown = right[#right]
  local mirror = { [invert] = invert, [crown] = crown }
  local ring = {}
  for i, p in ipairs(right) do ring[i] = p end
  for i = #right - 1, 2, -1 do
    local q = { -right[i][1], right[i][2] }
    mirror[right[i]] = q
    ring[#ring + 1] = q
  end
  local index = {}
  for i, p in ipairs(ring) do index[p] = i end
  return { points = ring, index = index, mirror = mirror, invert = invert, crown = crown }
end

-- The ring's points from p to q (both included), going counter-clockwise.
local function slice(ring, p, q, into)
  into = into or {}
  local n, i = #ring.points, ring.index[p]
  while true do
    into[#into + 1] = ring.points[i]
    if ring.points[i] == q then return into end
    i = i % n + 1
  end
end

-- Horizontal bands of the ring between levels, top-down: `levels` lists right-half points
-- top-down, one per cut; n levels give n + 1 bands.
local function bands(ring, levels)
  local m = ring.mirror
  if #levels == 0 then return { ring.points } end
  local out = { slice(ring, levels[1], m[levels[1]]) }                 -- over the crown
  for i = 1, #levels - 1 do
    local lo, hi = levels[i + 1], levels[i]
    out[#out + 1] = slice(ring, m[hi], m[lo], slice(ring, lo, hi))
  end
  out[#out + 1] = slice(ring, m[levels[#levels]], levels[#levels])     -- under the invert
  return out
end

-- Adds to each polygon's edges the corners of the other polygons that lie on them, so that
-- neighbours have the same points along their common edge.
local function add_junctions(polygons, size)
  local all, seen = {}, {}
  for _, poly in ipairs(polygons) do
    for _, p in ipairs(poly) do
      if not seen[p] then seen[p] = true; all[#all + 1] = p end
    end
  end
  local tolerance = 1e-9 * size
  for k, poly in ipairs(polygons) do
    local out = {}
    for i, p in ipairs(poly) do
      local q = poly[i % #poly + 1]
      local dx, dy = q[1] - p[1], q[2] - p[2]
      local length = math.sqrt(dx * dx + dy * dy)
      local on = {}
      for _, x in ipairs(all) do
        local t = ((x[1] - p[1]) * dx + (x[2] - p[2]) * dy) / (length * length)
        local off = math.abs((x[1] - p[1]) * dy - (x[2] - p[2]) * dx) / length
        if off <= tolerance and t * length > tolerance and (1 - t) * length > tolerance then
          on[#on + 1] = { t, x }
        end
      end
      table.sort(on, function(u, v) return u[1] < v[1] end)
      out[#out + 1] = p
      for _, e in ipairs(on) do out[#out + 1] = e[2] end
    end
    polygons[k] = out
  end
end

-- The result: stage polygons completed at their junctions, every point moved by the centre and
-- copied (no two polygons share a point table).
local function result(ring, prefix, stages, centre, size)
  local polygons = { ring.points }
  for i, s in ipairs(stages) do polygons[i + 1] = s[2] end
  add_junctions(polygons, size)
  local cx, cy = centre[1], centre[2]
  local function moved(poly)
    local out = {}
    for i, p in ipairs(poly) do out[i] = { p[1] + cx, p[2] + cy } end
    return out
  end
  local out = { outline = moved(polygons[1]), stages = {},
                crown = { ring.crown[1] + cx, ring.crown[2] + cy },
                invert = { ring.invert[1] + cx, ring.invert[2] + cy } }
  for i, s in ipairs(stages) do
    out.stages[i] = { name = prefix .. "_" .. s[1], polygon = moved(polygons[i + 1]) }
  end
  return out
end

-- Names for horizontally split shapes: full; or heading, bench_01, ...
local function band_stages(polygons, last_name)
  if #polygons == 1 then return { { "full", polygons[1] } } end
  local stages = { { "heading", polygons[1] } }
  for i = 2, #polygons do
    local name = ("bench_%02d"):format(i - 1)
    if i == #polygons and last_name then name = last_name end
    stages[#stages + 1] = { name, polygons[i] }
  end
  return stages
end

-- Right-half legs of a vertical wall at x = a from the floor at y0 up to the springline at ys,
-- with a corner at each level in cuts (bottom-up). Returns the springline corner and the
-- level corners top-down.
local function wall_legs(legs, a, y0, ys, cuts)
  legs[#legs + 1] = { to = { a, y0 } }
  local points = {}
  for _, y in ipairs(cuts) do
    local p = { a, y }
    legs[#legs + 1] = { to = p }
    table.insert(points, 1, p)
  end
  local springline = { a, ys }
  legs[#legs + 1] = { to = springline }
  return springline, points
end

-- Shapes -----------------------------------------------------------------------------------------

function cavern.warhead(t)
  local o = read("warhead", t, {
    { "width", "positive", 24 }, { "height", "positive", 48 }, { "arch_height", "positive" },
    { "heading", "positive" }, { "benches", "count", 13 }, { "centre", "point", { 0, 0 } },
    { "segments", "count" }, { "name", "name", "warhead" },
  })
  local w, h = o.width, o.height
  local rise, heading = o.arch_height or w / 3, o.heading or w / 3
  if rise > w / 2 then
    error(("cavern.warhead: arch_height = %s: must be at most width / 2 = %s (a circular arch, "
      .. "at most a semicircle)"):format(show(rise), show(w / 2)), 2)
  end
  if rise >= h then
    error(("cavern.warhead: arch_height = %s: must be below height = %s (the walls need a "
      .. "height)"):format(show(rise), show(h)), 2)
  end
  if heading >= w then
    error(("cavern.warhead: heading = %s: must be narrower than width = %s"):format(
      show(heading), show(w)), 2)
  end

  local a, hc, top, y0 = w / 2, heading / 2, h / 2, -h / 2
  local ys = top - rise
  local r = (a * a + rise * rise) / (2 * rise)
  local c = { 0, top - r }
  local spring = math.atan(ys - c[2], a)       -- angle of the springline corner
  local split = math.acos(hc / r)              -- angle where the heading's side meets the arch
  local cuts = {}
  for k = 1, o.benches - 1 do cuts[k] = y0 + (ys - y0) * k / o.benches end  -- bottom-up
  local legs = {}
  local springline, levels = wall_legs(legs, a, y0, ys, cuts)
  local corner = { hc, c[2] + math.sqrt(r * r - hc * hc) }
  legs[#legs + 1] = arc_leg(corner, c, r, spring, split)
  legs[#legs + 1] = arc_leg({ 0, top }, c, r, split, pi / 2)
  local ring = build_ring({ 0, y0 }, legs, o.segments)

  local m = ring.mirror
  local foot_r, foot_l = { hc, ys }, { -hc, ys }
  local stages = {
    { "arch_centre", slice(ring, corner, m[corner], { foot_l, foot_r }) },
    { "arch_left", slice(ring, m[corner], m[springline], { foot_l }) },
    { "arch_right", slice(ring, springline, corner, { foot_r }) },
  }
  table.insert(levels, 1, springline)
  local parts = bands(ring, levels)
  for i = 2, #parts do stages[#stages + 1] = { ("bench_%02d"):format(i - 1), parts[i] } end
  return result(ring, o.name, stages, o.centre, math.max(w, h))
end

function cavern.circle(t)
  local o = read("circle", t, {
    { "radius", "positive" }, { "stages", "count", 1 },
    { "split", { "benches", "sectors" }, "benches" },
    { "centre", "point", { 0, 0 } }, { "segments", "count" }, { "name", "name", "circle" },
  })
  if not o.radius then error("cavern.circle: radius is required", 2) end
  local r, n = o.radius, o.stages
  local c = { 0, 0 }
  local legs, levels, points = {}, {}, {}   -- points: sector corners by k (sectors)
  local angle = -pi / 2
  local function to(p, a)
    legs[#legs + 1] = arc_leg(p, c, r, angle, a)
    angle = a
  end
  if o.split == "benches" then
    for k = n - 1, 1, -1 do                 -- bottom-up
      local y = r - 2 * r * k / n
      local p = { math.sqrt(r * r - y * y), y }
      to(p, math.asin(y / r))
      table.insert(levels, 1, p)
    end
  else
    -- Sector k (0 ... n - 1) starts at pi/2 + 2 pi k / n; the right half holds 2k > n.
    for k = 1, n - 1 do                     -- bottom-up
      if 2 * k > n then
        local a = pi / 2 - 2 * pi * (n - k) / n
        local p = { r * math.cos(a), r * math.sin(a) }
        to(p, a)
        points[k] = p
      end
    end
  end
  to({ 0, r }, pi / 2)
  local ring = build_ring({ 0, -r }, legs, o.segments)
  local stages
  if o.split == "benches" then
    stages = band_stages(bands(ring, levels))
  elseif n == 1 then
    stages = { { "full", ring.points } }
  else
    points[0] = ring.crown
    if n % 2 == 0 then points[n // 2] = ring.invert end
    for k = 1, n - 1 do
      if 2 * k < n then points[k] = ring.mirror[points[n - k]] end
    end
    points[n] = ring.crown
    stages = {}
    for k = 0, n - 1 do
      local pie = slice(ring, points[k], points[k + 1], { c })
      stages[k + 1] = { ("sector_%02d"):format(k + 1), pie }
    end
  end
  return result(ring, o.name, stages, o.centre, 2 * r)
end

function cavern.horseshoe(t)
  local o = read("horseshoe", t, {
    { "width", "positive" }, { "height", "positive" }, { "form", { "classic", "flat" }, "classic" },
    { "stages", "count", 1 }, { "centre", "point", { 0, 0 } }, { "segments", "count" },
    { "name", "name", "horseshoe" },
  })
  if not o.width then error("cavern.horseshoe: width is required", 2) end
  local r, n = o.width / 2, o.stages
  local legs, levels = {}, {}
  local ring, stages, size
  if o.form == "classic" then
    if o.height then
      error(("cavern.horseshoe: height = %s: the classic horseshoe is as high as it is wide; "
        .. "form = \"flat\" takes a height"):format(show(o.height)), 2)
    end
    -- The sides (centres {-r, 0}, {r, 0}, radius 2r) meet the invert (centre {0, r}, radius 2r)
    -- on y = -x, x = r (sqrt 7 - 1) / 2.
    local s = r * (math.sqrt(7) - 1) / 2
    local joint = { s, -s }
    local side_c = { -r, 0 }
    legs[1] = arc_leg(joint, { 0, r }, 2 * r, -pi / 2, math.atan(-s - r, s))
    local angle = math.atan(-s, s + r)
    local cuts = n >= 3 and n - 2 or 1     -- benches between the springline and the joint
    for k = cuts - 1, 1, -1 do
      local y = -s * k / cuts
      local p = { -r + math.sqrt(4 * r * r - y * y), y }
      local a = math.asin(y / (2 * r))
      legs[#legs + 1] = arc_leg(p, side_c, 2 * r, angle, a)
      angle = a
      table.insert(levels, 1, p)
    end
    local springline = { r, 0 }
    legs[#legs + 1] = arc_leg(springline, side_c, 2 * r, angle, 0)
    legs[#legs + 1] = arc_leg({ 0, r }, { 0, 0 }, r, 0, pi / 2)
    ring = build_ring({ 0, -r }, legs, o.segments)
    if n >= 2 then table.insert(levels, 1, springline) end
    if n >= 3 then levels[#levels + 1] = joint end
    stages = band_stages(bands(ring, levels), n >= 3 and "invert" or nil)
    size = 2 * r
  else
    local h = o.height
    if not h then error("cavern.horseshoe: height is required for form = \"flat\"", 2) end
    if h <= r then
      error(("cavern.horseshoe: height = %s: must exceed width / 2 = %s (the semicircular "
        .. "arch's rise)"):format(show(h), show(r)), 2)
    end
    local top, y0 = h / 2, -h / 2
    local ys = top - r
    local cuts = {}
    for k = 1, n - 2 do cuts[k] = y0 + (ys - y0) * k / (n - 1) end       -- bottom-up
    local springline, points = wall_legs(legs, r, y0, ys, cuts)
    legs[#legs + 1] = arc_leg({ 0, top }, { 0, ys }, r, 0, pi / 2)
    ring = build_ring({ 0, y0 }, legs, o.segments)
    if n >= 2 then
      levels = points
      table.insert(levels, 1, springline)
    end
    stages = band_stages(bands(ring, levels))
    size = math.max(2 * r, h)
  end
  return result(ring, o.name, stages, o.centre, size)
end

function cavern.rectangle(t)
  local o = read("rectangle", t, {
    { "width", "positive" }, { "height", "positive" }, { "stages", "count", 1 },
    { "centre", "point", { 0, 0 } }, { "name", "name", "rectangle" },
  })
  if not o.width then error("cavern.rectangle: width is required", 2) end
  if not o.height then error("cavern.rectangle: height is required", 2) end
  local a, top, n = o.width / 2, o.height / 2, o.stages
  local cuts = {}
  for k = 1, n - 1 do cuts[k] = -top + o.height * k / n end            -- bottom-up
  local legs = { { to = { a, -top } } }
  local levels = {}
  for _, y in ipairs(cuts) do
    local p = { a, y }
    legs[#legs + 1] = { to = p }
    table.insert(levels, 1, p)
  end
  legs[#legs + 1] = { to = { a, top } }
  legs[#legs + 1] = { to = { 0, top } }
  local ring = build_ring({ 0, -top }, legs)
  local stages = band_stages(bands(ring, levels))
  return result(ring, o.name, stages, o.centre, math.max(o.width, o.height))
end

return cavern
