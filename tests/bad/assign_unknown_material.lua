-- line: 6
-- expect: assign: unknown material 'rok' \(did you mean 'rock'\?\)
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
assign{ material = "rok" }
