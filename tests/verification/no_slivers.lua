-- No slivers: cutting never leaves a block edge shorter than zone{ sliver }
-- (a tenth by default) of the zone edge there. Where two cuts would make one (a joint crossing
-- another just past a vertex, a region's outline passing close to a joint's end), they are bent
-- together through the vertex, at most that far; info().snapped counts those bends, and
-- info().shortest_edge is the shortest block edge over the zone edge at its midpoint. Required cuts
-- crossing at a shallow angle may not bend clear: there, within a spot of 8 tolerances, the model's
-- own tolerance holds and the slivers are kept, counted by info().slivers_kept (optional cuts, the
-- automatic potential cracks, are left out there instead).
--   * checked: the seed's region with its cavern's stages, zoned as scripts/paper/case.lua zones
--     it (1.5 m at the cavern growing to 10 m), each of the seed's three joint patterns; and every
--     tutorial in scripts/examples, as it is zoned;
--   * printed: the seed's region with potential cracks drawn by hand (required cuts) at case.lua's
--     4.8 m spacing, at 30 and 120 deg, over the rock within 44 m of the cavern's centre, the cuts
--     most prone to slivers: what was snapped, the spots kept and the shortest edge. case.lua
--     prints the same for its automatic potential cracks.
-- Each prints what was snapped and the shortest edge, beside the shortest edge without zone{
-- sliver }.
local check = require "edem.check"
local seed = require "edem.seed"
local cavern = require "edem.cavern"

local SLIVER = 0.1
local c = cavern.warhead{}
local around = { {-44, -44}, {44, -44}, {44, 44}, {-44, 44} }

local function seed_region(case, sliver, with_seeds)
  model{ title = ("the seed's case %d"):format(case), tolerance = 1e-9 }
  local zone_now = zone
  zone = function(t)
    if with_seeds then crackseed{ angles = {30, 120}, spacing = 4.8, region = around, material = "rock" } end
    t.sliver = sliver
    zone_now(t)
  end
  seed.region{ case = case, regions = c.stages, near = { c.outline }, edge = 1.5, far = 10 }
  zone = zone_now
  return info()
end

for _, with_seeds in ipairs({ false, true }) do
  for case = 1, 3 do
    local without = seed_region(case, 0, with_seeds)
    local i = seed_region(case, SLIVER, with_seeds)
    print(("  case %d%s: %d blocks, %d zones; %d features snapped, %d spots kept, shortest edge %.3f of the "
           .. "zone edge (without zone{ sliver }: %.2g)"):format(case, with_seeds and ", potential cracks" or "",
           i.blocks, i.zones, i.snapped, i.slivers_kept, i.shortest_edge, without.shortest_edge))
    if not with_seeds then
      check.report(("seed region, case %d: shortest edge / zone edge >= %g"):format(case, SLIVER),
                   i.shortest_edge >= SLIVER and 1 or 0, 1, 0, { absolute = true })
    end
  end
end

-- The tutorials, each up to its zone{}: the geometry is whole there.
local here = (arg and arg[0] or ""):match("^(.*)/[^/]*$") or "."
local examples = here .. "/../../scripts/examples/"
local STOP = {}
for _, name in ipairs({ "first_model", "jointed_cavern", "reading_the_model", "staged_tunnel" }) do
  local zone_now = zone
  zone = function(t)
    zone_now(t)
    error(STOP)
  end
  local ok, err = pcall(dofile, examples .. name .. ".lua")
  zone = zone_now
  if not ok and err ~= STOP then error(err, 0) end
  local i = info()
  print(("  %s: %d blocks, %d zones; %d features snapped, shortest edge %.3f of the zone edge"):format(
    name, i.blocks, i.zones, i.snapped, i.shortest_edge))
  check.report(("tutorial %s: shortest edge / zone edge >= %g"):format(name, SLIVER),
               i.shortest_edge >= SLIVER and 1 or 0, 1, 0, { absolute = true })
end
check.finish()
