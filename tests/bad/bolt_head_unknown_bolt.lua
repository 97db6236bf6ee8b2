-- line: 11
-- expect: bolt_head: there is no bolt 2 \(1 laid so far\)
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
               bond_stiffness = 50e6, bond_strength = 0.2e6 }
bolt{ from = {1, 5}, to = {3, 5}, segments = 2, material = "rebar" }
bolt_head{ bolt = 2, velocity = 1e-6 }
