-- edem.args: reading a stdlib function's table of named keys, for edem.cavern and edem.bolts.
--
--   local args = require "edem.args"
--   local o = args.read("cavern", "warhead", t, { { "width", "positive", 24 }, { "split", { "a", "b" } } })
--
-- args.read(module, fn, t, spec, kinds): t is the caller's table (nil: {}); spec a list of
-- { key, kind, default }, the kind a name in args.kinds (or in `kinds`, the module's own) or a
-- list of allowed strings. Returns a table of the values, the defaults filled in (nil when none).
-- An unknown key or a wrong value raises "module.fn: key = value: must be ...", blamed on the
-- line that called module.fn: the public function must call args.read itself, or through tail
-- calls only, so that the caller is the third frame up.
local args = {}

-- A value as messages show it: strings quoted, numbers to 10 digits, short lists spelt out.
function args.show(v, depth)
  if type(v) == "string" then return ("%q"):format(v) end
  if type(v) == "number" then return ("%.10g"):format(v) end
  if type(v) == "table" and (depth or 0) < 2 and #v <= 4 then  -- a point, a short list
    local items = {}
    for i, x in ipairs(v) do items[i] = args.show(x, (depth or 0) + 1) end
    local more = next(v, #v > 0 and #v or nil) ~= nil
    return "{" .. table.concat(items, ", ") .. (more and (#v > 0 and ", ...}" or "...}") or "}")
  end
  return tostring(v)
end

function args.finite(v)
  return type(v) == "number" and v == v and v > -math.huge and v < math.huge
end

local finite = args.finite

-- {x, y} or {x =, y =}, as a fresh {x, y}; nil if it is not one.
function args.point(v)
  if type(v) ~= "table" then return nil end
  local x, y = v[1], v[2]
  if x == nil and y == nil then x, y = v.x, v.y end
  return finite(x) and finite(y) and { x, y } or nil
end

args.kinds = {
  positive = { says = "a number > 0", read = function(v) return finite(v) and v > 0 and v or nil end },
  nonnegative = { says = "a number >= 0", read = function(v) return finite(v) and v >= 0 and v or nil end },
  count = { says = "an integer >= 1",
            read = function(v) return finite(v) and v >= 1 and v < 2 ^ 31 and math.tointeger(v) or nil end },
  point = { says = "a point {x, y}", read = args.point },
  name = { says = "a non-empty string",
           read = function(v) return type(v) == "string" and v ~= "" and v or nil end },
}

function args.read(module, fn, t, spec, kinds)
  local show = args.show
  if t == nil then t = {} end
  if type(t) ~= "table" then
    error(("%s.%s: takes a table of named keys, got %s"):format(module, fn, show(t)), 3)
  end
  local known, keys = {}, {}
  for _, s in ipairs(spec) do known[s[1]] = true; keys[#keys + 1] = s[1] end
  for k in pairs(t) do
    if not known[k] then
      error(("%s.%s: unknown key %s (keys: %s)"):format(module, fn, show(k), table.concat(keys, ", ")), 3)
    end
  end
  local o = {}
  for _, s in ipairs(spec) do
    local key, kind, v = s[1], s[2], t[s[1]]
    if v == nil then
      o[key] = s[3]
    elseif type(kind) == "table" then
      for _, allowed in ipairs(kind) do if v == allowed then o[key] = v end end
      if o[key] == nil then
        error(("%s.%s: %s = %s: must be one of \"%s\""):format(module, fn, key, show(v),
          table.concat(kind, "\", \"")), 3)
      end
    else
      local k = (kinds and kinds[kind]) or args.kinds[kind]
      o[key] = k.read(v)
      if o[key] == nil then
        error(("%s.%s: %s = %s: must be %s"):format(module, fn, key, show(v), k.says), 3)
      end
    end
  end
  return o
end

return args
