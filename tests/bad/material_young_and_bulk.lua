-- line: 3
-- expect: material: give young and poisson, or bulk and shear, not both pairs
material{ "rock", young = 10e9, poisson = 0.25, bulk = 6e9, shear = 4e9 }
