-- line: 13
-- expect: cycle: cycle [0-9]+: overlap too great: the gridpoint at \([-0-9.e]+, [-0-9.e]+\) of block [0-9]+ is [0-9.e-]+ m inside block [0-9]+, more than the limit of [0-9.e-]+ m .*measured cause: joint material 'soft' is too soft for this stress
-- Two blocks pressed together by 10 MPa through a joint of 1 MPa/m: the joint would close by
-- 10 m, far more than the blocks' zones can show; the run stops and says why.
block{ x = {0, 1}, y = {0, 2} }
jset{ angle = 0, spacing = 10, origin = {0, 1} }
zone{ edge = 0.25 }
material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "soft", kn = 1e6, ks = 1e6, friction = 30 }
jassign{ material = "soft" }
boundary{ side = "bottom", fix = "y" } boundary{ side = "top", stress = {0, -10e6, 0} }
cycle(5000)
