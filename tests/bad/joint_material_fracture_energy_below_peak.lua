-- line: 4
-- expect: joint_material: fracture_energy must be more than tension\^2 / \(2 kn\) = 0.5 J/m\^2 \(the elastic energy at the peak\), got 0.4
-- A softening bond needs more energy than it stores elastically at its peak (joint_law.hpp).
joint_material{ "crack", kn = 1e10, ks = 1e10, friction = 30, tension = 1e5,
                fracture_energy = 0.4 }
