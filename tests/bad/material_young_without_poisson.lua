-- line: 3
-- expect: material: young needs poisson too \(or give bulk and shear\)
material{ "rock", density = 2650, young = 10e9 }
