-- A corner of one block in the concave corner of another: a block in a uniform in-situ stress is
-- in equilibrium as built, wherever its corners sit.
--
-- An 8 m x 8 m square cut by two joints from its centre to its left side (or to its top and
-- bottom): a wedge (x < 0) with its apex at the centre, in the concave corner of the rest. The rock
-- is given the in-situ stress sxx = -3 MPa, syy = -5 MPa, sxy = -1 MPa and carries it on all four
-- sides (the seed's consistent joints, kn = 84 MPa/m, ks = 3.6 MPa/m, friction 31.2 deg, hold their
-- closure under it as prestress). The gridpoints at the apex each have two half-edges, each along
-- its own face of the other block, the two faces' normals 127 deg apart for a wedge of 53 deg and
-- 70 deg for a blunt one of 110 deg. Each face carries its half-edge's traction, sigma . n: the
-- state is an equilibrium, and no gridpoint moves. One contact with one face's normal would carry
-- the other half-edge's load only as far as its normal faces that one's (a third of it at 110 deg):
-- the apex would be pushed by the rest (6.5e5 N/m here for the wedge, a ratio of 5.7e-4; in the
-- seed's cavern model, where crackseed's potential cracks glue blocks into concave bodies, 1.3e5
-- N/m). Where the rest is two blocks glued by a potential crack (y = 0, x > 0), its gridpoint at
-- the apex is one for both, with the same two faces to carry.
-- Checks, for the wedge and the blunt corner, one block or two glued around them: the unbalanced
-- force ratio after one cycle (round-off, at most 1e-12); the normal and shear stress of every
-- contact at the apex against n . sigma . n and s . sigma . n (1e-9); the corner pairs there, as
-- contacts() shows them (corner, face 1 and 2): the wedge and the rest each have one at their
-- apex gridpoint, on the other's two faces, but a wedge between two glued blocks, which has one
-- face of each; the largest displacement after 1,000 cycles (at most a nanometre).
local check = require "edem.check"
local wedge = require "edem.corner_wedge"

local SXX, SYY, SXY = wedge.sxx, wedge.syy, wedge.sxy

local function corner(case)
  wedge.build(case.what, case.to, case.glued)
  for _, side in ipairs{ "left", "right", "top", "bottom" } do boundary{ side = side, stress = {SXX, SYY, SXY} } end
  cycle(1)
  check.report(case.what .. ": unbalanced force ratio after one cycle", info().ratio, 0, 1e-12, { absolute = true })
  local worst_n, worst_s, count, paired = 0, 0, 0, {}
  for c in contacts() do
    if math.abs(c.x) < 1e-9 and math.abs(c.y) < 1e-9 then
      if c.corner then
        local key = c.block .. " " .. c.other
        paired[key] = (paired[key] or 0) + c.face  -- a pair's faces: 1 + 2
      end
      local n = c.normal
      local tx, ty = SXX * n.x + SXY * n.y, SXY * n.x + SYY * n.y
      local sn, tau = tx * n.x + ty * n.y, -tx * n.y + ty * n.x
      worst_n = math.max(worst_n, math.abs(c.sn - sn) / math.abs(sn))
      worst_s = math.max(worst_s, math.abs(math.abs(c.tau) - math.abs(tau)) / math.abs(sn))
      count = count + 1
    end
  end
  check.report(case.what .. ": contacts at the apex", count, 4, 0, { absolute = true })
  local pairs_found, unpaired = 0, 0
  for _, faces in pairs(paired) do
    if faces == 3 then pairs_found = pairs_found + 1 else unpaired = unpaired + 1 end
  end
  check.report(case.what .. ": corner pairs at the apex (faces 1 and 2)", pairs_found, case.pairs, 0,
               { absolute = true })
  check.report(case.what .. ": corner contacts at the apex without their pair", unpaired, 0, 0, { absolute = true })
  check.report(case.what .. ": their normal stress against n.sigma.n, worst [-]", worst_n, 0, 1e-9, { absolute = true })
  check.report(case.what .. ": their shear stress against s.sigma.n, worst [-]", worst_s, 0, 1e-9, { absolute = true })
  cycle(1000)
  local moved = 0
  for g in gridpoints() do moved = math.max(moved, math.sqrt(g.ux ^ 2 + g.uy ^ 2)) end
  check.report(case.what .. ": largest displacement after 1,000 cycles [m]", moved, 0, 1e-9, { absolute = true })
end

local blunt = {-4 / math.tan(math.rad(55)), 4}  -- on the top and bottom sides
corner{ what = "wedge of 53 deg in one block", to = {-4, 2}, pairs = 2 }
corner{ what = "wedge of 53 deg in two glued blocks", to = {-4, 2}, glued = true, pairs = 1 }
corner{ what = "corner of 110 deg in one block", to = blunt, pairs = 2 }
corner{ what = "corner of 110 deg in two glued blocks", to = blunt, glued = true, pairs = 1 }
check.finish()
