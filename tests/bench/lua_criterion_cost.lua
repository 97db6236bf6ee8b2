-- What a Lua crack criterion costs per judged section (tests/bench/RESULTS.md, issue 5).
-- Run: cd stdlib && ../build/interp/edem ../tests/bench/lua_criterion_cost.lua
local function crit(s)
  if s.s3 > s.tension then return "tension" end
  local sp = math.sin(math.rad(s.friction))
  if (1 - sp) * s.s1 - (1 + sp) * s.s3 + 2 * s.cohesion * math.cos(math.rad(s.friction)) < 0 then return "shear" end
end
local function run(every, criterion)
  model{}
  block{ x = {0, 4}, y = {0, 4} }
  crackseed{ angles = {0, 90}, spacing = 0.2, origin = {0.1, 0.1} }
  zone{ edge = 0.1 }
  material{ "rock", model = "mohr", young = 10e9, poisson = 0.25, density = 2600, cohesion = 1e9, friction = 30, tension = 1e9 }
  assign{ material = "rock" }
  joint_material{ "j", kn = 1e11, ks = 1e11, friction = 30 }
  jassign{ material = "j" }
  judge{ every = every, criterion = criterion }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "top", yvel = -1e-9 }
  cycle(10)
  local t = os.clock()
  cycle(2000)
  return os.clock() - t
end
local none = run(100000)
local builtin = run(10)
local lua = run(10, crit)
local z, s = info().zones, info().sections
print(("zones %d sections %d: no judging %.3f s, built-in every 10 %.3f s, Lua every 10 %.3f s"):format(z, s, none, builtin, lua))
print(("per section judged: built-in %.3g us, Lua %.3g us; per zone-cycle %.3g us"):format(
  (builtin - none) / (200 * s) * 1e6, (lua - none) / (200 * s) * 1e6, none / (2000 * z) * 1e6))
