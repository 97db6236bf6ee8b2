-- line: 9
-- expect: chart: no history named 'roof' \(histories: sag\)
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
material{ "rock", density = 2000, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
history{ name = "sag", unit = "m", fn = function() return 0 end }
cycle(10)
chart{ file = "roof.png", history = "roof" }
