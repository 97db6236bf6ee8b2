-- The energy balance (energy()): the work done on the model against what it stores, dissipates
-- and loses to excavation, as PFC and 3DEC keep it. What is left is energy the method made or
-- lost; it must stay below 1 % of the largest term, in dynamic mode with
-- no damping, where any energy made would show as motion:
--   * a 2 m x 1 m deformable block sliding on a 40 deg slope with friction 20 deg (fast), and on
--     a 30 deg slope with friction 29.9 deg (at the threshold), both from rest after settling
--     with friction 89 deg, for 1 s;
--   * a 2 m x 2 m block settled the same way and then given 30.9 deg on the 30 deg slope, which
--     rocks and slides although a rigid block would stop (see below);
--   * the fast slide again, 0.5 s, with a grouted bolt through the block into the base: sheared
--     where the joint slips, its segments pull across its axis on the rock that hosts them;
--   * a block dropped 0.2 m onto a base, bouncing (contacts made, pressed and lost);
--   * a P wave crossing a joint: a 20 m bar cut by a joint at mid-length, a velocity pulse at one
--     end, until the wave has crossed (boundary work, zones and joint springs);
--   * a circular hole excavated at once in dynamic mode from a plate under in-situ stress: the
--     rock dug out takes its strain energy away and the wall rings.
-- The balance's terms are printed for each; the settling before a dynamic run is left out
-- (energy{ reset = true }).
--
-- The tall block slides about 5 cm in 1 s with its friction a degree above the slope, where a
-- rigid block decelerates at once. The balance closes: the energy comes from gravity, not from
-- the method. Dropping the friction releases the shear locked in at the heel and toe and sets the
-- block rocking and bouncing on its stiff joint (its contacts all open now and then); with no
-- damping the vibration never decays, and a block whose normal force swings by more than
-- 1 - tan(theta) / tan(phi) (3 % here) slips while it is low and sticks while it is high, so it
-- ratchets down the slope, gravity paying for the slip and for the vibration's growth. Settled at
-- its own friction, with nothing released, it stays put (sliding_block.lua).
local check = require "edem.check"

local function balance(label, tolerance)
  local e = energy()
  print(("%s: kinetic %.4g, strain %.4g, contact %.4g | gravity %.4g, boundary %.4g, release %.4g, "
         .. "prestress %.4g, commands %.4g | excavated %.4g | slip %.4g, plastic %.4g, bond %.4g, damping %.4g, "
         .. "bolts %.4g, stored in bolts %.4g [J/m]; error %.4g (zones %.3g, contacts %.3g, bolts %.3g) of the largest "
         .. "%.4g"):format(
    label, e.kinetic, e.strain, e.contact, e.gravity, e.boundary, e.release, e.prestress, e.commands, e.excavated,
    e.slip, e.plastic, e.bond, e.damping, e.bolt_plastic, e.bolt, e.error, e.zone_error, e.contact_error,
    e.bolt_error, e.largest))
  check.report(label .. ": |error| / largest term", math.abs(e.relative_error), 0, tolerance or 0.01,
               { absolute = true })
  return e
end

-- A block of width 2 m on a base, gravity tilted by theta, settled with friction 89 deg and run
-- for `seconds` with friction phi, undamped. Returns the slide of its top centre [m].
local function slope(theta, phi, height, seconds, bolted)
  local g, width = 9.81, 2.0
  model{ title = ("block %g m high, slope %g, phi %g"):format(height, theta, phi) }
  block{ x = {-3, 8}, y = {-1, 0} }
  block{ x = {-width / 2, width / 2}, y = {0, height} }
  zone{ edge = 0.5, far = 0.5 }
  material{ "rock", density = 2650, young = 10e9, poisson = 0.25 }
  assign{ material = "rock" }
  joint_material{ "plane", kn = 1e10, ks = 1e10, friction = 89 }
  jassign{ material = "plane" }
  boundary{ polygon = {{-3.1, -1.1}, {8.1, -1.1}, {8.1, -0.01}, {-3.1, -0.01}}, fix = "xy" }
  gravity{ g * math.sin(math.rad(theta)), -g * math.cos(math.rad(theta)) }
  solve{ ratio = 1e-9, max_cycles = 20000 }
  if bolted then  -- grouted through the block into the base, across the joint it slides on
    bolt_material{ "bolt", young = 200e9, area = 490e-6, yield_tension = 0.02e6, failure_strain = 0.5,
                   bond_stiffness = 50e6, bond_strength = 0.05e6 }
    bolt{ from = { 0, height - 0.05 }, to = { 0, -0.9 }, segment_length = 0.05, material = "bolt" }
  end
  joint_material{ "plane", kn = 1e10, ks = 1e10, friction = phi }
  set{ mode = "dynamic", damping = "none" }
  reset{ "velocity" }
  energy{ reset = true }
  local start, t0 = gp_near(0, height).ux, info().time
  while info().time - t0 < seconds do cycle(100) end
  return gp_near(0, height).ux - start
