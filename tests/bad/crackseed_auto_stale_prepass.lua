-- line: 11
-- expect: crackseed: auto: the prepass result has zone [0-9]+ at \(.*\), the model at \(.*\): the geometry changed after prepass\{\}; run prepass\{\} again
block{ x = {0, 10}, y = {0, 10} }
region{ name = "heading", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "y" }
local pre = prepass{ stages = { "heading" } }
zone{ edge = 0.7 }  -- new zones: the result no longer fits
crackseed{ auto = pre }
