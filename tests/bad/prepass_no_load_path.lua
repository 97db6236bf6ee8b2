-- line: 10
-- expect: prepass: present state: no equilibrium found beyond load factor 0 \(
-- A block under gravity with no support at all (a mechanism): the load cannot be carried. The
-- prepass says which stage failed instead of returning garbage.
block{ x = {0, 10}, y = {0, 10} }
zone{ edge = 2 }
material{ "rock", density = 2000, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
gravity{ 0, -10 }
prepass{}