end

local slid = slope(40, 20, 1.0, 1.0)
print(("  slid %.4g m in 1 s (rigid block: %.4g m)"):format(slid, 0.5 * 9.81 * (math.sin(math.rad(40)) -
  math.cos(math.rad(40)) * math.tan(math.rad(20)))))
balance("sliding, 40 deg slope, phi 20")
slid = slope(40, 20, 1.0, 0.5, true)
print(("  the bolted block slid %.4g m in 0.5 s, bending its bolt at the joint"):format(slid))
balance("bolted, sliding, 40 deg slope, phi 20")
slid = slope(30, 29.9, 1.0, 1.0)
balance("sliding at the threshold, 30 deg slope, phi 29.9")
slid = slope(30, 30.9, 2.0, 1.0)
print(("  the tall block slid %.3g m in 1 s with phi above the slope angle"):format(slid))
balance("tall block rocking, 30 deg slope, phi 30.9")

-- A 1 m block dropped from 0.2 m above a base onto a joint (kn = ks = 10 GPa/m), bouncing for
-- 0.5 s.
model{ title = "dropped block" }
block{ x = {0, 1}, y = {0, 1} }
block{ x = {0, 1}, y = {1.2, 2.2} }
zone{ edge = 0.25 }
material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "j", kn = 1e10, ks = 1e10, friction = 30 }
jassign{ material = "j" }
boundary{ side = "bottom", fix = "xy" }
gravity{ 0, -9.81 }
set{ mode = "dynamic", damping = "none" }
local landed = 0
while info().time < 0.5 do
  cycle(50)
  if info().contacts > 0 then
    for c in contacts() do if c.state ~= "open" then landed = landed + 1 break end end
  end
end
print(("  pressed on %d of the samples"):format(landed))
check.report("dropped block: it landed", landed > 0 and 1 or 0, 1, 0, { absolute = true })
balance("dropped block, bouncing")

-- A P wave along a bar (20 m x 1 m, rollers top and bottom) cut by a joint at x = 10: the left
-- end is pushed at 0.1 m/s for 1 ms, then held, until the wave has crossed the joint.
model{ title = "P wave across a joint" }
block{ x = {0, 20}, y = {0, 1} }
jset{ angle = 90, spacing = {20}, origin = {10, 0} }
zone{ edge = 0.1 }
material{ "rock", density = 2600, young = 10e9, poisson = 0.25 }
assign{ material = "rock" }
joint_material{ "j", kn = 2e10, ks = 1e10, friction = 30, cohesion = 1e7, tension = 1e7 }
jassign{ material = "j" }
boundary{ side = "top", fix = "y" }
boundary{ side = "bottom", fix = "y" }
set{ mode = "dynamic", damping = "none" }
boundary{ side = "left", xvel = 0.1 }
while info().time < 1e-3 do cycle(10) end
boundary{ side = "left", xvel = 0 }
while info().time < 7e-3 do cycle(50) end  -- P waves at about 2200 m/s: well past the joint
local far = 0
for g in gridpoints() do if g.x > 10.5 then far = math.max(far, math.abs(g.vx)) end end
print(("  largest speed beyond the joint %.3g m/s"):format(far))
check.report("P wave: it crossed the joint (speed beyond it / 0.1 m/s)", far / 0.1, 1, 0.5)
balance("P wave across a joint")

-- A hole of radius 1 m dug at once from a 20 m plate (quarter model) under 30 / 15 MPa.
local shapes = require "edem.shapes"
model{ title = "hole dug in dynamic mode" }
block{ x = {0, 20}, y = {0, 20} }
region{ name = "hole", polygon = shapes.sector{ r1 = 1, from = 0, to = 90, segments = 32 } }
zone{ edge = 0.1, far = 2.0, growth = 0.15, near = { shapes.sector{ r1 = 1, from = 0, to = 90, segments = 32 } } }
material{ "rock", density = 2600, bulk = 3.9e9, shear = 2.8e9 }
assign{ material = "rock" }
insitu{ sxx = -15e6, syy = -30e6, szz = -15e6 }
boundary{ side = "left", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "right", stress = "insitu" }
boundary{ side = "top", stress = "insitu" }
set{ mode = "dynamic", damping = "none" }
cycle(1)
energy{ reset = true }
excavate{ region = "hole" }
while info().time < 5e-3 do cycle(50) end
local dug = balance("hole dug at once, ringing")
check.report("hole: the strain energy dug out is taken away (excavated > 0)", dug.excavated > 0 and 1 or 0, 1, 0,
             { absolute = true })
check.finish()
