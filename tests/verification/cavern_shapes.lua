-- stdlib/edem/cavern.lua: excavation outlines and stages.
--
-- For each shape: the outline's area against its closed form, the stages' areas adding up to
-- the outline's (1e-9 relative), every stage counter-clockwise, and the stages tiling the
-- outline edge for edge (every stage edge is the reverse of exactly one other stage's edge or
-- one of the outline's, with identical coordinates: the region{} cuts coincide). The outline's
-- polygon is inscribed in the curved shape: its area lies in [exact - bound, exact], with
-- bound = Phi L^2 / (12 n^2) from the module's promise that no chord is longer than L / n
-- (L the curved length, Phi the total turning of the arcs, n = segments): a chord spanning
-- delta radians of radius R cuts off R^2 (delta - sin delta) / 2 <= R^2 delta^3 / 12.
-- The warhead gives the seed's 16 steps in its order (Figure 7). Then real models: the
-- seed's 200 m x 180 m block with the warhead's 16 stages as regions, zoned, each region's
-- zones adding up to its stage's area (1e-6 relative); and the other shapes side by side.
-- Bad input names the key and value and blames the caller's line.
local check = require "edem.check"
local cavern = require "edem.cavern"

local pi = math.pi

local function signed_area(p)
  local s = 0
  for i, a in ipairs(p) do
    local b = p[i % #p + 1]
    s = s + a[1] * b[2] - b[1] * a[2]
  end
  return s / 2
end

-- Edges that are not shared with exactly one other stage (reversed) or the outline.
local function unmatched_edges(c)
  local function key(a, b) return ("%.17g %.17g > %.17g %.17g"):format(a[1], a[2], b[1], b[2]) end
  local stage_edges, outline_edges, bad = {}, {}, 0
  for _, s in ipairs(c.stages) do
    local p = s.polygon
    for i, a in ipairs(p) do
      local k = key(a, p[i % #p + 1])
      if stage_edges[k] then bad = bad + 1 end   -- the same edge twice in one direction: overlap
      stage_edges[k] = true
    end
  end
  for i, a in ipairs(c.outline) do outline_edges[key(a, c.outline[i % #c.outline + 1])] = true end
  for _, s in ipairs(c.stages) do
    local p = s.polygon
    for i, a in ipairs(p) do
      local b = p[i % #p + 1]
      if not (stage_edges[key(b, a)] or outline_edges[key(a, b)]) then bad = bad + 1 end
    end
  end
  for k in pairs(outline_edges) do
    if not stage_edges[k] then bad = bad + 1 end
  end
  return bad
end

-- The checks every shape gets; exact: closed-form area of the curved shape; bound: the chord
-- bound (0: no arcs).
local function shape_checks(label, c, exact, bound)
  local area = signed_area(c.outline)
  if bound > 0 then
    check.report(label .. ": outline area (chords, rel tol = bound / area)", area, exact, bound / exact)
    check.report(label .. ": outline inscribed (area above exact)", math.max(0, area - exact), 0,
                 1e-12 * exact, { absolute = true })
  else
    check.report(label .. ": outline area", area, exact, 1e-12)
  end
  local sum, clockwise = 0, 0
  for _, s in ipairs(c.stages) do
    local a = signed_area(s.polygon)
    sum = sum + a
    if a <= 0 then clockwise = clockwise + 1 end
  end
  check.report(label .. ": stage areas add up to the outline's", sum, area, 1e-9)
  check.report(label .. ": stages not counter-clockwise", clockwise, 0, 0, { absolute = true })
  check.report(label .. ": stage edges not shared exactly", unmatched_edges(c), 0, 0, { absolute = true })
end

-- 1. Warhead: the seed's cavern, 24 m x 48 m, arch rise 8 m (radius 13 m), 13 benches.
do
  local w, h, rise, n = 24, 48, 8, 24
  local a = w / 2
  local r = (a * a + rise * rise) / (2 * rise)
  local phi = 2 * math.asin(a / r)
  local exact = w * (h - rise) + r * r / 2 * (phi - math.sin(phi))
  local c = cavern.warhead{ width = w, height = h, arch_height = rise, benches = 13, segments = n }
  shape_checks("warhead 24 x 48, rise 8", c, exact, phi * (r * phi) ^ 2 / (12 * n * n))
  local names = { "warhead_arch_centre", "warhead_arch_left", "warhead_arch_right" }
  for k = 1, 13 do names[#names + 1] = ("warhead_bench_%02d"):format(k) end
  local wrong = 0
  for i, s in ipairs(c.stages) do if s.name ~= names[i] then wrong = wrong + 1 end end
  check.report("warhead: stages", #c.stages, 16, 0, { absolute = true })
  check.report("warhead: stage names out of the seed's order", wrong, 0, 0, { absolute = true })
  check.report("warhead: crown y (centre {0, 0})", c.crown[2], 24, 0, { absolute = true })
  -- The defaults are the seed's cavern: the same polygons.
  local d = cavern.warhead{ segments = n }
  check.report("warhead{}: area as the seed's cavern", signed_area(d.outline), signed_area(c.outline), 0,
               { absolute = true })
  -- A semicircular arch, moved, renamed, a few benches.
  local s = cavern.warhead{ width = 10, height = 14, arch_height = 5, heading = 4, benches = 3,
                            centre = { 100, -50 }, segments = 40, name = "cut" }
  shape_checks("warhead 10 x 14, semicircular, centre {100, -50}", s, 10 * 9 + pi * 25 / 2,
               pi * (5 * pi) ^ 2 / (12 * 40 * 40))
  check.report("warhead renamed: first stage is cut_arch_centre", s.stages[1].name == "cut_arch_centre"
               and 1 or 0, 1, 0, { absolute = true })
end

-- 2. Circle.
do
  local r, n = 3, 64
  local exact, bound = pi * r * r, 2 * pi * (2 * pi * r) ^ 2 / (12 * n * n)
  for _, v in ipairs({ { 1, "benches" }, { 2, "benches" }, { 5, "benches" }, { 4, "sectors" },
                       { 3, "sectors" }, { 2, "sectors" } }) do
    local c = cavern.circle{ radius = r, stages = v[1], split = v[2], centre = { 1, 2 }, segments = n }
    shape_checks(("circle r = 3, %d %s"):format(v[1], v[2]), c, exact, bound)
    check.report(("circle %d %s: stages"):format(v[1], v[2]), #c.stages, v[1], 0, { absolute = true })
  end
  local c = cavern.circle{ radius = r, stages = 2 }
  check.report("circle 2 benches: names heading, bench_01",
               (c.stages[1].name == "circle_heading" and c.stages[2].name == "circle_bench_01") and 1 or 0,
               1, 0, { absolute = true })
end

-- 3. Horseshoe: classic (semicircle r on top, sides and invert of radius 2 r) and flat.
do
  local w, n = 6, 48
  local r = w / 2
  local s = r * (math.sqrt(7) - 1) / 2                 -- sides meet the invert at (+-s, -s)
  local side = math.atan(s, s + r)                     -- each side arc's angle
  local invert = 2 * math.atan(s, r + s)               -- the invert arc's angle
  local segment = function(R, t) return R * R / 2 * (t - math.sin(t)) end
  local exact = (2 * r + 2 * s) / 2 * s + pi * r * r / 2 + 2 * segment(2 * r, side) + segment(2 * r, invert)
  local turn, length = pi + 2 * side + invert, pi * r + 2 * (2 * r) * side + 2 * r * invert
  local bound = turn * length ^ 2 / (12 * n * n)
  check.report("classic horseshoe: area / width^2 (USBR 0.8293)", exact / (w * w), 0.8293, 1e-4)
  for _, stages in ipairs({ 1, 2, 3, 5 }) do
    local c = cavern.horseshoe{ width = w, stages = stages, segments = n }
    shape_checks(("classic horseshoe w = 6, %d stages"):format(stages), c, exact, bound)
    check.report(("classic horseshoe %d: stages"):format(stages), #c.stages, stages, 0, { absolute = true })
  end
  local c = cavern.horseshoe{ width = w, stages = 3 }
  check.report("classic horseshoe 3: last stage is horseshoe_invert", c.stages[3].name == "horseshoe_invert"
               and 1 or 0, 1, 0, { absolute = true })
  for _, stages in ipairs({ 1, 2, 4 }) do
    local f = cavern.horseshoe{ width = w, height = 8, form = "flat", stages = stages, segments = n }
    shape_checks(("flat horseshoe 6 x 8, %d stages"):format(stages), f, w * (8 - r) + pi * r * r / 2,
                 pi * (pi * r) ^ 2 / (12 * n * n))
  end
end

-- 4. Rectangle.
for _, stages in ipairs({ 1, 4 }) do
  local c = cavern.rectangle{ width = 20, height = 30, stages = stages, centre = { -3, 7 } }
  shape_checks(("rectangle 20 x 30, %d stages"):format(stages), c, 600, 0)
end

-- 5. Bad input: the key and value named, the caller's line blamed.
local function attempt(shape, args)
  local c = cavern[shape](args)   -- not a tail call: this line must be on the stack to be blamed
  return c
end
for _, case in ipairs({
  { "warhead", { width = -1 }, "width = -1: must be a number > 0" },
  { "warhead", { arch_height = 13 }, "arch_height = 13: must be at most width / 2 = 12" },
  { "warhead", { arch_height = 4, height = 4 }, "arch_height = 4: must be below height = 4" },
  { "warhead", { benches = 0 }, "benches = 0: must be an integer >= 1" },
  { "warhead", { benches = 2.5 }, "benches = 2.5: must be an integer >= 1" },
  { "warhead", { heading = 30 }, "heading = 30: must be narrower than width = 24" },
  { "warhead", { benchs = 3 }, "unknown key \"benchs\"" },
  { "circle", { centre = { 0, 0 } }, "radius is required" },
  { "circle", { radius = 1, split = "wedges" }, "split = \"wedges\": must be one of" },
  { "horseshoe", { width = 2, height = 3 }, "height = 3: the classic horseshoe" },
  { "horseshoe", { width = 4, height = 2, form = "flat" }, "height = 2: must exceed" },
  { "rectangle", { width = 1 }, "height is required" },
}) do
  local ok, message = pcall(attempt, case[1], case[2])
  local good = not ok and message:find(case[3], 1, true)
               and message:find("cavern_shapes.lua:%d+: cavern%." .. case[1])
  print("  " .. tostring(message))
  check.report("bad input: " .. case[3], good and 1 or 0, 1, 0, { absolute = true })
end

-- 6. Real models: the regions cut, zoned, each region's zones covering its stage exactly.
local function zoned(label, x, y, shapes, edge, far)
  model{ title = label }
  block{ x = x, y = y }
  local near, stages = {}, {}
  for _, c in ipairs(shapes) do
    for _, s in ipairs(c.stages) do
      region(s)
      near[#near + 1] = s.name
      stages[#stages + 1] = s
    end
  end
  zone{ edge = edge, far = far, near = near }
  check.report(label .. ": info().regions", info().regions, #stages, 0, { absolute = true })
  local by_region, total = {}, 0
  for z in zones() do
    if z.region then by_region[z.region] = (by_region[z.region] or 0) + z.area end
    total = total + z.area
  end
  local worst, worst_name = 0, ""
  for _, s in ipairs(stages) do
    local a = signed_area(s.polygon)
    local e = math.abs((by_region[s.name] or 0) - a) / a
    if e > worst then worst, worst_name = e, s.name end
  end
  print(("  %s: %d zones, %d blocks; worst region area error %.2e (%s)"):format(
    label, info().zones, info().blocks, worst, worst_name))
  check.report(label .. ": zones of each region vs its stage (largest rel error)", worst, 0, 1e-6,
               { absolute = true })
  check.report(label .. ": all zones vs the block", total, (x[2] - x[1]) * (y[2] - y[1]), 1e-9)
end

local seconds = os.clock()
zoned("seed block 200 x 180, warhead's 16 stages", { -100, 100 }, { -90, 90 }, { cavern.warhead{} }, 2, 10)
zoned("other shapes side by side", { -40, 40 }, { -20, 20 }, {
  cavern.circle{ radius = 5, stages = 4, split = "sectors", centre = { -27, 0 } },
  cavern.horseshoe{ width = 10, stages = 4, centre = { -10, 0 } },
  cavern.horseshoe{ width = 8, height = 10, form = "flat", stages = 3, centre = { 6, 0 },
                   name = "arched" },
  cavern.rectangle{ width = 10, height = 8, stages = 3, centre = { 24, 0 } },
}, 0.5, 4)
print(("  models built and zoned in %.1f s"):format(os.clock() - seconds))

check.finish()
