-- line: 7
-- expect: jassign: unknown joint material 'joints' \(did you mean 'joint'\?\)
block{ x = {0, 10}, y = {0, 10} }
jset{ angle = 45, spacing = 4 }
zone{ edge = 2 }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joints" }
