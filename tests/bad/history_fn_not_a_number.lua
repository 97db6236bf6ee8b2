-- line: 9
-- expect: history: fn of history .sag. must return a number, got nil \(while solve\(\) at history_fn_not_a_number.lua:13 was running\)
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
history{ name = "sag", fn = function()
  local gp = gp_near(5, 10)
  if gp.uy < -1 then return gp.uy end -- forgets the other case
end }
solve()
