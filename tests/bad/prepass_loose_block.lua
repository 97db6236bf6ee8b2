-- line: 14
-- expect: prepass: present state: no equilibrium found beyond load factor 0 \(
-- A block on a 40 degree joint with 30 degrees of friction slides: there is no static equilibrium
-- to find, and the prepass says so instead of returning one.
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 40, spacing = 20, origin = {5, 5} }
zone{ edge = 1 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -10 }
prepass{ steps = 2 }
