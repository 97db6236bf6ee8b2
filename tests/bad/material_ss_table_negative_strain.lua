-- line: 3
-- expect: material: cohesion_table point 1: e_ps must be >= 0, got -0\.01
material{ "rock", model = "ss", young = 10e9, poisson = 0.25, cohesion = 1e6, friction = 35,
          cohesion_table = { { -0.01, 1e6 }, { 0.01, 0.2e6 } } }
