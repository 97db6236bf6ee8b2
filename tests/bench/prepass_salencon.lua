-- The implicit prepass on the Salençon tunnel (tests/verification/salencon_implicit.lua's model):
-- time and Newton iterations for one solver (tests/bench/RESULTS.md, issue 7).
-- Run: cd stdlib && ../build/interp/edem ../tests/bench/prepass_salencon.lua PSI EDGE STEPS SOLVER
--   e.g. ... 0 0.02 10 umfpack   (psi in deg, zone edge at the wall in m, load steps, umfpack | lu | ldlt | klu)
local salencon = require "edem.salencon"
local psi, edge = tonumber(arg[1]) or 0, tonumber(arg[2]) or 0.05
local steps, solver = tonumber(arg[3]) or 10, arg[4] or "umfpack"
salencon.build{ psi = psi, edge = edge }
local pre = prepass{ steps = steps, solver = solver }
local s = pre.stages[1]
print(("psi %g, edge %g, %d zones, %d steps, %s: %d Newton iterations, %d cut-backs, %.3f s"):format(
  psi, edge, info().zones, steps, solver, s.iterations, s.cutbacks, s.seconds))
