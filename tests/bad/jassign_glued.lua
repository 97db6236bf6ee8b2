-- line: 7
-- expect: jassign: glued edges \(region outlines\) join their blocks into one continuum and have no contacts; cut the region with glued = false
block{ x = {0, 10}, y = {0, 10} }
region{ name = "roof", polygon = {{2, 2}, {8, 2}, {8, 8}, {2, 8}} }
zone{ edge = 2 }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint", kind = "glued" }
