-- line: 10
-- expect: judge: the criterion must return nil, "shear" or "tension", got 1 \(while cycle\(\) at judge_criterion_bad_return.lua:14 was running\)
block{ x = {0, 2}, y = {0, 2} }
crackseed{ angle = 30, spacing = 0.5 }
zone{ edge = 0.25 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint" }
judge{ every = 5, criterion = function(s)
  return 1
end }
boundary{ side = "bottom", fix = "xy" }
cycle(10)
