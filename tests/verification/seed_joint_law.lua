-- The cubic joint law of the seed paper (Jiang et al., §3.2, eq. 7),
-- sn = -4.302 v^3 + 7.688 v^2 - 0.123 v (MPa, mm), on a two-block joint loaded from 0 to 6 MPa and
-- back.
--
-- The raw polynomial gives tension below v = 0.0161 mm and a negative stiffness past
-- v = 1.183 mm (3.49 MPa), so 6 MPa is out of its reach; kn_law = "seed-cubic" starts it at its
-- zero crossing and goes straight at 1880 MPa/m past its descending 1880 MPa/m point
-- (engine/contact/joint_law.cpp). A 1 m x 2 m column with a joint at mid-height, the seed's rock
-- (E = 7.4 GPa, nu = 0.136), base and left side on rollers, the top loaded in 0.5 MPa steps to
-- 6 MPa and back to 0, each step solved (static mode). Checked:
--   * the mean closure against the law's closure at that stress (inverted here independently,
--     by bisection on the polynomial), within 0.5 %, on the way up and on the way down;
--   * monotone: every step up closes the joint further, every step down opens it, and the secant
--     stiffness of every step is positive; at 0 the joint is back to zero closure;
--   * a stable step: at 6 MPa, dynamic mode with no damping for 5000 steps at the automatic
--     time step (which allows for the law's stiffest tangent, 4456 MPa/m): the top moves less
--     than 1e-3 of the joint's closure, and no step is refused by the watchdog.
local check = require "edem.check"

-- The law as this script understands it (edem.seed_law, from the paper): closure c [m] -> sn [Pa],
-- compression positive.
local seed_law = require "edem.seed_law"
local poly, slope, v0, v1 = seed_law.poly, seed_law.slope, seed_law.v0, seed_law.v1
local closure_for = seed_law.closure
print(("  law: starts at v0 = %.5f mm, straight past v1 = %.4f mm (%.4f MPa, tangent %.1f MPa/mm)"):format(
  v0, v1, poly(v1), slope(v1)))

model{ title = "seed cubic joint law, 0 -> 6 MPa -> 0" }
block{ x = {0, 1}, y = {0, 2} }
jset{ angle = 0, spacing = 10, origin = {0, 1} }
zone{ edge = 0.1 }
material{ "rock", density = 2650, young = 7.4e9, poisson = 0.136 }
assign{ material = "rock" }
joint_material{ "seed", kn_law = "seed-cubic", ks = 8.07e7, friction = 31.2 }
jassign{ material = "seed" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "left", fix = "x" }

local function mean_closure()
  local sum, length = 0, 0
  for c in contacts() do
    sum = sum - c.un * c.length
    length = length + c.length
  end
  return sum / length
end

local levels = {}
for k = 1, 12 do levels[#levels + 1] = 0.5e6 * k end
for k = 11, 0, -1 do levels[#levels + 1] = 0.5e6 * k end
local worst, monotone, previous, previous_sn = 0, true, 0, 0
for i, sn in ipairs(levels) do
  boundary{ side = "top", stress = {0, -sn, 0} }
  if sn > 0 then
    local r = solve{ ratio = 1e-10, max_cycles = 200000 }
    if not r.converged then error(("not solved at %g MPa: ratio %g"):format(sn / 1e6, r.ratio)) end
  else
    cycle(20000)  -- nothing left to balance, so no ratio to solve to: the blocks come to rest
  end
  local closure = mean_closure()
  if sn > 0 then worst = math.max(worst, math.abs(closure / closure_for(sn) - 1)) end
  if i > 1 then
    local secant = (sn - previous_sn) / (closure - previous)
    if not (secant > 0) then monotone = false end
  end
  if i == 12 or i == #levels then print(("  %4.1f MPa: closure %.6g mm, law %.6g mm"):format(
    sn / 1e6, closure * 1e3, closure_for(sn) * 1e3)) end
  previous, previous_sn = closure, sn
  if i == 12 then
    check.report("closure at 6 MPa [m]", closure, closure_for(6e6), 0.005)
    local top = gp_near(0.5, 2).uy
    set{ mode = "dynamic", damping = "none" }
    reset{ "velocity" }
    local ok, err = pcall(cycle, 5000)
    local step = info().step
    if not ok then print("  " .. tostring(err)) end
    check.report("6 MPa, 5000 dynamic steps: ran (1 = yes)", ok and 1 or 0, 1, 0, { absolute = true })
    check.report("6 MPa, 5000 dynamic steps: top moved / closure", math.abs(gp_near(0.5, 2).uy - top) / closure,
                 0, 1e-3, { absolute = true })
    print(("  dynamic step %.4g s"):format(step))
    set{ mode = "static" }
    reset{ "velocity" }
  end
end
check.report("worst closure error, all levels (rel.)", worst, 0, 0.005, { absolute = true })
check.report("monotone, positive secant stiffness (1 = yes)", monotone and 1 or 0, 1, 0, { absolute = true })
check.report("closure back at 0 MPa [m]", previous, 0, 1e-9, { absolute = true })
check.finish()
