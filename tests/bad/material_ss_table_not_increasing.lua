-- line: 3
-- expect: material: friction_table point 3: e_ps must increase, got 0\.01 after 0\.02
material{ "rock", model = "ss", young = 10e9, poisson = 0.25, cohesion = 1e6, friction = 35,
          friction_table = { { 0, 35 }, { 0.02, 30 }, { 0.01, 28 } } }
