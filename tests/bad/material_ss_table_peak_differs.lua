-- line: 4
-- expect: material: cohesion_table starts at 2000000 \(e_ps = 0\), but cohesion is 1000000: give cohesion = 2000000, the peak value
-- the table's value at e_ps = 0 is the peak: it must be the cohesion given
material{ "rock", model = "ss", young = 10e9, poisson = 0.25, cohesion = 1e6, friction = 35,
          cohesion_table = { { 0, 2e6 }, { 0.01, 0.2e6 } } }
