-- line: 9
-- expect: every: error in the callback \(while solve\(\) at cycle_inside_callback.lua:10 was running\): cycle: cannot cycle inside a callback while solve\(\) at cycle_inside_callback.lua:10 is cycling
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
every(10, function() cycle(5) end)
solve()
