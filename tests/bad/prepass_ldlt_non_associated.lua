-- line: 8
-- expect: prepass: solver = "ldlt" needs a symmetric tangent, and material 'rock' flows non-associated
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
boundary{ side = "bottom", fix = "xy" }
prepass{ solver = "ldlt" }
