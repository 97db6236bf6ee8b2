-- A detection finds each contact as it was held: contacts found again carry the forces they had.
--
-- Between detections a contact's length follows how its gridpoint's half-edges face the edge
-- (engine/contact/facing_length.hpp); a detection measures it afresh (engine/contact/detect.cpp)
-- and keeps the length followed while its measure is within 10 % of it (rocked_corner.lua).
-- Where the two disagree further, a state that was settled is pushed off its equilibrium at the
-- next detection: its contacts' forces jump with their lengths, and the energy balance books what
-- the jump makes. A re-preparation (any set{} between cycles) detects every contact afresh.
--
-- The corner_in_corner wedge: an 8 m x 8 m square cut by two joints from its centre to its left
-- side, a wedge of 53 deg (x < 0) in the concave corner of the rest, the seed's consistent joints
-- (kn = 84 MPa/m: closures of centimetres). In-situ sxx = -3 MPa, syy = -5 MPa, sxy = -1 MPa; the
-- right side held, top and bottom loaded with the in-situ stress, the left side with 1.3 sxx: the
-- wedge is pushed 2.4 cm into the corner, its apex gridpoint past the other block's apex, each of
-- the two apexes carried by a pair of contacts, one on each face (Contact::split). Solved to a
-- ratio of 1e-6; then cycled once as it is, and the same model, built and solved again, cycled
-- once after set{ damping = "adaptive" } (the damping it has), which re-prepares it.
-- Checks: the lengths and normal forces of the corner pairs' contacts (the four at the two
-- apexes) the same both ways, within 1e-6 of each (round-off; a pair's lengths held as found
-- until the next detection would change by 15 % here); every other contact's length within 1e-4
-- (the detection shares a half-edge among faces by how squarely it faces each, half_edge_parts,
-- which the facing length follows to second order in the faces' turn: 2e-5 here; at the joints'
-- ends on the model's left side, where the wedge's corners slide 2.5 cm past the rest's, a
-- detection that counted the half-edge's piece past a sharp corner by its projection on the side
-- beyond, where the followed length stops at the corner, would change them by 6 %).
--
-- And a corner pair undone: the same wedge with the rest as two blocks glued by a potential crack
-- along y = 0 from the apex (crackseed, as corner_in_corner's glued case), whose gridpoint at the
-- apex, one for both, carries the pair on the wedge's two faces. Solved as above, then the
-- crack's section at the apex is broken (judge{ criterion }): the gridpoint splits in two, and the
-- one that keeps its number has a single contact with the wedge, on one of the two faces, and the
-- gridpoint made new by the split one on the other. Checks: each carries the normal stress its
-- pair's contact on that face had (1e-3 of it; two cycles pass), and no energy goes with contacts
-- dropped (the contacts' error over the break less what the contacts kept made, each booking its
-- own: within 1e-3 of what the pair's contact on the new gridpoint's face stored). A detection
-- that took the first for a new contact, its pair's numbering gone, would drop the old one and
-- let the new inherit the faces' state with its energy booked as given: nearly all of the 4.8
-- MPa would be gone. One that took the second for new would let it inherit its neighbours' state
-- along the joint (6.3 MPa would become 0.07) and drop the old one's 1.6e4 J/m from the balance.
-- (The contacts kept make 6.1e3 J/m over the break, nearly all of it at the wedge's apex, whose
-- lengths on the rest's faces grow by 16 % where the crack's mouth opens; printed, not checked.)
local check = require "edem.check"
local wedge = require "edem.corner_wedge"

local SXX, SYY, SXY = wedge.sxx, wedge.syy, wedge.sxy

-- The wedge pushed into the corner and solved; `glued`: the rest in two blocks glued at y = 0.
local function wedge_in_corner(glued)
  wedge.build("contacts found again", {-4, 2}, glued)
  boundary{ side = "right", fix = "xy" }
  for _, side in ipairs{ "top", "bottom" } do boundary{ side = side, stress = {SXX, SYY, SXY} } end
  boundary{ side = "left", stress = {1.3 * SXX, SYY, SXY} }
  return solve{ ratio = 1e-6, max_cycles = 20000 }
end

local function settled(reprepare)
  local solved = wedge_in_corner(false)
  if reprepare then set{ damping = "adaptive" } end
  cycle(1)
  local found = {}
  for c in contacts() do found[#found + 1] = c end
  return found, solved
end

-- The contact of `list` between the same blocks, on the same face, nearest `c` (within 1 mm).
local function same_contact(list, c)
  local best, distance = nil, 1e-3
  for _, d in ipairs(list) do
    local r = math.sqrt((d.x - c.x)^2 + (d.y - c.y)^2)
    if d.block == c.block and d.other == c.other and d.face == c.face and r < distance then
      best, distance = d, r
    end
  end
  return best
end

local held, solved = settled(false)
check.report("solved to its ratio (1 yes)", solved.converged and 1 or 0, 1, 0, { absolute = true })
local again = settled(true)
local pairs_seen, worst_length, worst_force, worst_other = 0, 0, 0, 0
for _, c in ipairs(held) do
  local d = same_contact(again, c)
  if not d then
    error(string.format("contact %d on %d (face %d) at (%.4f, %.4f) not found again", c.block, c.other,
                        c.face, c.x, c.y))
  end
  local length = math.abs(d.length - c.length) / c.length
  if c.corner then
    pairs_seen = pairs_seen + 1
    worst_length = math.max(worst_length, length)
    worst_force = math.max(worst_force, math.abs(d.fn - c.fn) / math.abs(c.fn))
  elseif c.length > 0 then
    worst_other = math.max(worst_other, length)
  end
end
check.report("corner pairs' contacts", pairs_seen, 4, 0, { absolute = true })
check.report("their lengths found again, worst change [-]", worst_length, 0, 1e-6, { absolute = true })
check.report("their normal forces, worst change [-]", worst_force, 0, 1e-6, { absolute = true })
check.report("every other contact's length found again, worst change [-]", worst_other, 0, 1e-4, { absolute = true })

-- The pair undone.
local function at_apex(c) return math.abs(c.x) < 0.1 and math.abs(c.y) < 0.1 end
wedge_in_corner(true)
local pair = {}
for c in contacts() do
  if at_apex(c) and c.corner and c.other == 1 then pair[#pair + 1] = c end
end
check.report("undone: the pair at the rest's apex, before", #pair, 2, 0, { absolute = true })
energy{ by_contact = true }
local contact_error_before = energy().contact_error
judge{ every = 1, criterion = function(section) if section.x < 0.3 then return "shear" end end }
cycle(2)
-- The pair's contact along the face of `c` (their normals within 8 deg), or nil.
local function pair_on_face_of(c)
  for _, p in ipairs(pair) do
    if p.normal.x * c.normal.x + p.normal.y * c.normal.y > 0.99 then return p end
  end
end
local kept, taken_over = nil, nil
for c in contacts() do
  if at_apex(c) and c.other == 1 then
    if c.block == pair[1].block then kept = c else taken_over = c end
  end
end
local had = kept and pair_on_face_of(kept)
local had_other = taken_over and pair_on_face_of(taken_over)
check.report("undone: cracks", info().cracks, 1, 0, { absolute = true })
check.report("undone: the contact kept on its face (1 yes)", (kept and had) and 1 or 0, 1, 0, { absolute = true })
if kept and had then check.report("undone: its normal stress [Pa]", kept.sn, had.sn, 1e-3) end
check.report("undone: the new gridpoint's contact on the other face (1 yes)", (taken_over and had_other) and 1 or 0, 1,
             0, { absolute = true })
if taken_over and had_other then
  check.report("undone: its normal stress [Pa]", taken_over.sn, had_other.sn, 1e-3)
end
-- The contacts' error over the break is what the contacts there made (each books its own) and
-- what the contacts dropped took with them: the latter should be nothing.
local made = 0
for c in contacts() do made = made + (c.energy_made or 0) end
local dropped = energy().contact_error - contact_error_before - made
if had_other then
  local stored = had_other.fn ^ 2 / (2 * wedge.kn * had_other.length)  -- the pair's contact there, linear joint
  print(("undone: the contacts' error over the break %.4g J/m: made by contacts kept %.4g, gone with contacts "
         .. "dropped %.4g; the pair's contact on the new gridpoint's face stored %.4g"):format(
    dropped + made, made, dropped, stored))
  check.report("undone: energy gone with contacts dropped [J/m]", dropped, 0, 1e-3 * stored, { absolute = true })
end
check.finish()
