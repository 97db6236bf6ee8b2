-- line: 3
-- expect: material: model must be one of elastic, mohr, null, ss, got "mohr_coulomb"
material{ "rock", model = "mohr_coulomb", young = 10e9, poisson = 0.25 }
