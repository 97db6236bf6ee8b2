-- The implicit prepass on the Salençon tunnel (tests/verification/salencon_implicit.lua's model):
-- time and Newton iterations for one solver (tests/bench/RESULTS.md, issue 7).
-- Run: cd stdlib && ../build/interp/edem ../tests/bench/prepass_salencon.lua PSI EDGE STEPS SOLVER
--   e.g. ... 0 0.02 10 lu   (psi in deg, zone edge at the wall in m, load steps, lu | ldlt | klu)
local shapes = require "edem.shapes"
local a, R, P0, G, K, c, phi = 1.0, 40.0, 30e6, 2.8e9, 3.9e9, 3.45e6, 30.0
local psi, edge = tonumber(arg[1]) or 0, tonumber(arg[2]) or 0.05
local steps, solver = tonumber(arg[3]) or 10, arg[4] or "lu"
model{ title = "Salencon, implicit" }
block(shapes.quarter_plate{ hole = a, size = R, segments = 64 })
zone{ edge = edge, far = 4.0, growth = 0.06, near = { shapes.sector{ r1 = a, from = 0, to = 90, segments = 32 } } }
material{ "rock", model = "mohr", density = 2600, bulk = K, shear = G, cohesion = c, friction = phi, dilation = psi,
          tension = 1e9 }
assign{ material = "rock" }
insitu{ sxx = -P0, syy = -P0, szz = -P0 }
boundary{ side = "left", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "right", stress = "insitu" }
boundary{ side = "top", stress = "insitu" }
local pre = prepass{ steps = steps, solver = solver }
local s = pre.stages[1]
print(("psi %g, edge %g, %d zones, %d steps, %s: %d Newton iterations, %d cut-backs, %.3f s"):format(
  psi, edge, info().zones, steps, solver, s.iterations, s.cutbacks, s.seconds))
