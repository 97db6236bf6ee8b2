-- line: 3
-- expect: joint_material: kn_table stage 3: closures must increase, got 0\.0001 after 0\.0002
joint_material{ "staged", kn_table = {{0, 1e9}, {2e-4, 5e9}, {1e-4, 2e9}}, ks = 1e10 }
