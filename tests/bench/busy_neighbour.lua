-- The model of busy_neighbour.sh: two jointed blocks settling under gravity, 12,000 zones,
-- about 6 s of cycling on two threads of an idle two-core machine.
local s = settings{ edge = 0.04, cycles = 30000 }
block{ x = {0, 2}, y = {-1, 0} }
block{ x = {0, 2}, y = {0, 1} }
jset{ angle = 60, spacing = 0.5 }
zone{ edge = s.edge }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "j", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "j" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
cycle(s.cycles)
print(("zones %d, contacts %d, threads at the end %s"):format(info().zones, info().contacts, tostring(info().threads)))
