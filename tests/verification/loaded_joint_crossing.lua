-- A block sliding a metre along a loaded joint, past a joint crossing it:
-- contacts made during the slide carry the joint's stress at once.
--
-- A 6 m x 1 m block (x from -4 to 2) on a base 16 m x 3 m cut in two by a vertical joint at
-- x = 0, all joints with the seed's consistent stiffness (Set P: kn = 84 MPa/m, ks = 3.6 MPa/m,
-- friction 31.2 deg), the rock in an in-situ stress of 3 MPa both ways (the joints' closure,
-- 3.6 cm, is given as their prestress). The block's top is held in y and pushed along x by 1 m;
-- its ends carry the in-situ stress. Its gridpoints slide off the left base block onto the right
-- one, and the right one's come under its leading end: each new contact takes the state of the
-- faces already pressed together there (closure at zero gap and shear traction), so the joint's
-- normal stress is the applied 3 MPa all along, as its equilibrium needs (the held top keeps the
-- block from tilting). Made with nothing, they would carry 0.05 to 0.1 MPa until sunk in by the
-- joint's closure, while the rest of the joint carried their share.
-- Checks, every 0.1 m of the slide: every pressed contact along the joint within 10 % of 3 MPa;
-- no contact deeper than 1.5 sigma_n / kn into its face beyond its prestress (the sinking a
-- contact made with nothing would need); and the energy balance within 1 % of its largest term
-- (the shear scaled with a contact's length when its length is found again, so that its stress,
-- not its force, carries over); and no contact's length jumping in 100 cycles by much more than
-- the slide between two detections gives (a half-edge over both base blocks is shared by them).
local check = require "edem.check"

local sn, kn, ks = 3e6, 84e6, 3.6e6
model{ title = "a block sliding past a joint crossing" }
block{ x = {-8, 8}, y = {-3, 0} }
block{ x = {-4, 2}, y = {0, 1} }
crack{ from = {0, -3}, to = {0, 0} }
zone{ edge = 0.25 }
material{ "rock", density = 2700, young = 7.4e9, poisson = 0.14 }
assign{ material = "rock" }
joint_material{ "j", kn = kn, ks = ks, friction = 31.2 }
jassign{ material = "j" }
insitu{ sxx = -sn, syy = -sn }
boundary{ side = "bottom", fix = "xy" }
boundary{ polygon = {{-8.1, -3.1}, {-7.9, -3.1}, {-7.9, 0.1}, {-8.1, 0.1}}, fix = "x" }
boundary{ polygon = {{7.9, -3.1}, {8.1, -3.1}, {8.1, 0.1}, {7.9, 0.1}}, fix = "x" }
local top = {{-4.1, 0.9}, {2.1, 0.9}, {2.1, 1.1}, {-4.1, 1.1}}
boundary{ polygon = top, fix = "y" }
boundary{ polygon = {{-4.1, 0.05}, {-3.9, 0.05}, {-3.9, 0.95}, {-4.1, 0.95}}, stress = {-sn, -sn, 0} }
boundary{ polygon = {{1.9, 0.05}, {2.1, 0.05}, {2.1, 0.95}, {1.9, 0.95}}, stress = {-sn, -sn, 0} }
solve{ ratio = 1e-7 }
energy{ reset = true }

-- The pressed contacts along the sliding joint: the smallest and largest normal stress [Pa], the
-- deepest overlap [m].
local function along_joint()
  local low, high, deepest = math.huge, 0, 0
  for c in contacts() do
    if math.abs(c.y) < 0.2 and math.abs(c.normal.y) > 0.9 and c.state ~= "open" then
      low, high = math.min(low, -c.sn), math.max(high, -c.sn)
      deepest = math.max(deepest, c.overlap)
    end
  end
  return low, high, deepest
end

-- How far the block's base has moved [m]: the mean of its gridpoints on the joint.
local function base_moved()
  local sum, count = 0, 0
  for g in gridpoints() do
    if g.block == 3 and g.y < 0.01 then sum, count = sum + g.ux, count + 1 end
  end
  return sum / count
end

-- The block's boundary edges along the joint are 0.125 m long (zone{} halves them there): a
-- gridpoint's half-edge, this side's half of it, is what one contact's length gains or loses
-- when a half-edge passes from one base block to the other [m].
local edge = 0.125
local half_edge_share = 0.5 * 0.5 * edge

-- The sliding block's contacts with the base, by the base block and the gridpoint's place on the
-- block (its x less how far the base has moved, in edges): their lengths [m].
local function base_contact_lengths(moved)
  local lengths = {}
  for c in contacts() do
    if c.block == 3 and c.other ~= 3 and math.abs(c.y) < 0.2 then
      lengths[("%d:%d"):format(c.other, math.floor((c.x - moved) / edge + 0.5))] = c.length
    end
  end
  return lengths
end

local worst, deepest_all, start = 0, 0, base_moved()
local largest_step, lengths = 0, nil
boundary{ polygon = top, xvel = 2e-5 }  -- m per cycle in static mode
for step = 1, 10 do
  for _ = 1, 50 do
    cycle(100)
    -- (From the first 100 cycles on: a contact's length as listed is that of its last cycle.)
    local now = base_contact_lengths(base_moved() - start)
    for key, length in pairs(lengths and now or {}) do
      largest_step = math.max(largest_step, math.abs(length - (lengths[key] or 0)))
    end
    for key, length in pairs(lengths or {}) do
      if not now[key] then largest_step = math.max(largest_step, length) end
    end
    lengths = now
  end
  local low, high, deepest = along_joint()
  print(("  base moved %.3f m: normal stress %.3f to %.3f MPa, deepest %.2f mm"):format(
    base_moved() - start, low / 1e6, high / 1e6, deepest * 1e3))
  worst = math.max(worst, math.abs(low / sn - 1), math.abs(high / sn - 1))
  deepest_all = math.max(deepest_all, deepest)
end
local e = energy()
print(("  energy: boundary %.4g, slip %.4g, stored %.4g, prestress %.4g J/m; error %.3g"):format(
  e.boundary, e.slip, e.kinetic + e.strain + e.contact, e.prestress, e.error))
check.report("the block's base moved [m]", base_moved() - start, 1.0, 0.02)
check.report("largest departure of the joint's normal stress from 3 MPa", worst, 0, 0.10, { absolute = true })
check.report("deepest overlap / (1.5 sigma_n / kn)", deepest_all / (1.5 * sn / kn), 0, 1, { absolute = true })
-- A half-edge passing the crossing goes from one base block to the other as it goes over, not at
-- one detection: a contact's length moves with the slide between two detections (about a fifth
-- of a half-edge), not by the part of a half-edge over the other block (about half a share,
-- given over at once).
check.report("largest change of a contact's length in 100 cycles / a half-edge's share", largest_step / half_edge_share,
             0, 0.4, { absolute = true })
check.report("energy balance: |error| / largest term", math.abs(e.relative_error), 0, 0.01, { absolute = true })
check.finish()
