-- line: 9
-- expect: cycle: crackseed 1: the rock at \([-0-9.e]+, [-0-9.e]+\) is of material 'rock', which has no strength \(elastic\); give crackseed\{ material = \.\.\. \} a material of model "mohr"
block{ x = {0, 2}, y = {0, 2} }
crackseed{ angle = 30, spacing = 0.5 }
zone{ edge = 0.25 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
cycle(10)
