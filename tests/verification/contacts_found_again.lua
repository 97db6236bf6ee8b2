-- A detection finds each contact as it was held: contacts found again carry the forces they had.
--
-- Between detections a contact's length follows how its gridpoint's half-edges face the edge
-- (engine/contact/facing_length.hpp); a detection measures it afresh (engine/contact/detect.cpp).
-- Where the two disagree, a state that was settled is pushed off its equilibrium at the next
-- detection: its contacts' forces jump with their lengths, and the energy balance books what the
-- jump makes. A re-preparation (any set{} between cycles) detects every contact afresh.
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
-- one that keeps its number has a single contact with the wedge, on one of the two faces. Check:
-- its normal stress is the one its pair's contact on that face had (1e-3 of it; two cycles pass).
-- A detection that took it for a new contact, its pair's numbering gone, would drop the old one
-- and let the new inherit the faces' state with its energy booked as given: nearly all of the
-- 4.8 MPa would be gone. (The gridpoint made new by the split, on the other face, is a new contact
-- that inherits the faces' state from its neighbours along the joint: it carries far less, and
-- the balance loses its energy; not checked here.)
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
  for c in contacts() do
    found[string.format("%d %d %d %.3f %.3f", c.block, c.other, c.face, c.x, c.y)] = c
  end
  return found, solved
end

local held, solved = settled(false)
check.report("solved to its ratio (1 yes)", solved.converged and 1 or 0, 1, 0, { absolute = true })
local again = settled(true)
local pairs_seen, worst_length, worst_force, worst_other = 0, 0, 0, 0
for key, c in pairs(held) do
  local d = again[key]
  if not d then error("contact " .. key .. " not found again") end
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
judge{ every = 1, criterion = function(section) if section.x < 0.3 then return "shear" end end }
cycle(2)
local kept, had = nil, nil
for c in contacts() do
  if at_apex(c) and c.other == 1 and c.block == pair[1].block then kept = c end
end
if kept then
  for _, c in ipairs(pair) do
    if c.normal.x * kept.normal.x + c.normal.y * kept.normal.y > 0.99 then had = c end
  end
end
check.report("undone: cracks", info().cracks, 1, 0, { absolute = true })
check.report("undone: the contact kept on its face (1 yes)", (kept and had) and 1 or 0, 1, 0, { absolute = true })
if kept and had then check.report("undone: its normal stress [Pa]", kept.sn, had.sn, 1e-3) end
check.finish()
