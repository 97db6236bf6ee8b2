-- A block 1e-300 m wide hung in mesh refinement (1e-9 to 1e-100 m were refused after 6 to 78 s
-- and 1 GB); it is refused at once for what it is.
-- line: 5
-- expect: block is 1e-300 m wide .*thinner than the model's geometric tolerance
block{ x = {0, 1e-300}, y = {0, 1} }
zone{ edge = 0.5 }
