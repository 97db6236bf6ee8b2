-- line: 11
-- expect: bolt: the bolt's point \(5, 5\), 1 m from its head, is not in the rock \(outside the model, or in excavated
block{ x = {0, 10}, y = {0, 10} }
region{ name = "stage1", polygon = {{4, 4}, {6, 4}, {6, 6}, {4, 6}} }
zone{ edge = 1 }
material{ "rock", young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
               bond_stiffness = 50e6, bond_strength = 0.2e6 }
excavate("stage1")
bolt{ from = {4, 5}, to = {6, 5}, segments = 2, material = "rebar" }
