-- line: 11
-- expect: prepass: the model has [0-9]+ blocks with joints between them, and joints as interface elements are not built yet; joints = false
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 30, spacing = 4 }
zone{ edge = 1 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint" }
boundary{ side = "bottom", fix = "xy" }
local pre = prepass{}
