-- Robustness: the seed region of tests/verification/seed_region_joints.lua
-- with a finer jointing (the Case 3 main set, 60 deg at 16, 12, 8 m, and cross joints every
-- 2 m: about 1700 blocks, 55,000 zones), in its K0 = 0.6 in-situ state, takes a sudden load
-- change: the top stress raised by a fifth at once (sides on rollers, so the stress ratio and
-- the joints' tau / sigma_n change), then 10,000 cycles in static mode. Passes if the run
-- neither stops (the overlap watchdog, an instability) nor produces a NaN, and no contact is
-- found late, already pressed in by more than a tenth of its reach (info().late_contacts: a
-- gridpoint that went into another block before detection saw it, a lost contact).
-- Label "long" (about two minutes): ctest -L long -R sudden_load.
local check = require "edem.check"
local seed = require "edem.seed"

local function region(cross_spacing, edge)
  local n = seed.region{ cross_spacing = cross_spacing, edge = edge }
  print(("  %d blocks, %d zones"):format(n.blocks, n.zones))
end

local function joint_summary()
  local slip, us, closed, where = 0, 0, 0, nil
  for c in contacts() do
    if c.slip > slip then where = c end
    slip = math.max(slip, c.slip)
    us = math.max(us, math.abs(c.us))
    if c.state ~= "open" then closed = closed + 1 end
  end
  if where then print(("  largest slip at (%.2f, %.2f), blocks %d and %d"):format(where.x, where.y, where.block, where.other)) end
  return { slip = slip, us = us, closed = closed, count = info().contacts }
end

region(2, 2)
cycle(1)
local before = joint_summary()
local surface_stress = -(2688 * 9.81 * (182 - 90))
boundary{ side = "top", stress = {0.6 * 1.2 * surface_stress, 1.2 * surface_stress, 0} }
local ok, err = pcall(cycle, 10000)
if not ok then print("  " .. tostring(err)) end
check.report("sudden load: 10,000 cycles ran (1 = yes)", ok and 1 or 0, 1, 0, { absolute = true })
local ratio = info().ratio
check.report("sudden load: ratio is a number (1 = yes)", (ratio == ratio and ratio < math.huge) and 1 or 0, 1, 0,
             { absolute = true })
local after = joint_summary()
print(("  contacts %d closed of %d before, %d closed of %d after; largest slip %.3g m, |us| %.3g m"):format(
  before.closed, before.count, after.closed, after.count, after.slip, after.us))
check.report("sudden load: contacts found late", info().late_contacts, 0, 0, { absolute = true })
check.finish()
