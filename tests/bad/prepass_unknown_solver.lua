-- line: 7
-- expect: prepass: solver must be one of lu, ldlt, klu, umfpack, got "cholmod"
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
prepass{ solver = "cholmod" }
