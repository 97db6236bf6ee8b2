-- line: 10
-- expect: crackseed: auto: the prepass excavated nothing, so there is no opening to take a tenth of; give spacing
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "y" }
gravity{ 0, -9.81 }
local pre = prepass{}
crackseed{ auto = pre }
