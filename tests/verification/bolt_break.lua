-- A bolt across an opening joint, strained past its failure strain: it yields, breaks, and then
-- carries nothing, in tension or in compression (the law: engine/bolt/bolt_law.hpp).
--
-- Two blocks of rock 1 m long, 0.5 m high, with a joint between them at x = 1 that has no tensile
-- strength. A 1.8 m bolt lies across it along y = 0 (segments 0.05 m long, the one across the
-- joint from x = 0.975 to 1.025), grouted all along: E = 200 GPa, A = 490 mm^2, F_y = 0.156 MN,
-- failure strain 3.5 %, k_b = 50 MN/m/m, s_b = 0.2 MN/m, one per metre of thickness. The left
-- block's left side is held; the right block's right side is pulled to the right slowly, so the
-- joint opens and only the bolt holds the blocks together.
-- Expected:
--   * the bolt's force at the joint rises to F_y and no grout slips to its end (the bond on each
--     side, 0.2 MN/m x 0.875 m = 0.175 MN, could take more, so the steel yields at the joint
--     instead of pulling out);
--   * the segment across the joint yields and, once its strain passes 3.5 %, breaks: its force is
--     exactly 0 from then on, and, held still and solved, the right side's reaction is what the
--     open joint carries, nothing (below 1e-6 F_y). (While the block moves, static mode's
--     damping drags on it, so reactions are read only once it is held and solved.)
--   * pushed back until the joint closes and is compressed, the broken segment still carries
--     exactly 0 (a broken bolt takes no compression either) and the bolt's pieces add nothing
--     across the joint (the push equals the joint's normal force, within 1e-6).
local check = require "edem.check"

local FY, FAILURE = 0.156e6, 0.035
local SPEED = 1e-7  -- the right side's velocity [m per cycle]: 200 N/m per cycle on a segment

block{ x = { 0, 2 }, y = { -0.25, 0.25 } }
crack{ from = { 1, -1 }, to = { 1, 1 } }
zone{ edge = 0.05 }
material{ "rock", young = 30e9, poisson = 0.25, density = 2600 }
assign{ material = "rock" }
joint_material{ "joint", kn = 20e9, ks = 20e9, friction = 30 }
jassign{ material = "joint" }
boundary{ side = "left", fix = "xy" }
bolt_material{ "bolt", young = 200e9, area = 490e-6, yield_tension = FY, failure_strain = FAILURE,
               bond_stiffness = 50e6, bond_strength = 0.2e6 }
bolt{ from = { 0.125, 0 }, to = { 1.875, 0 }, segment_length = 0.05, material = "bolt" }

local function the_bolt() for b in bolts() do return b end end
local function across(b)  -- the segment across the joint
  for i, s in ipairs(b.segments) do
    if s.a.x < 1 and s.b.x > 1 then return s, i end
  end
end
-- The internal force of the right side's held gridpoints [N/m]: negative when the block is pulled,
-- positive when it is pushed.
local function pull()
  local f = 0
  for g in gridpoints() do
    if g.x > 2 - 1e-9 then f = f + g.fx end
  end
  return f
end

local function opening()
  local un = 0
  for c in contacts() do un = math.max(un, c.un) end
  return un
end

-- Opening: pull the right side in batches, watching the bolt.
boundary{ side = "right", xvel = SPEED }
local peak, broke_at = 0, nil
for batch = 1, 300 do
  cycle(1000)
  local b = the_bolt()
  local s = across(b)
  if not broke_at then peak = math.max(peak, s.force) end
  if s.state == "broken" and not broke_at then
    broke_at = batch
    print(("broke in batch %d: joint opened %.4g m, the bolt's force at the joint before %.6g N/m"):format(
      batch, opening(), peak))
  end
  if broke_at and batch >= broke_at + 10 then break end
end
assert(broke_at, "the bolt did not break")
local b = the_bolt()
local s, index = across(b)
print(("segment %d across the joint: state %s, force %g N/m, strain %.4g"):format(index, s.state, s.force, s.strain))
local end_slip = math.max(math.abs(b.segments[1].plastic_slip), math.abs(b.segments[#b.segments].plastic_slip))
check.report("the bolt's force at the joint before it broke / F_y", peak, FY, 1e-9)
check.report("no plastic slip at the bolt's ends [m]", end_slip, 0, 0, { absolute = true })
check.report("it broke past the failure strain", s.strain > FAILURE and 1 or 0, 1, 0, { absolute = true })
check.report("the broken segment's force", s.force, 0, 0, { absolute = true })
check.report("broken: 1 segment", b.broken, 1, 0, { absolute = true })
-- Held still and solved: no pull left across the open joint.
boundary{ side = "right", xvel = 0 }
solve{ ratio = 1e-8 }
check.report("pull after the break / F_y", math.abs(pull()) / FY, 0, 1e-6, { absolute = true })
check.report("the broken segment's force, held", across(the_bolt()).force, 0, 0, { absolute = true })

-- Closing: push the right block back until the joint is compressed.
boundary{ side = "right", xvel = -SPEED }
cycle(math.ceil((opening() + 2e-5) / SPEED))
boundary{ side = "right", xvel = 0 }
solve{ ratio = 1e-8 }
local push = pull()
local normal = 0
for c in contacts() do normal = normal + c.fn end
local seg = across(the_bolt())
print(("closed: push %.6g N/m, joint normal force %.6g N/m (summed over both faces' contacts), "
       .. "broken segment strain %.4g"):format(push, normal, seg.strain))
assert(normal < 0, "the joint is not in compression after pushing back")
check.report("the broken segment's force, compressed", seg.force, 0, 0, { absolute = true })
check.report("push (held side's internal force) / the joint's normal force: the bolt adds nothing", push,
             -normal, 1e-6)

check.finish()
