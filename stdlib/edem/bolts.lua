-- edem.bolts: bolting patterns along excavated walls, on top of bolt{}.
--
--   local cavern = require "edem.cavern"
--   local bolts = require "edem.bolts"   -- also callable as the bolts() iterator it hides
--   local c = cavern.warhead{ width = 24, height = 48 }                -- the seed's cavern
--   -- ... regions, zones, materials, stress; then the seed's pattern 1, 5 m bolts at 1.5 m laid
--   -- on the new permanent walls after each of the 16 steps:
--   bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6,
--                  failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6,
--                  spacing = 1.5 }
--   for _, s in ipairs(c.stages) do
--     excavate{ region = s.name, release = 2000 }; solve{}
--     bolts.pattern{ surface = bolts.exposed(s, c.outline), spacing = 1.5, length = 5,
--                    segments = 10, material = "rebar" }
--   end
--
-- bolts.pattern{ surface, spacing, length, segments | segment_length, material, where, first,
--                free_length }
--   Lays a bolt every `spacing` metres of arc length along each polyline of the surface, its head
--   on the wall and the bolt normal to the wall there, pointing into the rock, `length` long.
--   surface        a polyline { {x, y}, {x, y}, ... } (2 points or more; {x =, y =} points too)
--                  or a list of them (an empty list lays nothing), e.g. bolts.exposed(...)
--   spacing  m     > 0, required: between heads, along each polyline (starting over on each)
--   length   m     > 0, required: the whole bolt, head to end (free_length included)
--   segments n | segment_length m   one of them, required: passed on to bolt{}
--   material       required: a bolt_material{}'s name
--   first    m     >= 0, default spacing / 2: arc length from each polyline's start to its
--                  first head; the heads are at first, first + spacing, ... up to its end
--   where          function(x, y) -> boolean, optional: lay only the bolts whose head (x, y) it
--                  accepts; the others keep their places in the spacing
--   free_length m  >= 0, optional: passed on to bolt{} (the ungrouted length from the head)
--   missing        "error" (default) or "skip": what a head with no rock near it on either side
--                  or with rock on both sides does (see below), and a bolt whose far end lies
--                  outside the rock; "skip" leaves such bolts out, as where rock has fallen out and
--                  there is nothing to bolt into, or fallen rock lies against the wall
--   Returns the list of the bolt ids laid, in order along the surface, their count, and the
--   number of heads skipped (missing = "skip").
--   The normal: a head inside a segment takes the segment's normal; a head on a vertex between
--   two segments takes the mean of their unit normals (the bisector of the corner). The rock's
--   side is found at each head: zone_at() a tenth of the bolt's length off the wall on both
--   sides along the normal (not nearer: a model{ tolerance } can bend the blocks' outlines off
--   the drawn outline by a fraction of a metre); a point is rock when a zone holds it that
--   is not excavated and has a material other than "null". Rock on both sides stops the script
--   (unless missing = "skip"):
--   "bolts.pattern: the wall at (x, y) has rock on both sides". Rock on neither (the wall is
--   gone there: a block fell out of it) takes the side where rock comes first along the normal,
--   up to half the bolt's length away, and the bolt starts where the rock begins (found in steps
--   of a 40th of its length); with none that near: "... has rock on neither side". A bolt also
--   starts where the rock begins if the blocks' outline lies a little off the drawn wall. Every head is placed and checked before any bolt is laid; bolt{}'s own
--   refusal (a bolt running out of the rock into a neighbouring opening, an unknown material)
--   stops the script naming that bolt, with the bolts before it laid.
--
-- bolts.exposed(stage, outline)
--   The walls a stage's excavation exposes that stay walls: the parts of the stage polygon's
--   edges that lie on the final excavation outline, as a list of polylines, each following the
--   stage polygon's order, consecutive parts joined (a stage whose whole boundary is on the
--   outline gives one closed polyline, its first point repeated at its end). An edge part lies
--   on the outline where the outline has a collinear edge over it (both within 1e-9 of the
--   outline's size). stage: { name =, polygon = } as cavern.lua gives it, { name, polygon }, or a
--   bare polygon; outline: a polygon, or a table with an `outline` (cavern.lua's result).
--   With cavern.warhead: the arch stages give their arcs of the arch; each bench gives its two
--   side walls, and the last bench one polyline down the left wall, along the floor and up the
--   right wall: the floor is part of the final outline, so it is a permanent wall then. The
--   temporary floors (the cuts between stages) are never exposed.
--
-- Lengths in m. A wrong key or value stops the script at the caller's line:
-- "bolts.pattern: spacing = 0: must be a number > 0".

-- The module is callable as the bolts() iterator it hides: `local bolts = require "edem.bolts"`
-- then `for b in bolts() do ... end` still goes over the bolts laid.
local iterate = bolts
local bolts = {}
setmetatable(bolts, { __call = function(_, ...) return iterate(...) end })

-- Reading and checking the arguments -----------------------------------------------------------

local args = require "edem.args"
local show, as_point = args.show, args.point

-- The keys of its own; the rest are edem.args's.
local kinds = {
  ["function"] = { says = "a function(x, y) returning true for the heads to keep",
                   read = function(v) return type(v) == "function" and v or nil end },
  surface = { says = "a polyline { {x, y}, ... } or a list of them",
              read = function(v) return type(v) == "table" and v or nil end },
  missing = { says = "\"error\" or \"skip\"",
              read = function(v) return (v == "error" or v == "skip") and v or nil end },
}

-- Reads t against spec (edem.args); errors are blamed on the caller of the public function.
local function read(fn, t, spec) return args.read("bolts", fn, t, spec, kinds) end

-- A polyline's points, copied, or nil and what is wrong with it (`label` names it).
local function read_polyline(v, label, least)
  if type(v) ~= "table" then
    return nil, ("%s = %s: must be a list of points {x, y}"):format(label, show(v))
  end
  local out = {}
  for i, p in ipairs(v) do
    out[i] = as_point(p)
    if not out[i] then
      return nil, ("%s[%d] = %s: must be a point {x, y}"):format(label, i, show(p))
    end
  end
  if #out < least then
    return nil, ("%s: %d point(s): needs at least %d"):format(label, #out, least)
  end
  return out
end

-- The surface as a list of polylines: one polyline (its first item a point) or a list of them.
local function read_surface(v)
  local wrong = "surface = %s: must be a polyline { {x, y}, ... } or a list of them"
  if type(v) ~= "table" then return nil, wrong:format(show(v)) end
  if #v == 0 and next(v) == nil then return {} end
  if as_point(v[1]) then
    local line, why = read_polyline(v, "surface", 2)
    return line and { line }, why
  end
  local lines = {}
  for i, l in ipairs(v) do
    local line, why = read_polyline(l, ("surface[%d]"):format(i), 2)
    if not line then return nil, why end
    lines[i] = line
  end
  if #lines == 0 then return nil, wrong:format(show(v)) end
  return lines
end

-- Geometry ---------------------------------------------------------------------------------------

local function unit_normal(a, b)        -- the left normal of a -> b; nil for a zero-length edge
  local dx, dy = b[1] - a[1], b[2] - a[2]
  local l = math.sqrt(dx * dx + dy * dy)
  if l == 0 then return nil end
  return { -dy / l, dx / l }
end

local function extent(lines)            -- the largest side of the bounding box of the points
  local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
  for _, line in ipairs(lines) do
    for _, p in ipairs(line) do
      x0, x1 = math.min(x0, p[1]), math.max(x1, p[1])
      y0, y1 = math.min(y0, p[2]), math.max(y1, p[2])
    end
  end
  return math.max(x1 - x0, y1 - y0, 0)
end

-- Heads along a polyline: { point, normal } at arc lengths first, first + spacing, ... <= its
-- length (tol: how near a vertex or the end counts as on it).
local function heads_along(line, first, spacing, tol, into)
  local segs = {}                        -- the non-degenerate segments { a, b, n, s0, s1 }
  local s = 0
  for i = 1, #line - 1 do
    local a, b = line[i], line[i + 1]
    local n = unit_normal(a, b)
    if n then
      local l = math.sqrt((b[1] - a[1]) ^ 2 + (b[2] - a[2]) ^ 2)
      segs[#segs + 1] = { a = a, b = b, n = n, s0 = s, s1 = s + l }
      s = s + l
    end
  end
  local total = s
  -- A closed polyline (its last point its first): no second head where it closes, and a head
  -- where it starts takes the corner's bisector too.
  local closed = #segs > 1 and line[1][1] == line[#line][1] and line[1][2] == line[#line][2]
  local function bisector(n, m)
    local nx, ny = n[1] + m[1], n[2] + m[2]
    local l = math.sqrt(nx * nx + ny * ny)
    return l > 1e-12 and { nx / l, ny / l } or n
  end
  local k, j = 0, 1
  while #segs > 0 do
    local at = first + k * spacing
    if at > total + tol or (closed and at >= total - tol) then break end
    while j < #segs and at > segs[j].s1 + tol do j = j + 1 end
    local seg = segs[j]
    local point, normal
    if math.abs(at - seg.s1) <= tol and segs[j + 1] then
      point, normal = seg.b, bisector(seg.n, segs[j + 1].n)   -- on a vertex: the bisector
    elseif math.abs(at - seg.s0) <= tol and j == 1 and closed then
      point, normal = seg.a, bisector(segs[#segs].n, seg.n)
    elseif math.abs(at - seg.s0) <= tol then
      point, normal = seg.a, seg.n
    elseif math.abs(at - seg.s1) <= tol then
      point, normal = seg.b, seg.n
    else
      local t = (at - seg.s0) / (seg.s1 - seg.s0)
      point = { seg.a[1] + t * (seg.b[1] - seg.a[1]), seg.a[2] + t * (seg.b[2] - seg.a[2]) }
      normal = seg.n
    end
    into[#into + 1] = { point = point, normal = normal }
    k = k + 1
  end
  return into
end

local function is_rock(x, y)
  local z = zone_at(x, y)
  return z ~= nil and (z.excavated == nil or z.excavated == 0) and z.material ~= nil
         and z.material ~= "null"
end

-- bolts.pattern ----------------------------------------------------------------------------------

function bolts.pattern(t)
  local o = read("pattern", t, {
    { "surface", "surface" }, { "spacing", "positive" }, { "length", "positive" },
    { "segments", "count" }, { "segment_length", "positive" }, { "material", "name" },
    { "where", "function" }, { "first", "nonnegative" }, { "free_length", "nonnegative" },
    { "missing", "missing" },
  })
  for _, key in ipairs({ "surface", "spacing", "length", "material" }) do
    if o[key] == nil then error(("bolts.pattern: %s is required"):format(key), 2) end
  end
  if (o.segments == nil) == (o.segment_length == nil) then
    error(("bolts.pattern: give segments = n or segment_length = l (one of them), got %s"):format(
      o.segments and ("segments = %s and segment_length = %s"):format(show(o.segments),
        show(o.segment_length)) or "neither"), 2)
  end
  if o.free_length and o.free_length >= o.length then
    error(("bolts.pattern: free_length = %s: must be shorter than length = %s"):format(
      show(o.free_length), show(o.length)), 2)
  end
  local lines, why = read_surface(o.surface)
  if not lines then error("bolts.pattern: " .. why, 2) end
  local first = o.first or o.spacing / 2

  -- Place every head and find its rock side before laying any bolt.
  local size = math.max(extent(lines), o.length)
  local tol, probe = 1e-9 * size, 0.1 * o.length
  local heads = {}
  for _, line in ipairs(lines) do heads_along(line, first, o.spacing, tol, heads) end
  local plan, skipped = {}, 0
  for _, h in ipairs(heads) do
    local x, y, n = h.point[1], h.point[2], h.normal
    if not o.where or o.where(x, y) then
      -- The rock's side: the one with rock a tenth of the bolt off the wall. With neither (the
      -- wall has gone: a block fell out of it) the side where rock comes first, up to half the
      -- bolt's length away; the bolt then starts where the rock begins.
      local function rock_within(sx, sy)
        if is_rock(x + tol * sx, y + tol * sy) then return 0 end
        for k = 1, 20 do
          if is_rock(x + k * o.length / 40 * sx, y + k * o.length / 40 * sy) then return k * o.length / 40 end
        end
      end
      local plus = is_rock(x + probe * n[1], y + probe * n[2])
      local minus = is_rock(x - probe * n[1], y - probe * n[2])
      if plus and minus and o.missing ~= "skip" then
        error(("bolts.pattern: the wall at (%s, %s) has rock on both sides"):format(show(x), show(y)), 2)
      end
      local sign, start = plus and 1 or -1, nil
      if plus and minus then
        skipped = skipped + 1  -- rock that fell into the opening lies against the wall
      elseif plus or minus then
        start = rock_within(sign * n[1], sign * n[2])
      else
        local ahead, behind = rock_within(n[1], n[2]), rock_within(-n[1], -n[2])
        if not ahead and not behind and o.missing ~= "skip" then
          error(("bolts.pattern: the wall at (%s, %s) has rock on neither side"):format(show(x), show(y)), 2)
        end
        if not ahead and not behind then skipped = skipped + 1 end
        sign = (ahead and (not behind or ahead <= behind)) and 1 or -1
        start = sign == 1 and ahead or behind
      end
      local dx, dy = sign * n[1], sign * n[2]
      if start then plan[#plan + 1] = { x = x + start * dx, y = y + start * dy, dx = dx, dy = dy } end
    end
  end

  local ids = {}
  for i, p in ipairs(plan) do
    local def = { from = { p.x, p.y }, to = { p.x + o.length * p.dx, p.y + o.length * p.dy },
                  segments = o.segments, segment_length = o.segment_length,
                  free_length = o.free_length, material = o.material }
    local ok, id = pcall(bolt, def)
    if not ok and o.missing == "skip" and tostring(id):find("is not in the rock", 1, true) then
      skipped = skipped + 1  -- its far end lies where rock has fallen out
    elseif not ok then
      local text = tostring(id):gsub("^.-:%d+: ", "", 1)
      error(("bolts.pattern: bolt %d of %d, from (%s, %s) to (%s, %s) (%d laid): %s"):format(
        i, #plan, show(def.from[1]), show(def.from[2]), show(def.to[1]), show(def.to[2]),
        #ids, text), 2)
    end
    if ok then ids[#ids + 1] = id end
  end
  return ids, #ids, skipped
end

-- bolts.exposed ----------------------------------------------------------------------------------

function bolts.exposed(stage, outline)
  local poly, why
  if type(stage) == "table" and (stage.polygon ~= nil or type(stage[1]) == "string") then
    poly, why = read_polyline(stage.polygon or stage[2], "stage.polygon", 3)
  else
    poly, why = read_polyline(stage, "stage", 3)
  end
  if not poly then error("bolts.exposed: " .. why, 2) end
  local ring
  if type(outline) == "table" and outline.outline ~= nil then
    ring, why = read_polyline(outline.outline, "outline.outline", 3)
  else
    ring, why = read_polyline(outline, "outline", 3)
  end
  if not ring then error("bolts.exposed: " .. why, 2) end

  local tol = 1e-9 * extent({ ring })
  local pieces = {}                      -- { a, b }: the parts on the outline, in polygon order
  for i, a in ipairs(poly) do
    local b = poly[i % #poly + 1]
    local dx, dy = b[1] - a[1], b[2] - a[2]
    local l2 = dx * dx + dy * dy
    if l2 > 0 then
      local l = math.sqrt(l2)
      -- The outline's edges collinear with a -> b, as intervals of its parameter t, each end
      -- with its point (an outline corner, or a or b themselves).
      local spans = {}
      for j, p in ipairs(ring) do
        local q = ring[j % #ring + 1]
        local op = math.abs((p[1] - a[1]) * dy - (p[2] - a[2]) * dx) / l
        local oq = math.abs((q[1] - a[1]) * dy - (q[2] - a[2]) * dx) / l
        if op <= tol and oq <= tol then
          local tp = ((p[1] - a[1]) * dx + (p[2] - a[2]) * dy) / l2
          local tq = ((q[1] - a[1]) * dx + (q[2] - a[2]) * dy) / l2
          if tp > tq then tp, tq, p, q = tq, tp, q, p end
          if tp < 1 - tol / l and tq > tol / l then
            local s = { t0 = tp, p0 = p, t1 = tq, p1 = q }
            if s.t0 <= tol / l then s.t0, s.p0 = 0, a end
            if s.t1 >= 1 - tol / l then s.t1, s.p1 = 1, b end
            spans[#spans + 1] = s
          end
        end
      end
      table.sort(spans, function(u, v) return u.t0 < v.t0 end)
      local open
      for _, s in ipairs(spans) do         -- merge touching spans, emit the covered parts
        if open and s.t0 <= open.t1 + tol / l then
          if s.t1 > open.t1 then open.t1, open.p1 = s.t1, s.p1 end
        else
          if open then pieces[#pieces + 1] = { open.p0, open.p1 } end
          open = { t0 = s.t0, p0 = s.p0, t1 = s.t1, p1 = s.p1 }
        end
      end
      if open then pieces[#pieces + 1] = { open.p0, open.p1 } end
    end
  end

  local function same(p, q) return math.abs(p[1] - q[1]) <= tol and math.abs(p[2] - q[2]) <= tol end
  local lines = {}
  for _, piece in ipairs(pieces) do
    local last = lines[#lines]
    if last and same(last[#last], piece[1]) then
      last[#last + 1] = { piece[2][1], piece[2][2] }
    else
      lines[#lines + 1] = { { piece[1][1], piece[1][2] }, { piece[2][1], piece[2][2] } }
    end
  end
  -- The polygon's start may fall inside a wall: join the last polyline to the first.
  if #lines > 1 and same(lines[#lines][#lines[#lines]], lines[1][1]) then
    local last = table.remove(lines)
    for k = 2, #lines[1] do last[#last + 1] = lines[1][k] end
    lines[1] = last
  end
  return lines
end

return bolts
