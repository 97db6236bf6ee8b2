-- line: 3
-- expect: joint_material: friction must be in \[0, 90\), got 90
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 90 }
