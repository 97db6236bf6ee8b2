-- line: 11
-- expect: prepass: joint material 'seed' has a nonlinear normal law: the prepass's interface elements take a constant kn only
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30, spacing = 4 }
zone{ edge = 1 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
joint_material{ "seed", kn_law = "seed-cubic", ks = 8.07e7, friction = 31.2 }
jassign{ material = "seed" }
boundary{ side = "bottom", fix = "xy" }
local pre = prepass{}
