-- line: 3
-- expect: material: cohesion_table\[1\] must be a pair of numbers \{a, b\}, got 0
material{ "rock", model = "ss", young = 10e9, poisson = 0.25, cohesion = 1e6, friction = 35,
          cohesion_table = { 0, 1e6, 0.01, 0.2e6 } }
