-- The seed's Figure 12: the vertical displacement 10 m above the crown of Case 3 at the
-- end, without bolts and with bolt patterns 1 and 2, on one chart, from the profiles
-- scripts/paper/case.lua writes (TAG_profile.csv). study.sh draws it in the study's folder once the
-- three runs are there.
--
--   edem --set none=A.csv --set pattern1=B.csv --set pattern2=C.csv run scripts/paper/figure12.lua
--
-- Settings (--set KEY=VALUE):
--   none, pattern1, pattern2  the three runs' profiles [case3_M_h158_none_profile.csv,
--             case3_M_h158_pattern1_profile.csv, case3_M_h158_pattern2_profile.csv]
--   file      the chart to write (.png, .svg or .pdf) [figure12.png]
--   title     its title [Case 3, 158 m: vertical displacement 10 m above the crown]
local function setting(key, default)
  local v = arg and arg[key]
  if v == nil then return default end
  return tostring(v)
end

-- A profile: its header must be case.lua's, then x and uy a line, in the order drawn.
local function read_profile(path)
  local f = io.open(path, "r")
  if not f then error(("figure12: cannot read the profile %s"):format(path), 0) end
  local header = f:read("l")
  if header ~= "x_m,uy_m" then
    f:close()
    error(("figure12: %s starts %q, not case.lua's header x_m,uy_m"):format(path, tostring(header)), 0)
  end
  local x, uy, line_number = {}, {}, 1
  for line in f:lines() do
    line_number = line_number + 1
    local a, b = line:match("^([^,]+),([^,]+)$")
    local xi, yi = tonumber(a), tonumber(b)
    if not xi or not yi then
      f:close()
      error(("figure12: %s line %d is not two numbers: %q"):format(path, line_number, line), 0)
    end
    x[#x + 1], uy[#uy + 1] = xi, yi
  end
  f:close()
  if #x < 2 then error(("figure12: %s has %d points; a profile needs two at least"):format(path, #x), 0) end
  return x, uy
end

local runs = {
  { name = "no bolts", key = "none", default = "case3_M_h158_none_profile.csv" },
  { name = "pattern 1", key = "pattern1", default = "case3_M_h158_pattern1_profile.csv" },
  { name = "pattern 2", key = "pattern2", default = "case3_M_h158_pattern2_profile.csv" },
}
local series = {}
for i, run in ipairs(runs) do
  local x, uy = read_profile(setting(run.key, run.default))
  series[i] = { name = run.name, x = x, y = uy }
end
local file = setting("file", "figure12.png")
local title = setting("title", "Case 3, 158 m: vertical displacement 10 m above the crown")
chart{ file = file, series = series, title = title,
       x_label = "x [m] (right: the side whose joints dip into the opening)", y_label = "vertical displacement uy [m]" }
print(("figure12: %s written"):format(file))
