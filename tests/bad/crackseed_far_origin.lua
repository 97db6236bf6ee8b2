-- The same for the potential cracks' grid.
-- line: 6
-- expect: origin \(9e\+06, 0\) is 9e\+06 m from the blocks, 1.8e\+07 spacings
block{ x = {-10, 10}, y = {-10, 10} }
material{ "strength", model = "mohr", young = 1e9, poisson = 0.2, cohesion = 1e6, friction = 30, tension = 1e5 }
crackseed{ angle = 0, spacing = 0.5, origin = {9e6, 0}, material = "strength" }
