-- The same for the potential cracks' grid.
-- line: 6
-- expect: origin \(500000, 0\) is 5e\+05 m from the blocks
block{ x = {-10, 10}, y = {-10, 10} }
material{ "strength", model = "mohr", young = 1e9, poisson = 0.2, cohesion = 1e6, friction = 30, tension = 1e5 }
crackseed{ angle = 0, spacing = 1, origin = {5e5, 0}, material = "strength" }
