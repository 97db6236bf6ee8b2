-- line: 4
-- expect: bolt_material: failure_strain must be > 0, got -0.1
block{ x = {0, 10}, y = {0, 10} }
bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = -0.1,
               bond_stiffness = 50e6, bond_strength = 0.2e6 }
