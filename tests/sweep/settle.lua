-- A block settling on a fixed base under gravity: the model of the sweep tests, a second or two
-- a run; its result depends on every setting in its last digits.
local s = settings{ height = 1, density = 2500, cycles = 20000 }
block{ x = {0, 2}, y = {-1, 0} }
block{ x = {0, 2}, y = {0, s.height} }
zone{ edge = 0.25 }
material{ "rock", density = s.density, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "j", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "j" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
cycle(s.cycles)
result{ settlement = gp_near(1, s.height).uy, top = gp_near(0, s.height).ux }
