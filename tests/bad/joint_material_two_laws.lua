-- line: 3
-- expect: joint_material: give one of kn, kn_table and kn_law, not several
joint_material{ "joint", kn = 1e10, kn_table = {{0, 1e9}, {1e-4, 5e9}}, ks = 1e10 }
