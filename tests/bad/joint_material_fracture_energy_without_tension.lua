-- line: 3
-- expect: joint_material: fracture_energy = 20 needs a tension > 0 to soften from
joint_material{ "crack", kn = 1e10, ks = 1e10, friction = 30, cohesion = 1e5, fracture_energy = 20 }
