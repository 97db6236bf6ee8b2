-- line: 4
-- expect: joint_material: stress_scale and closure_scale scale kn_law's curve: give kn_law, or leave them out
-- A similarity scale has nothing to scale without a named law.
joint_material{ "joint", kn = 8.39e7, stress_scale = 17.86, ks = 3.6e6, friction = 31.2 }
