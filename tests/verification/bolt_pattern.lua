-- stdlib/edem/bolts.lua: bolting patterns along excavated walls.
--
-- A 60 m x 60 m block of elastic rock around a 12 m x 24 m warhead cavern (arch rise 4 m, three
-- arch stages and four benches) cut as regions and zoned; the stages are excavated one by one
-- (geometry only, nothing solved) and after each one the seed's pattern (5 m bolts at 1.5 m) is
-- laid on bolts.exposed(stage, outline). Checked:
--   exposed(): the arch stages give one arc of the arch each, the upper benches their two side
--     walls, the last bench one polyline down the left wall, along the floor and up the right
--     wall; over all stages each stretch of the outline exactly once (lengths add up to its
--     perimeter), no temporary floor;
--   pattern{}: per stage, as many bolts as the exposed lengths and the spacing give
--     (floor((P - s/2) / s) + 1 per polyline of length P), returned and in bolts(); every head on
--     the outline (1e-9 of the cavern's size), every bolt 5 m long, normal to the wall (|d . t|
--     <= 1e-9, t the wall's tangent, the corner's mean tangent at a vertex), its tip outside the
--     cavern in rock and the wall's excavated side behind its head; the heads at s/2, s/2 + s, ...
--     of arc length along each polyline (1e-9);
--   where = function(x, y) return y > springline end over the whole outline: only the arch's
--     heads, as many as the positions above the springline;
--   a closed rectangle with heads on its corners: corner bolts along the bisector, no double
--     head where the loop closes; free_length and segment_length passed on to bolt{};
--   the seed's sequence in small (in-situ stress, each stage excavated, solved, then bolted): the
--     same bolts, the first stage's in tension at the end, none cut or out of service;
--   bad input: the key and value named and the caller's line blamed; a wall in solid rock
--     ("rock on both sides") or in the opening ("on neither side"; with missing = "skip" either's
--     heads are skipped and counted); bolt{}'s own refusal (a bolt
--     running out of the model) named with the bolt.
local check = require "edem.check"
local cavern = require "edem.cavern"
local bolts = require "edem.bolts"
local shapes = require "edem.shapes"

local clock = os.clock()
local SPACING, LENGTH, SEGMENTS = 1.5, 5, 10
local W, H, RISE, BENCHES = 12, 24, 4, 4
local c = cavern.warhead{ width = W, height = H, arch_height = RISE, benches = BENCHES }
local outline = c.outline
local SIZE = H
local TOL = 1e-9 * SIZE
local SPRINGLINE = H / 2 - RISE
local R = (W * W / 4 + RISE * RISE) / (2 * RISE)     -- the arch's radius, centre (0, H/2 - R)

local function count_true(list, f)
  local n = 0
  for _, v in ipairs(list) do if f(v) then n = n + 1 end end
  return n
end

local function length_of(line)
  local s = 0
  for i = 1, #line - 1 do
    s = s + math.sqrt((line[i + 1][1] - line[i][1]) ^ 2 + (line[i + 1][2] - line[i][2]) ^ 2)
  end
  return s
end

