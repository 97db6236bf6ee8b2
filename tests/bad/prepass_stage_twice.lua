-- line: 9
-- expect: prepass: stage 2, heading: no rock left there to excavate
block{ x = {0, 10}, y = {0, 10} }
region{ name = "heading", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
prepass{ stages = { "heading", "heading" } }
