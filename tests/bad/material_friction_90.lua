-- line: 3
-- expect: material: friction must be in \[0, 90\), got 90
material{ "rock", model = "mohr", young = 10e9, poisson = 0.25,
          cohesion = 1e6, friction = 90 }
