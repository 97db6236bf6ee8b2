-- line: 7
-- expect: jassign: set 3 does not exist: the model has 1 joint set
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 45, spacing = 4 }
zone{ edge = 2 }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint", set = 3 }
