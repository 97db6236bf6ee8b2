-- A tip driven in point first: the corner of a triangle pressed into the flat face of a block.
--
-- A penalty interface pushes back on the overlap: where the faces overlap by d(x), with a
-- linear joint (kn), the force is kn times the overlap's area. A tip whose edges leave the face
-- at angles a_l and a_r from its normal, pressed in by d, overlaps it by a triangle of area
-- d^2 (tan a_l + tan a_r) / 2, so under a force F it stops at
--   d = sqrt(2 F / (kn (tan a_l + tan a_r))),
-- and its contact then carries F over a length d (tan a_l + tan a_r) / 2 (contacts.hpp). A
-- contact length from the gridpoint's half-edges projected on the face alone (h sin^2 a each,
-- a few millimetres here) does not grow with d: the tip would sink far deeper than d and stop on
-- the overlap watchdog, as the corners of small blocks around the seed's cavern would
-- (scripts/paper/case.lua).
--
-- Two cases, each a block 1 m tall ending in a tip (E = 100 GPa, so that its own strain is
-- negligible) on a 2 m x 1 m block with its base held, apex 1 mm above the face and between the
-- face's gridpoints; the tip's edges run 0.5 m, the top is 0.4 m wide, centred over the apex,
-- held sideways and loaded down by a stress; kn = 1 GPa/m, ks = 1 GPa/m, friction 45 deg; static
-- mode, solved to ratio 1e-9:
--   1. a 26 deg tip (13 deg either side, the sharpest corner found at a stop in the study);
--   2. a leaning tip, its right edge at 30 deg to the right of the normal and its left edge 5 deg
--      to the right too (half-angles +30 and -5: a 25 deg tip pointing down and to the left).
-- The load is set for d = 0.06 m. Checked within 0.5 %: the overlap against d, the contact's
-- length against d times half the tangents' spread, and the sum of the contact forces against
-- the load (equilibrium).
local check = require "edem.check"

local E, kn = 100e9, 1e9
local HEIGHT, LIFT, APEX_X = 1.0, 1e-3, 0.05
local DEPTH = 0.045  -- [m] the overlap the load is set for
local TOP = 0.4      -- [m] width of the loaded top

local function tip(case)
  local tr, tl = math.tan(math.rad(case.right)), math.tan(math.rad(case.left))
  local wedge = (tr + tl) / 2  -- half the chord per unit depth
  local force = kn * wedge * DEPTH ^ 2  -- [N/m]
  model{ title = "a tip pressed into a face: " .. case.what }
  block{ x = {-1, 1}, y = {-1, 0} }
  -- The tip's edges run half the height; above them the block's top is centred over the apex,
  -- so the load needs no sideways reaction there (which would turn the block on the tip).
  local half = HEIGHT / 2
  block{ {APEX_X, LIFT}, {APEX_X + half * tr, LIFT + half}, {APEX_X + TOP / 2, LIFT + HEIGHT},
         {APEX_X - TOP / 2, LIFT + HEIGHT}, {APEX_X - half * tl, LIFT + half} }
  zone{ edge = 0.25 }
  material{ "rock", density = 2600, young = E, poisson = 0.25 }
  assign{ material = "rock" }
  joint_material{ "j", kn = kn, ks = kn, friction = 45 }
  jassign{ material = "j" }
  boundary{ side = "bottom", fix = "xy" }
  boundary{ side = "top", fix = "x", stress = {0, -force / TOP, 0} }
  local r = solve{ ratio = 1e-9, max_cycles = 200000 }
  if not r.converged then error(case.what .. ": not solved, ratio " .. r.ratio) end
  local apex, carrying, total = nil, 0, 0
  for c in contacts() do
    total = total - c.fn
    if c.fn < 0 then
      carrying = carrying + 1
      apex = c
    end
  end
  check.report(case.what .. ": contacts carrying force", carrying, 1, 0, { absolute = true })
  check.report(case.what .. ": overlap [m]", -apex.un, math.sqrt(force / (kn * wedge)), 0.005)
  check.report(case.what .. ": contact length [m]", apex.length, wedge * DEPTH, 0.005)
  check.report(case.what .. ": contact force against the load [N/m]", total, force, 0.005)
end

tip{ what = "26 deg tip", right = 13, left = 13 }
tip{ what = "leaning tip", right = 30, left = -5 }
check.finish()
