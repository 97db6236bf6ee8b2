-- line: 3
-- expect: material: poisson must be in \(-1, 0\.5\), got 0\.5
material{ "rock", young = 10e9, poisson = 0.5 }
