-- edem.check: reporting measured against expected values in verification scripts.
--
--   local check = require "edem.check"
--   check.report("wall u [m]", measured, expected, 0.02)        -- relative tolerance
--   check.report("ratio", r, 0, 1e-6, { absolute = true })     -- absolute tolerance
--   check.finish()   -- raises an error (the script fails) if any check failed
--   check.acceleration(samples, from, to)  -- a of s = s0 + v0 t + a t^2 / 2 fitted to {t, s}
--
-- Each report prints one line: name, measured, expected, error and tolerance, ok or FAIL.
-- With `--set report=DIR` (scripts/make-docs.sh), finish() also writes the script's section of
-- the verification chapter: DIR/NAME.md (the script's opening comment, a table of its checks)
-- and DIR/NAME.png (each check's error over its tolerance, log scale).
local check = {}

local failures = {}
local rows = {}

function check.report(name, measured, expected, tolerance, options)
  options = options or {}
  local err
  if options.absolute then
    err = math.abs(measured - expected)
  else
    err = expected ~= 0 and math.abs(measured - expected) / math.abs(expected) or math.abs(measured)
  end
  local ok = err <= tolerance and measured == measured  -- NaN never passes
  print(("%-62s measured %-14.7g expected %-14.7g %s error %.3e (tolerance %.3g)  %s"):format(
    name, measured, expected, options.absolute and "abs" or "rel", err, tolerance,
    ok and "ok" or "FAIL"))
  if not ok then failures[#failures + 1] = name end
  rows[#rows + 1] = { name = name, measured = measured, expected = expected, err = err, tolerance = tolerance,
                      absolute = options.absolute, ok = ok }
  return ok
end

-- The script's opening comment block as written (its lists and alignments are the author's), in
-- a text block.
local function description(path)
  local lines, file = {}, io.open(path, "r")
  if not file then return "" end
  for line in file:lines() do
    local comment = line:match("^%-%-%s?(.*)$")
    if not comment then break end
    lines[#lines + 1] = comment
  end
  file:close()
  if #lines == 0 then return "" end
  return ("```text\n%s\n```"):format(table.concat(lines, "\n"))
end

local function escape(text) return (tostring(text):gsub("|", "\\|")) end

-- DIR/NAME.md and DIR/NAME.png for the verification chapter.
local function write_section(dir)
  local script = arg and arg[0] or "script.lua"
  local name = script:match("([^/]+)%.lua$") or script
  local md = assert(io.open(("%s/%s.md"):format(dir, name), "w"))
  md:write(("## %s\n\n%s\n\n"):format(name, description(script)))
  md:write("| check | measured | expected | error | tolerance | |\n|---|---|---|---|---|---|\n")
  local x, ratio = {}, {}
  for i, r in ipairs(rows) do
    md:write(("| %s | %.7g | %.7g | %.3e %s | %.3g | %s |\n"):format(escape(r.name), r.measured, r.expected, r.err,
      r.absolute and "abs" or "rel", r.tolerance, r.ok and "ok" or "**FAIL**"))
    x[i] = i
    -- How much of its tolerance each check uses, kept inside the log axis.
    local used = r.tolerance > 0 and r.err / r.tolerance or (r.err == 0 and 0 or 1e6)
    ratio[i] = math.min(math.max(used, 1e-12), 1e6)
  end
  md:write(("\n![%s: error over tolerance per check](report/%s.png)\n"):format(name, name))
  md:close()
  if #rows > 0 then
    chart{ file = ("%s/%s.png"):format(dir, name), size = {800, 420}, log = {"y"},
           title = name .. ": error / tolerance of each check (1 = at the limit)",
           x_label = "check (in the order of the table)", y_label = "error / tolerance",
           series = { { name = "error / tolerance", x = x, y = ratio },
                      { name = "limit", x = { 1, math.max(#rows, 2) }, y = { 1, 1 } } } }
  end
end

-- Least-squares fit of s = s0 + v0 t + a t^2 / 2 over samples {t, s} with t in [from, to]
-- (both optional): a.
function check.acceleration(samples, from, to)
  from, to = from or -math.huge, to or math.huge
  local S = {}
  for i = 1, 3 do S[i] = { 0, 0, 0, 0 } end
  for _, p in ipairs(samples) do
    local t, s = p[1], p[2]
    if t >= from and t <= to then
      local basis = { 1, t, t * t / 2 }
      for i = 1, 3 do
        for j = 1, 3 do S[i][j] = S[i][j] + basis[i] * basis[j] end
        S[i][4] = S[i][4] + basis[i] * s
      end
    end
  end
  for k = 1, 3 do  -- Gauss elimination, 3 x 3
    for i = k + 1, 3 do
      local f = S[i][k] / S[k][k]
      for j = k, 4 do S[i][j] = S[i][j] - f * S[k][j] end
    end
  end
  local x = {}
  for i = 3, 1, -1 do
    local sum = S[i][4]
    for j = i + 1, 3 do sum = sum - S[i][j] * x[j] end
    x[i] = sum / S[i][i]
  end
  return x[3]
end

function check.finish()
  if arg and arg.report then write_section(arg.report) end
  if #failures > 0 then
    error(("%d check(s) failed: %s"):format(#failures, table.concat(failures, "; ")), 0)
  end
  print("all checks passed")
end

return check
