-- A run that exercises every pass of the cycle (Mohr-Coulomb zones that yield, gravity,
-- stress and fixed boundaries, adaptive damping, glued blocks; then the mixed discretisation;
-- then contacts between jointed blocks; then potential cracks judged at equilibrium)
-- and prints a checksum of the state after each part: every displacement, velocity and stress,
-- as exact hexadecimal floats.
-- tests/threads/compare.cmake runs it with --threads 1 and --threads 2; the sums must agree.
local shapes = require "edem.shapes"

block{ x = { 0, 40 }, y = { 0, 30 } }
region{ name = "ring", polygon = shapes.circle{ centre = { 20, 15 }, radius = 6, segments = 48 } }
region{ name = "hole", polygon = shapes.circle{ centre = { 20, 15 }, radius = 3, segments = 48 } }
zone{ edge = 0.4, far = 1.5, near = { "ring" } }
material{ "rock", model = "mohr", density = 2500, young = 2e9, poisson = 0.25,
          cohesion = 0.4e6, friction = 30, dilation = 5, tension = 0.1e6 }
material{ "void", model = "null" }
assign{ material = "rock" }
assign{ material = "void", region = "hole" }
insitu{ surface = 130, density = 2500, k0 = 0.8 }
gravity{ 0, -9.81 }
boundary{ side = "left", fix = "x" }
boundary{ side = "right", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", stress = "insitu" }
-- FNV-1a over the text of every value.
local hash = 0xcbf29ce484222325  -- hexadecimal literals wrap: integer arithmetic modulo 2^64
local function add(value)
  for i = 1, #value do hash = (hash ~ value:byte(i)) * 1099511628211 end
end
local function add_state()
  for p in gridpoints() do add(("%a %a %a %a"):format(p.ux, p.uy, p.vx, p.vy)) end
  local yielded = 0
  for z in zones() do
    add(("%a %a %a %a"):format(z.sxx, z.syy, z.sxy, z.szz))
    if z.state ~= "elastic" then yielded = yielded + 1 end
  end
  return yielded
end

cycle(400)
local plain = add_state()
set{ mixed = true }
cycle(300)
local mixed = add_state()
print(("zones %d, yielded %d, then %d with the mixed discretisation"):format(info().zones, plain, mixed))

-- Contacts: jointed blocks in their in-situ state, the right side let go, so that blocks there
-- move out, slip, open and are found again; every contact's forces and displacements go in.
model{ title = "jointed" }
block{ x = { 0, 40 }, y = { 0, 30 } }
jset{ angle = 60, spacing = 3 }
jset{ angle = -30, spacing = 4 }
zone{ edge = 0.6 }
material{ "rock", density = 2500, young = 2e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "joint", kn = 2e9, ks = 1e9, friction = 25, cohesion = 2e4, tension = 1e4, dilation = 5 }
jassign{ material = "joint" }
gravity{ 0, -9.81 }
insitu{ surface = 130, density = 2500, k0 = 0.8 }
boundary{ side = "left", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", stress = "insitu" }
cycle(400)
add_state()
local sliding = 0
for c in contacts() do
  add(("%a %a %a %a %a %s"):format(c.fn, c.fs, c.un, c.us, c.slip, c.state))
  if c.state == "slip" then sliding = sliding + 1 end
end
print(("zones %d, contacts %d, slipping %d"):format(info().zones, info().contacts, sliding))

-- Potential cracks judged at equilibrium: a hole dug at once in weak rock, judged in rounds until
-- none breaks; every crack (where, how, when) and the state go in.
model{ title = "cracks at equilibrium" }
block{ x = { 0, 40 }, y = { 0, 30 } }
region{ name = "hole", polygon = shapes.circle{ centre = { 20, 15 }, radius = 3, segments = 32 } }
region{ name = "ring", polygon = shapes.circle{ centre = { 20, 15 }, radius = 7, segments = 32 } }
crackseed{ region = "ring", angles = { 30, 120 }, spacing = 1, material = "strength", after = "crack" }
zone{ edge = 0.5, far = 2, near = { "ring" } }
material{ "rock", density = 2500, young = 2e9, poisson = 0.25 }
material{ "strength", model = "mohr", young = 2e9, poisson = 0.25, cohesion = 1e6, friction = 30,
          tension = 0.3e6 }
assign{ material = "rock" }
joint_material{ "crack", kn = 2e10, ks = 1e10, friction = 30 }
insitu{ sxx = -3e6, syy = -5e6, szz = -4e6 }
for _, side in ipairs{ "left", "right", "top", "bottom" } do boundary{ side = side, fix = "xy" } end
judge{ at = "equilibrium" }
excavate{ region = "hole" }
local judged = solve{ ratio = 1e-5, max_cycles = 20000 }
add_state()
for c in cracks() do add(("%a %a %s %d"):format(c.x, c.y, c.mode, c.cycle)) end
print(("sections %d, cracks %d in %d judgments at equilibrium"):format(info().sections, info().cracks,
                                                                      judged.judgments))
print(("checksum %016x"):format(hash))
