-- The seed paper's trends (issue 9, acceptance 1) checked in the rows scripts/paper/case.lua wrote.
--
--   edem --set tables=study.csv --set markdown=trends.md run scripts/paper/trends.lua
--
-- Settings (--set KEY=VALUE):
--   tables    CSV files of case.lua's rows, separated by commas [case_results.csv]; where one case
--             (case, set, depth, bolts) has several rows the last one counts
--   set       the parameter set whose rows are compared [M]
--   depth     the depth of the comparisons that are not about depth [158]
--   step      N: compare each run's row after step N (the tables are case.lua's _steps files);
--             common: after the last step every run reached [the end of each run]
--   markdown  also write the table of trends to this file (markdown)
--   strict    true: fail (exit 1) unless every trend holds [false]
-- Each trend compares the rows it needs; a row missing, or a run that stopped before its last
-- step, makes the trend "not shown" (a comparison of unfinished runs says nothing), which fails
-- as a trend that does not hold does.
local function setting(key, default)
  local v = arg and arg[key]
  if v == nil then return default end
  return v
end
local SET, DEPTH = tostring(setting("set", "M")), setting("depth", 158)

-- A CSV line: commas between fields, a field in double quotes may hold commas.
local function fields(line)
  local out, i = {}, 1
  while i <= #line + 1 do
    if line:sub(i, i) == '"' then
      local j = line:find('"', i + 1, true) or (#line + 1)
      out[#out + 1] = line:sub(i + 1, j - 1)
      i = j + 2
    else
      local j = line:find(",", i, true) or (#line + 1)
      out[#out + 1] = line:sub(i, j - 1)
      i = j + 1
    end
  end
  return out
end

local rows = {}  -- per case key, the rows in the order read
local function key(case, depth, bolts) return ("%s/%g/%s"):format(case, depth, bolts) end
for file in tostring(setting("tables", "case_results.csv")):gmatch("[^,]+") do
  local f = io.open(file, "r")
  if not f then error(("trends: cannot read the table %s"):format(file), 0) end
  local names
  for line in f:lines() do
    local values = fields(line)
    if not names then
      names = values
    else
      local row = {}
      for i, name in ipairs(names) do row[name] = tonumber(values[i]) or values[i] end
      if row.set == SET then
        local k = key(row.case, row.depth, row.bolts)
        rows[k] = rows[k] or {}
        table.insert(rows[k], row)
      end
    end
  end
  f:close()
end

-- step = N: each run's row after its step N; "common": after the last step every run reached.
local STEP = setting("step", nil)
if STEP == "common" then
  local common = math.huge
  for _, list in pairs(rows) do
    local most = 0
    for _, r in ipairs(list) do most = math.max(most, r.steps) end
    common = math.min(common, most)
  end
  STEP = common < math.huge and common or nil
end

-- A finished run's row (at STEP, if given), or nil and why not.
local function run(case, depth, bolts)
  local list = rows[key(case, depth, bolts)]
  if not list then return nil, ("no run of Case %s, %g m, bolts %s"):format(case, depth, bolts) end
  local r = list[#list]
  if STEP then
    r = nil
    for _, row in ipairs(list) do if row.steps == STEP then r = row end end
    if not r then return nil, ("Case %s, %g m, bolts %s has no row after step %d"):format(case, depth, bolts, STEP) end
  end
  if r.stopped ~= "" then
    return nil, ("Case %s, %g m, bolts %s stopped at %s"):format(case, depth, bolts, r.stopped:sub(1, 60))
  end
  return r
end

local results = {}
local function trend(statement, needs, judge)
  local got, why = {}, nil
  for i, n in ipairs(needs) do
    local r, missing = run(n[1], n[2], n[3])
    if not r then why = why or missing end
    got[i] = r
  end
  local verdict, numbers
  if why then
    verdict, numbers = "not shown", why
  else
    local ok, holds, text = pcall(judge, table.unpack(got))
    if ok then
      verdict, numbers = holds and "holds" or "fails", text
    else  -- a table from an older case.lua, without the column
      verdict, numbers = "not shown", "the table lacks a column it needs"
    end
  end
  results[#results + 1] = { statement = statement, verdict = verdict, numbers = numbers }
end

local D = DEPTH
trend("Case 3 (denser joints) gives more new cracks than Case 2", { { 3, D, "none" }, { 2, D, "none" } },
  function(c3, c2)
    return c3.cracks > c2.cracks, ("Case 3: %d, Case 2: %d cracks"):format(c3.cracks, c2.cracks)
  end)
trend("The crack count grows with depth, 158 < 212 < 262 m (Case 3)",
  { { 3, 158, "none" }, { 3, 212, "none" }, { 3, 262, "none" } },
  function(a, b, c)
    return a.cracks < b.cracks and b.cracks < c.cracks,
      ("158 m: %d, 212 m: %d, 262 m: %d cracks"):format(a.cracks, b.cracks, c.cracks)
  end)
for _, case in ipairs{ 1, 2, 3 } do
  trend(("Tension cracks are the majority without bolts (Case %d)"):format(case), { { case, D, "none" } },
    function(r)
      return r.tension > r.shear, ("%d tension, %d shear"):format(r.tension, r.shear)
    end)
end
trend("Case 2's cracks on the right side sit higher than Case 1's", { { 2, D, "none" }, { 1, D, "none" } },
  function(c2, c1)
    return c2.right_mean_y_m > c1.right_mean_y_m,
      ("mean height of the right side's cracks: Case 2 %.1f m (%d cracks), Case 1 %.1f m (%d cracks)"):format(
        c2.right_mean_y_m, c2.right, c1.right_mean_y_m, c1.right)
  end)
trend("Pattern 1 lowers the crack count and the crown settlement (Case 3)", { { 3, D, "1" }, { 3, D, "none" } },
  function(p1, none)
    return p1.cracks < none.cracks and p1.crown_settlement_m < none.crown_settlement_m,
      ("cracks %d against %d; crown %.3f against %.3f m"):format(p1.cracks, none.cracks, p1.crown_settlement_m,
        none.crown_settlement_m)
  end)
trend("Pattern 2 lowers them at least as much as pattern 1 (Case 3)", { { 3, D, "2" }, { 3, D, "1" } },
  function(p2, p1)
    return p2.cracks <= p1.cracks and p2.crown_settlement_m <= p1.crown_settlement_m,
      ("cracks %d against %d; crown %.3f against %.3f m"):format(p2.cracks, p1.cracks, p2.crown_settlement_m,
        p1.crown_settlement_m)
  end)
for _, case in ipairs{ 1, 2, 3 } do
  trend(("The side the joints dip towards (right) moves more (Case %d)"):format(case), { { case, D, "none" } },
    function(r)
      return r.right_wall_m > r.left_wall_m,
        ("walls moved in %.3f m (right) and %.3f m (left)"):format(r.right_wall_m, r.left_wall_m)
    end)
end

local when = STEP and ("after step %d of 16 in every run"):format(STEP) or "at the end of each run"
local lines = { ("Set %s, %s. Trends of the seed paper (§3.4, §4, §5) in EDEM's runs:"):format(SET, when), "",
                "| trend | EDEM | verdict |", "|---|---|---|" }
local failed = 0
for _, r in ipairs(results) do
  lines[#lines + 1] = ("| %s | %s | %s |"):format(r.statement, r.numbers, r.verdict)
  if r.verdict ~= "holds" then failed = failed + 1 end
end
lines[#lines + 1] = ""
lines[#lines + 1] = ("%d of %d trends hold."):format(#results - failed, #results)
local text = table.concat(lines, "\n")
print(text)
local markdown = setting("markdown", nil)
if markdown then
  local f = assert(io.open(tostring(markdown), "w"))
  f:write(text, "\n")
  f:close()
end
if setting("strict", false) == true and failed > 0 then
  error(("%d of %d trends do not hold or are not shown"):format(failed, #results), 0)
end