-- The nearest point of a polyline to p: distance, arc length there, unit tangent there (the
-- mean of the two edges' tangents at an inner vertex).
local function locate(line, p)
  local best, at, tangent = math.huge, 0, nil
  local s = 0
  for i = 1, #line - 1 do
    local a, b = line[i], line[i + 1]
    local dx, dy = b[1] - a[1], b[2] - a[2]
    local l = math.sqrt(dx * dx + dy * dy)
    local t = math.max(0, math.min(1, ((p[1] - a[1]) * dx + (p[2] - a[2]) * dy) / (l * l)))
    local d = math.sqrt((a[1] + t * dx - p[1]) ^ 2 + (a[2] + t * dy - p[2]) ^ 2)
    if d < best then
      best, at, tangent = d, s + t * l, { dx / l, dy / l }
      local near_end = (1 - t) * l <= TOL
      if near_end and line[i + 2] then
        local c2 = line[i + 2]
        local ex, ey = c2[1] - b[1], c2[2] - b[2]
        local m = math.sqrt(ex * ex + ey * ey)
        local mx, my = dx / l + ex / m, dy / l + ey / m
        local n = math.sqrt(mx * mx + my * my)
        tangent = { mx / n, my / n }
      end
    end
    s = s + l
  end
  return best, at, tangent
end

local function closed(poly)
  local line = {}
  for i, p in ipairs(poly) do line[i] = p end
  line[#line + 1] = poly[1]
  return line
end

local function rock(x, y)
  local z = zone_at(x, y)
  return z ~= nil and z.excavated == nil and z.material == "rock"
end

-- The model.
model{ title = "bolt patterns around a warhead cavern" }
block{ x = { -30, 30 }, y = { -30, 30 } }
local near = {}
for _, s in ipairs(c.stages) do region(s); near[#near + 1] = s.name end
zone{ edge = 1, far = 4, near = near }
material{ "rock", young = 10e9, poisson = 0.25, density = 2600 }
assign{ material = "rock" }
bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6,
               failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
print(("model: %d zones, %d stages"):format(info().zones, #c.stages))

-- 1. Stage by stage: exposed walls, then the pattern on them.
local ring = closed(outline)
local exposed_total, worst = 0, { head = 0, length = 0, normal = 0, spacing = 0 }
local wrong = { tip = 0, behind = 0, count = 0 }
local all_ids = {}
for k, s in ipairs(c.stages) do
  excavate{ region = s.name }
  local lines = bolts.exposed(s, outline)
  local expected = 0
  for _, line in ipairs(lines) do
    local P = length_of(line)
    exposed_total = exposed_total + P
    if P >= SPACING / 2 then expected = expected + math.floor((P - SPACING / 2) / SPACING + 1e-9) + 1 end
  end
  -- The shape of what is exposed.
  local label = ("%s: exposed"):format(s.name)
  if k <= 3 then
    local off = 0
    for _, line in ipairs(lines) do
      for _, p in ipairs(line) do
        off = math.max(off, math.abs(math.sqrt(p[1] ^ 2 + (p[2] - (H / 2 - R)) ^ 2) - R),
                       math.max(0, SPRINGLINE - p[2]))
      end
    end
    check.report(label .. " polylines (one arc)", #lines, 1, 0, { absolute = true })
    check.report(label .. ": points off the arch [m]", off, 0, TOL, { absolute = true })
  elseif k < #c.stages then
    local top, bottom = SPRINGLINE - (k - 4) * (H - RISE) / BENCHES, SPRINGLINE - (k - 3) * (H - RISE) / BENCHES
    local ok = #lines == 2
    for _, line in ipairs(lines) do
      ok = ok and #line == 2 and math.abs(math.abs(line[1][1]) - W / 2) <= TOL and line[1][1] == line[2][1]
           and math.abs(math.max(line[1][2], line[2][2]) - top) <= TOL
           and math.abs(math.min(line[1][2], line[2][2]) - bottom) <= TOL
    end
    check.report(label .. ": the two side walls of the bench", ok and 1 or 0, 1, 0, { absolute = true })
  else
    local bench = (H - RISE) / BENCHES
    check.report(label .. " polylines (walls and floor, one)", #lines, 1, 0, { absolute = true })
    check.report(label .. ": length = 2 bench heights + the floor [m]", length_of(lines[1]),
                 2 * bench + W, 1e-12)
  end
  -- The pattern.
  local ids, n = bolts.pattern{ surface = lines, spacing = SPACING, length = LENGTH, segments = SEGMENTS,
                                material = "rebar" }
  local laid = 0
  for b in bolts() do
    if b.stage == stage() then
      laid = laid + 1
      local head, tip = { b.head.x, b.head.y }, { b.tip.x, b.tip.y }
      local dx, dy = tip[1] - head[1], tip[2] - head[2]
      local l = math.sqrt(dx * dx + dy * dy)
      local d_outline = locate(ring, head)
      local bestd, at, tangent, home = math.huge, 0, nil, nil
      for i, line in ipairs(lines) do
        local d, a, t = locate(line, head)
        if d < bestd then bestd, at, tangent, home = d, a, t, i end
      end
      worst.head = math.max(worst.head, d_outline, bestd)
      worst.length = math.max(worst.length, math.abs(l - LENGTH), math.abs(b.length - LENGTH))
      worst.normal = math.max(worst.normal, math.abs((dx * tangent[1] + dy * tangent[2]) / l))
      -- Arc length: s/2 + j s for a whole j.
      local j = (at - SPACING / 2) / SPACING
      worst.spacing = math.max(worst.spacing, math.abs(j - math.floor(j + 0.5)) * SPACING)
      if shapes.contains(outline, tip[1], tip[2]) or not rock(tip[1], tip[2]) then wrong.tip = wrong.tip + 1 end
      local e = 1e-3
      if not rock(head[1] + e * dx / l, head[2] + e * dy / l) or rock(head[1] - e * dx / l, head[2] - e * dy / l) then
        wrong.behind = wrong.behind + 1
      end
    end
  end
  if n ~= expected or #ids ~= n or laid ~= n then wrong.count = wrong.count + 1 end
  print(("  %-20s %d polyline(s), %6.3f m exposed: %2d bolts (expected %2d, in bolts() %2d)"):format(
    s.name, #lines, (function() local t = 0; for _, l in ipairs(lines) do t = t + length_of(l) end; return t end)(),
    n, expected, laid))
  for _, id in ipairs(ids) do all_ids[#all_ids + 1] = id end
end
check.report("exposed over all stages = the outline's perimeter [m]", exposed_total, length_of(ring), 1e-12)
check.report("stages whose bolt count differs from floor((P - s/2)/s) + 1", wrong.count, 0, 0, { absolute = true })
-- A bolt some of whose rock was excavated after it was laid: cut there, or out of service whole.
local function cut(b)
  if b.removed then return true end
  for _, s in ipairs(b.segments) do if s.state == "removed" then return true end end
  return false
end
local in_model, out_of_service = 0, 0
for b in bolts() do   -- the module is callable as the bolts() iterator its name hides
  in_model = in_model + 1
  if cut(b) then out_of_service = out_of_service + 1 end
end
check.report("ids returned: 1 ... n in order, all the model's bolts", (function()
  for i, id in ipairs(all_ids) do if id ~= i then return -1 end end
  return #all_ids
end)(), in_model, 0, { absolute = true })
check.report("bolts cut or out of service after all stages (ground excavated later)", out_of_service, 0, 0,
             { absolute = true })
check.report("heads off the outline and their polyline [m]", worst.head, 0, TOL, { absolute = true })
check.report("bolt length - 5 m [m]", worst.length, 0, TOL, { absolute = true })
check.report("bolt direction . wall tangent (normal to the wall)", worst.normal, 0, 1e-9, { absolute = true })
check.report("heads off s/2 + j s of arc length [m]", worst.spacing, 0, TOL, { absolute = true })
check.report("tips inside the cavern or not in rock", wrong.tip, 0, 0, { absolute = true })
check.report("heads with rock not ahead or rock behind", wrong.behind, 0, 0, { absolute = true })

-- 2. where: only the arch, over the whole outline as one closed polyline.
do
  local P = length_of(ring)
  local expected, at = 0, SPACING / 2
  while at < P - TOL do
    -- The point at arc length `at`.
    local s = 0
    for i = 1, #ring - 1 do
      local a, b = ring[i], ring[i + 1]
      local l = math.sqrt((b[1] - a[1]) ^ 2 + (b[2] - a[2]) ^ 2)
      if at <= s + l then
        local y = a[2] + (at - s) / l * (b[2] - a[2])
        if y > SPRINGLINE then expected = expected + 1 end
        break
      end
      s = s + l
    end
    at = at + SPACING
  end
  local first_new = #all_ids + 1
  local ids, n = bolts.pattern{ surface = ring, spacing = SPACING, length = 3, segment_length = 1,
                                material = "rebar", where = function(x, y) return y > SPRINGLINE end }
  check.report("where y > springline: bolts", n, expected, 0, { absolute = true })
  local below, segments = 0, 0
  for b in bolts() do
    if b.id >= first_new then
      if b.head.y <= SPRINGLINE then below = below + 1 end
      if #b.segments ~= 3 then segments = segments + 1 end
    end
  end
  check.report("where: heads at or below the springline", below, 0, 0, { absolute = true })
  check.report("segment_length = 1 on 3 m bolts: bolts without 3 segments", segments, 0, 0, { absolute = true })
  check.report("where: ids returned", #ids, n, 0, { absolute = true })
end

-- 3. Bad input: the key and value named, the caller's line blamed.
local good = { surface = bolts.exposed(c.stages[1], c), spacing = 1.5, length = 5, segments = 10,
               material = "rebar" }
local function with(changes)
  local t = {}
  for k, v in pairs(good) do t[k] = v end
  for k, v in pairs(changes) do t[k] = v end
  if changes.material == false then t.material = nil end
  if changes.segments == false then t.segments = nil end
  return t
end
local function attempt(fn, ...)
  local r = bolts[fn](...)   -- not a tail call: this line must be on the stack to be blamed
  return r
end
local before = 0
for _ in bolts() do before = before + 1 end
for _, case in ipairs({
  { "pattern", with{ spacing = 0 }, "spacing = 0: must be a number > 0" },
  { "pattern", with{ spacing = -1 }, "spacing = -1: must be a number > 0" },
  { "pattern", with{ length = "5" }, "length = \"5\": must be a number > 0" },
  { "pattern", with{ material = false }, "material is required" },
  { "pattern", with{ segments = false }, "give segments = n or segment_length = l (one of them), got neither" },
  { "pattern", with{ segment_length = 1 }, "give segments = n or segment_length = l (one of them), got segments = 10 and" },
  { "pattern", with{ spacings = 1 }, "unknown key \"spacings\"" },
  { "pattern", with{ where = 3 }, "where = 3: must be a function" },
  { "pattern", with{ free_length = 5 }, "free_length = 5: must be shorter than length = 5" },
  { "pattern", with{ surface = { { 0, 0 } } }, "surface: 1 point(s): needs at least 2" },
  { "pattern", with{ surface = { { { 0, 0 }, { 1, 0 } }, { { 0, 0 }, { 1, "a" } } } }, "surface[2][2] = {1, \"a\"}: must be a point {x, y}" },
  { "pattern", with{ surface = { { 20, -5 }, { 20, 5 } } }, "bolts.pattern: the wall at (20, -4.25) has rock on both sides" },
  { "pattern", with{ surface = { { -1, 0 }, { 1, 0 } } }, "bolts.pattern: the wall at (-0.25, 0) has rock on neither side" },
  { "pattern", with{ missing = "maybe" }, "missing = \"maybe\": must be \"error\" or \"skip\"" },
  { "pattern", with{ length = 40 }, "bolts.pattern: bolt 1 of " },
  { "pattern", with{ material = "steel" }, "bolts.pattern: bolt 1 of " },
  { "exposed", c.stages[1], nil, "bolts.exposed: outline = nil: must be a list of points" },
  { "exposed", { name = "x", polygon = { { 0, 0 }, { 1, 0 } } }, outline, "stage.polygon: 2 point(s): needs at least 3" },
}) do
  local ok, message
  if case[1] == "exposed" then
    ok, message = pcall(attempt, "exposed", case[2], case[3])
  else
    ok, message = pcall(attempt, "pattern", case[2])
  end
  local expect = case[#case]
  local fine = not ok and message:find(expect, 1, true) and message:find("bolt_pattern.lua:%d+: bolts%.")
  print("  " .. tostring(message))
  check.report("bad input: " .. expect, fine and 1 or 0, 1, 0, { absolute = true })
end
local after = 0
for _ in bolts() do after = after + 1 end
check.report("bad input laid no bolt", after - before, 0, 0, { absolute = true })
-- The same wall with no rock near it, told to skip such heads (rock fallen out deeper than half
-- a bolt): nothing laid, every head counted as skipped.
do
  local t = with{ surface = { { -1, 0 }, { 1, 0 } }, missing = "skip" }
  local _, laid, skipped = bolts.pattern(t)
  local heads = math.floor((2 - t.spacing / 2) / t.spacing) + 1
  check.report("missing = \"skip\": bolts laid on a wall with no rock near it", laid, 0, 0, { absolute = true })
  check.report("missing = \"skip\": heads skipped", skipped, heads, 0, { absolute = true })
end
-- A "wall" inside the rock (as where fallen rock lies against it), told to skip: nothing laid,
-- every head counted as skipped.
do
  local t = with{ surface = { { 20, -5 }, { 20, 5 } }, missing = "skip" }
  local _, laid, skipped = bolts.pattern(t)
  local heads = math.floor((10 - t.spacing / 2) / t.spacing) + 1
  check.report("missing = \"skip\": bolts laid on a wall with rock on both sides", laid, 0, 0, { absolute = true })
  check.report("missing = \"skip\": heads with rock on both sides skipped", skipped, heads, 0, { absolute = true })
end
-- Bolts whose far end lies outside the rock (40 m: out of the model), told to skip: the rest laid,
-- those counted, no error. The same heads with 5 m bolts are all laid.
do
  local _, laid, skipped = bolts.pattern(with{ length = 40, missing = "skip" })
  local _, heads = bolts.pattern(with{})
  check.report("missing = \"skip\", 40 m bolts: laid + skipped = the heads", laid + skipped, heads, 0, { absolute = true })
  check.report("missing = \"skip\", 40 m bolts: some skipped", skipped > 0 and 1 or 0, 1, 0, { absolute = true })
end

-- 4. A closed loop with heads on its corners: a rectangle 8 m x 6 m excavated at once, its
--    outline from the floor's middle; spacing 2 from 0 puts heads on the four corners and on the
--    start, once.
do
  local r = cavern.rectangle{ width = 8, height = 6 }
  model{ title = "bolts at corners" }
  block{ x = { -15, 15 }, y = { -15, 15 } }
  region(r.stages[1])
  zone{ edge = 0.5, far = 3, near = { r.stages[1].name } }
  material{ "rock", young = 10e9, poisson = 0.25, density = 2600 }
  assign{ material = "rock" }
  bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6,
                 failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6 }
  excavate(r.stages[1].name)
  local lines = bolts.exposed(r.stages[1], r.outline)
  local loop = #lines == 1 and lines[1][1][1] == lines[1][#lines[1]][1] and lines[1][1][2] == lines[1][#lines[1]][2]
  check.report("rectangle excavated at once: exposed is one closed loop", loop and 1 or 0, 1, 0, { absolute = true })
  local _, n = bolts.pattern{ surface = lines, spacing = 2, first = 0, length = 2, segments = 4,
                              free_length = 0.5, material = "rebar" }
  check.report("closed loop 28 m at 2 m from 0: bolts (no double head)", n, 14, 0, { absolute = true })
  local corner, off, free = 0, 0, 0
  for b in bolts() do
    local dx, dy = (b.tip.x - b.head.x) / 2, (b.tip.y - b.head.y) / 2
    if math.abs(math.abs(b.head.x) - 4) < 1e-12 and math.abs(math.abs(b.head.y) - 3) < 1e-12 then
      corner = corner + 1
      local sx, sy = b.head.x > 0 and 1 or -1, b.head.y > 0 and 1 or -1
      off = math.max(off, math.abs(dx - sx / math.sqrt(2)), math.abs(dy - sy / math.sqrt(2)))
    end
    if #b.segments ~= 5 then free = free + 1 end
  end
  check.report("heads on corners", corner, 4, 0, { absolute = true })
  check.report("corner bolts off the outward bisector", off, 0, 1e-12, { absolute = true })
  check.report("free_length = 0.5 + 4 segments: bolts without 5 segments", free, 0, 0, { absolute = true })
end

-- 4b. A wall with a hole in it (a block fell out of it: a 1 m deep pocket behind the right wall,
--     excavated too): the bolts whose heads fall in the pocket's mouth start where the rock begins,
--     at its back (within the search's step, a 40th of the bolt's length), the rest on the wall.
do
  local r = cavern.rectangle{ width = 8, height = 6 }
  model{ title = "a wall with a pocket" }
  block{ x = { -15, 15 }, y = { -15, 15 } }
  region(r.stages[1])
  region{ name = "pocket", polygon = { { 4, -1 }, { 5, -1 }, { 5, 1 }, { 4, 1 } } }
  zone{ edge = 0.25, far = 3, near = { r.stages[1].name, "pocket" } }
  material{ "rock", young = 10e9, poisson = 0.25, density = 2600 }
  assign{ material = "rock" }
  bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6,
                 failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6 }
  excavate(r.stages[1].name)
  excavate("pocket")
  local _, n = bolts.pattern{ surface = { { 4, -3 }, { 4, 3 } }, spacing = 1, length = 4, segments = 8,
                              material = "rebar" }
  local moved, on_wall = 0, 0
  for b in bolts() do
    if math.abs(b.head.y) < 1 then
      if b.head.x >= 5 - 1e-9 and b.head.x <= 5 + 0.1 + 1e-9 and math.abs(b.tip.x - b.head.x - 4) < 1e-9 then
        moved = moved + 1
      end
    elseif math.abs(b.head.x - 4) < 1e-9 then
      on_wall = on_wall + 1
    end
  end
  check.report("pocket: bolts laid along the wall", n, 6, 0, { absolute = true })
  check.report("pocket: bolts starting at its back", moved, 2, 0, { absolute = true })
  check.report("pocket: bolts on the wall elsewhere", on_wall, 4, 0, { absolute = true })
end

-- 5. The seed's sequence in small: in-situ stress, each stage excavated with a release and
--    solved, then bolted; the bolts laid early take tension as the benches go down, none is cut
--    or goes out of service.
do
  local w = cavern.warhead{ width = W, height = H, arch_height = RISE, benches = BENCHES }
  model{ title = "staged, solved and bolted" }
  block{ x = { -30, 30 }, y = { -30, 30 } }
  local names = {}
  for _, s in ipairs(w.stages) do region(s); names[#names + 1] = s.name end
  zone{ edge = 1, far = 4, near = names }
  material{ "rock", young = 1e9, poisson = 0.25, density = 2600 }
  assign{ material = "rock" }
  insitu{ sxx = -10e6, syy = -10e6 }
  for _, side in ipairs({ "left", "right", "top", "bottom" }) do boundary{ side = side, stress = "insitu" } end
  boundary{ side = "bottom", fix = "y" }
  bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6,
                 failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
  local unconverged, laid = 0, 0
  for _, s in ipairs(w.stages) do
    excavate{ region = s.name, release = 500 }
    if not solve{}.converged then unconverged = unconverged + 1 end
    local _, n = bolts.pattern{ surface = bolts.exposed(s, w), spacing = SPACING, length = LENGTH,
                                segments = SEGMENTS, material = "rebar" }
    laid = laid + n
  end
  local early, loaded, removed = 0, 0, 0
  for b in bolts() do
    if b.stage == 1 then
      early = early + 1
      if b.max_force > 0 then loaded = loaded + 1 end
    end
    if cut(b) then removed = removed + 1 end
  end
  check.report("staged run: solves not converged", unconverged, 0, 0, { absolute = true })
  check.report("staged run: bolts laid (as in section 1)", laid, #all_ids, 0, { absolute = true })
  check.report("staged run: stage-1 bolts in tension at the end", loaded, early, 0, { absolute = true })
  check.report("staged run: bolts cut or out of service", removed, 0, 0, { absolute = true })
end

print(("bolt patterns checked in %.2f s"):format(os.clock() - clock))
check.finish()
