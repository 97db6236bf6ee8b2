-- line: 11
-- expect: judge: error in the criterion \(while cycle\(\) at judge_section_read_only.lua:14 was running\): a section is read-only \(field 's1'\)
block{ x = {0, 2}, y = {0, 2} }
crackseed{ angle = 30, spacing = 0.5 }
zone{ edge = 0.25 }
material{ "rock", model = "mohr", young = 1e9, poisson = 0.25, cohesion = 1e6, friction = 30 }
assign{ material = "rock" }
joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "joint" }
judge{ every = 5, criterion = function(s)
  s.s1 = 0
end }
boundary{ side = "bottom", fix = "xy" }
cycle(10)
