-- line: 12
-- expect: every: error in the callback \(while cycle\(\) at error_in_every_callback.lua:18 was running\): attempt to index a nil value \(local .gp.\).*traceback:.*:12: in function .roof_sag.*:16: in function <.*:15>.*:18: in main chunk
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
local watched = {}  -- never filled in
local function roof_sag()
  local gp = watched.roof
  return gp.uy
end

every(10, function()
  print(roof_sag())
end)
cycle(100)
