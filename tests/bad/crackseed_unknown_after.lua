-- line: 10
-- expect: cycle: unknown joint material 'jiont'
block{ x = {0, 2}, y = {0, 2} }
crackseed{ angle = 30, spacing = 0.5, after = "jiont" }
zone{ edge = 0.25 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
boundary{ side = "bottom", fix = "xy" }
cycle(10)
