-- line: 3
-- expect: joint_material: kn_law must be one of seed-cubic, got "cubic"
joint_material{ "seed", kn_law = "cubic", ks = 8.07e7, friction = 31.2 }
