-- A forced dynamic step far above the critical one drives contacts deep into their faces; the
-- overlap watchdog names the step, not the joint material.
-- line: 15
-- expect: measured cause: the forced time step 0.01 s is [0-9.]+ times the critical step
block{ x = {0, 4}, y = {0, 4} }
jset{ angle = 30, spacing = 1.3 }
zone{ edge = 0.5 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "j", kn = 1e9, ks = 1e9, friction = 30 }
jassign{ material = "j" }
gravity{ 0, -9.81 }
boundary{ side = "bottom", fix = "xy" }
set{ mode = "dynamic", step = 0.01 }
cycle(2000)
