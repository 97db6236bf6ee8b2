-- In-situ stress in a jointed model: the seed's 200 m x 180 m region with the Case 3 joints
-- (60 deg, spacing 16, 12, 8 m in turn, and a cross set at right angles every 16 m, as in
-- scripts/examples/jointed_cavern.lua), physically consistent prototype properties (Set P of
-- stdlib/edem/seed.lua: E = 7.421 GPa, nu = 0.136, rho = 2688 kg/m3; joints kn = 83.9 MPa/m,
-- ks = 3.60 MPa/m, phi = 31.2, c = 0), the cavern roof 158 m deep (ground surface at y = 182),
-- gravity, K0 = 0.6. insitu{} gives the zones their stresses and the joints the consistent
-- tractions: the initial unbalanced-force ratio is at most 1e-6 without cycling, and after
-- solving the largest joint slip is below 1e-6 m (tau / sigma_n = 0.25 on the 60 deg set and
-- below on the cross set, under tan 31.2 = 0.606: nothing may slip).
-- The cutter's snapping of slivers (zone{ sliver }) is off: with it, two joint crossings near the
-- top surface merge into one vertex at (-91.2, 90) where three blocks meet the free surface, and
-- the corner contacts there do not take consistent in-situ tractions (ratio 1.5e-5 after one
-- cycle, 0.11 m of slip at that vertex).
-- The region is edem.seed's (stdlib/edem/seed.lua); tests/verification/long/
-- seed_region_sudden_load.lua loads a finer version of it suddenly.
local check = require "edem.check"
local seed = require "edem.seed"

local function region(cross_spacing, edge)
  local n = seed.region{ cross_spacing = cross_spacing, edge = edge, sliver = 0 }
  print(("  %d blocks, %d zones"):format(n.blocks, n.zones))
end

local function joint_summary()
  local slip, us, closed = 0, 0, 0
  for c in contacts() do
    slip = math.max(slip, c.slip)
    us = math.max(us, math.abs(c.us))
    if c.state ~= "open" then closed = closed + 1 end
  end
  return { slip = slip, us = us, closed = closed, count = info().contacts }
end

-- 1. K0 = 0.6, solved.
region(16, 4)
cycle(1)
check.report("K0 = 0.6: unbalanced-force ratio after one cycle", info().ratio, 0, 1e-6, { absolute = true })
solve{ ratio = 1e-6, max_cycles = 20000 }
local j = joint_summary()
print(("  %d contacts, largest |us| %.3g m"):format(j.count, j.us))
check.report("K0 = 0.6: largest joint slip after solving [m]", j.slip, 0, 1e-6, { absolute = true })

check.finish()
