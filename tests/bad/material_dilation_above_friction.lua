-- line: 3
-- expect: material: dilation must be <= friction \(30\), got 35
material{ "rock", model = "mohr", young = 10e9, poisson = 0.25,
          cohesion = 1e6, friction = 30, dilation = 35 }
