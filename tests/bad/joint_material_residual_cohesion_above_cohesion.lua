-- line: 3
-- expect: joint_material: residual_cohesion must be at most cohesion = 100000, got 200000
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30, cohesion = 1e5,
                residual_cohesion = 2e5 }
