-- edem.check: reporting measured against expected values in verification scripts.
--
--   local check = require "edem.check"
--   check.report("wall u [m]", measured, expected, 0.02)        -- relative tolerance
--   check.report("ratio", r, 0, 1e-6, { absolute = true })     -- absolute tolerance
--   check.finish()   -- raises an error (the script fails) if any check failed
--
-- Each report prints one line: name, measured, expected, error and tolerance, ok or FAIL.
local check = {}

local failures = {}

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
  return ok
end

function check.finish()
  if #failures > 0 then
    error(("%d check(s) failed: %s"):format(#failures, table.concat(failures, "; ")), 0)
  end
  print("all checks passed")
end

return check
