-- line: 8
-- expect: crackseed: by_mode is for auto = a prepass{} result: it says how its groups are formed
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "y" }
crackseed{ angles = { 30, 120 }, spacing = 2, by_mode = true }
