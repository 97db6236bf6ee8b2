-- line: 11
-- expect: judge: error in the criterion \(while cycle\(\) at judge_criterion_error.lua:15 was running\): .*nil value
block{ x = {0, 2}, y = {0, 2} }
crackseed{ angle = 30, spacing = 0.5 }
zone{ edge = 0.25 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint" }
judge{ every = 5, criterion = function(s)
  return s.no_such_field + 1
end }
boundary{ side = "bottom", fix = "xy" }
-- nothing
cycle(10)
