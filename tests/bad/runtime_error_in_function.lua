-- line: 6
-- expect: lua: attempt to perform arithmetic on a nil value \(local 'depth'\).*traceback:.*runtime_error_in_function.lua:6: in function 'overburden'.*runtime_error_in_function.lua:9: in main chunk
block{ x = {0, 10}, y = {0, 10} }
local function overburden(depth)
  -- depth is nil when called without an argument
  return 2650 * 9.81 * depth
end

print(overburden())
