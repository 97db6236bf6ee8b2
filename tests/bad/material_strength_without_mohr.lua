-- line: 4
-- expect: material: cohesion, friction need model = "mohr" or "ss" \(this material.s model is "elastic"\)
-- model = "mohr" forgotten: the strength would be silently unused
material{ "rock", young = 10e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
