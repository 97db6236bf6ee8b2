-- Tutorial 1: a first model, command by command. Run it with `edem run first_model.lua`.
--
-- A block of rock is cut by two joint sets and one crack, a tunnel outline is cut in as a
-- named region, and the model is zoned finely around the tunnel. The script checks what it
-- built (examples are also tests) and draws it to first_model.png.

-- Every script starts a model; the title appears on pictures.
model{ title = "Tutorial 1: a jointed block around a tunnel" }

-- One block of intact rock, 60 m x 40 m. A block can also be given by its corners:
-- block{ {0, 0}, {60, 0}, {60, 40}, {0, 40} }.
block{ x = {-30, 30}, y = {-20, 20} }

-- A joint set: traces at 35 degrees counter-clockwise from +x, 6 m apart, passing through
-- the origin. jset returns the set's number.
local main_set = jset{ angle = 35, spacing = 6 }

-- A second, persistent-but-discontinuous set: traces 15 m long with 5 m gaps, spacings used in
-- turn, and a little random scatter of the angle (the same seed gives the same joints).
local cross_set = jset{ angle = -50, spacing = {8, 5}, trace = 15, gap = 5,
                        angle_dev = 3, seed = 42 }
print(("joint sets %d and %d"):format(main_set, cross_set))

-- A single crack; parts of it that split no block are dropped and counted.
crack{ from = {-25, -15}, to = {-5, 10} }

-- The tunnel: a horseshoe outline as a named region (glued: its outline never slides).
local function horseshoe(width, wall, segments)
  local half = width / 2
  local outline = { {-half, -wall}, {half, -wall} }
  for i = 0, segments do
    local a = math.pi * i / segments
    outline[#outline + 1] = { half * math.cos(a), half * math.sin(a) }
  end
  return outline
end
region{ name = "tunnel", polygon = horseshoe(8, 4, 12) }

-- Zones: 0.5 m near the tunnel, growing with distance to at most 4 m.
zone{ edge = 0.5, far = 4, growth = 0.3, near = "tunnel" }

local counts = info()
print(("%s: %d blocks, %d zones, %d gridpoints, %d dropped cuts"):format(
  counts.title, counts.blocks, counts.zones, counts.gridpoints, counts.dropped_cuts))

-- Blocks and zones can be read back; ids start at 1.
local total, tunnel = 0, 0
for b in blocks() do
  total = total + b.area
  if b.region == "tunnel" then tunnel = tunnel + b.area end
end
assert(math.abs(total - 60 * 40) < 1e-6, "the blocks tile the model")
local expected = 8 * 4 + math.pi * 16 / 2  -- rectangle + half disc, approximated by 12 chords
assert(tunnel > 0.97 * expected and tunnel < expected, "the tunnel's blocks fill its outline")
print(("tunnel area %.2f m2"):format(tunnel))

local finest = math.huge
for z in zones() do finest = math.min(finest, z.area) end
assert(finest < 0.5, "zones are fine near the tunnel")

plot{ file = "first_model.png", show = { "zones", "blocks", "joints", "regions" } }
print("wrote first_model.png")
