-- Where a run of case.lua laid its potential cracks, which broke, and how near their strength the
-- ones left intact stand: read from a checkpoint the run saved (case.lua --set save_after=16).
-- It shows why one case breaks a smaller share of its sections than another (Case 3 against
-- Case 2, for instance).
--
--   edem --set case=3 --set save_after=16 run scripts/paper/case.lua
--   edem --quiet --set file=case3_P_h158_none_step16.h5 run scripts/paper/sections_left.lua
--
-- For each place around the opening (the roof above y = 10 m, each wall's upper part down to
-- y = -8 m and its lower part, the floor below y = -23 m) and each band of distance from the
-- outline: sections laid, sections broken, and of those left intact the median share of their
-- strength (the larger of s3 / tension and the Mohr circle's radius over the shear strength at its
-- centre, as judge{ most } ranks them) and their mean pressure. A section whose rock was mucked
-- out is gone (sections()).
local shapes = require "edem.shapes"
local cavern = require "edem.cavern"

local given = settings{ file = "" }
if given.file == "" then error("sections_left: give --set file=CHECKPOINT.h5 (case.lua --set save_after=16)", 0) end
restore(given.file)
local outline = cavern.warhead{}.outline

local function place_of(x, y)
  if y < -23 then return "floor" end
  if y > 10 then return "roof" end
  return (x < 0 and "left" or "right") .. (y > -8 and " upper" or " lower")
end
local BANDS = { { 0, 2 }, { 2, 5 }, { 5, 10 }, { 10, math.huge } }
local function band_of(d)
  for i, b in ipairs(BANDS) do if d < b[2] then return i end end
end
local function band_name(b)
  local from, to = BANDS[b][1], BANDS[b][2]
  return to < math.huge and ("%g to %g m"):format(from, to) or ("beyond %g m"):format(from)
end

local broken = {}
for k in cracks() do broken[k.section] = true end
local rows, order = {}, {}
local function row(key)
  if not rows[key] then
    rows[key] = { laid = 0, broken = 0, gone = 0, shares = {}, pressure = 0 }
  end
  return rows[key]
end
for _, place in ipairs{ "roof", "left upper", "right upper", "left lower", "right lower", "floor" } do
  order[#order + 1] = "within 2 m, " .. place
end
for b = 2, #BANDS do order[#order + 1] = band_name(b) end
order[#order + 1] = "all"
for s in sections() do
  local d = shapes.distance_to(outline, s.x, s.y)
  local b = band_of(d)
  local key = b == 1 and ("within 2 m, " .. place_of(s.x, s.y)) or band_name(b)
  for _, r in ipairs{ row(key), row("all") } do
    r.laid = r.laid + 1
    if broken[s.id] then
      r.broken = r.broken + 1
    elseif s.gone then
      r.gone = r.gone + 1
    else
      r.shares[#r.shares + 1] = s.overstress
      r.pressure = r.pressure - (s.s1 + s.s3) / 2
    end
  end
end
print(("%-26s %6s %7s %6s %7s %13s %15s"):format("where", "laid", "broken", "gone", "intact", "median share",
                                               "pressure [MPa]"))
for _, key in ipairs(order) do
  local r = row(key)
  table.sort(r.shares)
  local n = #r.shares
  local median = n > 0 and (n % 2 == 1 and r.shares[(n + 1) // 2] or (r.shares[n // 2] + r.shares[n // 2 + 1]) / 2)
  print(("%-26s %6d %7d %6d %7d %13s %15s"):format(key, r.laid, r.broken, r.gone, n,
                                                 median and ("%.2f"):format(median) or "-",
                                                 n > 0 and ("%.2f"):format(r.pressure / n / 1e6) or "-"))
end
-- Each section falls in one place or band, and is broken, gone or intact.
local all, sum = row("all"), 0
for _, key in ipairs(order) do if key ~= "all" then sum = sum + row(key).laid end end
print(("every section counted once: %s (%d laid, %d in the places and bands, %d broken + gone + intact)"):format(
  (sum == all.laid and all.broken + all.gone + #all.shares == all.laid and all.laid == info().sections) and "yes" or "no",
  all.laid, sum, all.broken + all.gone + #all.shares))
