-- Two threads on one core: the thread watch must notice that they wait for each other, go on
-- with one, and change nothing but the speed. tests/threads/crowded.sh runs it pinned to one core
-- with --threads 2, and with --threads 1; the checksums must agree.
block{ x = { 0, 20 }, y = { 0, 15 } }
jset{ angle = 60, spacing = 3 }
jset{ angle = -30, spacing = 4 }
zone{ edge = 1 }
material{ "rock", density = 2500, young = 2e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "joint", kn = 2e9, ks = 1e9, friction = 25, cohesion = 2e4, tension = 1e4, dilation = 5 }
jassign{ material = "joint" }
gravity{ 0, -9.81 }
insitu{ surface = 115, density = 2500, k0 = 0.8 }
boundary{ side = "left", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", stress = "insitu" }
local asked = info().threads
cycle(8000)
local hash = 0xcbf29ce484222325
local function add(value)
  for i = 1, #value do hash = (hash ~ value:byte(i)) * 1099511628211 end
end
for p in gridpoints() do add(("%a %a %a %a"):format(p.ux, p.uy, p.vx, p.vy)) end
for z in zones() do add(("%a %a %a %a"):format(z.sxx, z.syy, z.sxy, z.szz)) end
for c in contacts() do add(("%a %a %a %a %a %s"):format(c.fn, c.fs, c.un, c.us, c.slip, c.state)) end
print(("zones %d, contacts %d; threads asked %d, used at the end %d"):format(info().zones, info().contacts, asked, info().threads))
print(("checksum %016x"):format(hash))
