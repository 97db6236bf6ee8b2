-- What the tests of scripts/paper/trends.lua share: run it over tables of rows and read its
-- verdicts, and count the verdicts and texts that are not as expected.
--
--   local check = dofile(here .. "trends_check.lua")
--   local found, text = check.verdicts(tables, { judge = "means" })
--   check.expect(found, statement, verdict)
--   if check.failures > 0 then error(...) end
local here = debug.getinfo(1, "S").source:match("^@(.*[/\\])") or "./"
local trends = here .. "../../scripts/paper/trends.lua"
local check = { failures = 0 }

-- Runs trends.lua over `tables` (with `settings` besides) and returns its markdown's verdicts, one
-- per trend statement, and the markdown.
function check.verdicts(tables, settings)
  local out = os.tmpname()  -- its own file: the tests that share this one run side by side
  arg = { tables = tables, markdown = out, set = "M" }  -- the fixtures' rows are Set M's
  for key, value in pairs(settings or {}) do arg[key] = value end
  dofile(trends)
  local f = assert(io.open(out, "r"))
  local text = f:read("a")
  f:close()
  os.remove(out)
  local found = {}
  for line in text:gmatch("[^\n]+") do
    local statement, verdict = line:match("^| (.-) | .- | ([^|]-) |$")
    if statement then found[statement] = verdict end
  end
  return found, text
end

function check.expect(found, statement, verdict)
  local got = found[statement]
  local ok = got == verdict
  print(("%s: %s -> %s (expected %s)"):format(ok and "ok" or "WRONG", statement, tostring(got), verdict))
  if not ok then check.failures = check.failures + 1 end
end

-- Whether the markdown says `words` (plain text).
function check.says(text, words)
  local ok = text:find(words, 1, true) ~= nil
  print(("%s: the table says %q"):format(ok and "ok" or "WRONG", words))
  if not ok then check.failures = check.failures + 1 end
end

return check
