-- line: 10
-- expect: crackseed: auto places its own cuts: leave out angle and angles
block{ x = {0, 10}, y = {0, 10} }
region{ name = "heading", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "y" }
local pre = prepass{ stages = { "heading" } }
crackseed{ auto = pre, angles = { 30, 120 } }
