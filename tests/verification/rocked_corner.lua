-- A corner rocked in a joint's mouth: the detections on the way make no energy.
--
-- Between detections a contact's length follows how its gridpoint's half-edges face the edge
-- (engine/contact/facing_length.hpp), and its force pays for what that length changes of its
-- energy; a detection measures the length otherwise (engine/contact/detect.cpp: it shares a
-- half-edge among the faces of the blocks it lies over by how near and how squarely each faces
-- it). A contact found again keeps the share of its facing length it had while the detection's
-- measure stays within 10 % of it (follows_as_before): taken afresh at every detection, a share
-- that wavers as the blocks rock would make the length, the stored energy and the force jump at
-- each, unpaid, and the rock ring on what the jumps make.
--
-- Two 4 m x 4 m blocks side by side (a vertical joint at x = 0) and a 2 m square turned corner
-- down above them (its sides at 75 and 165 deg), its lowest corner 5 cm right of the joint's
-- mouth; the seed's consistent joints (kn = 84 MPa/m, ks = 3.6 MPa/m, friction 31.2 deg), zones
-- of 0.25 m. The square's top corner is pushed
-- down 3 cm (static, local damping), held, solved; then, in dynamic mode with no damping, moved
-- sideways as x = a sin(2 pi n / N) (a = 2 mm, N = 8,000 cycles) for two periods: the lowest
-- corner, pressed 2.9 cm in, rocks over the mouth, its half-edges over both blocks' faces, and
-- the contacts are found again every ten cycles or so. Check: the contacts' energy error (what
-- they stored and dissipated less the work their forces did, energy()), at its largest over the
-- run (sampled every 100 cycles), within 0.5 % of the balance's largest term at the end. A
-- detection that took its own measure every time swings it by 35 % of that term here (56 J/m of
-- 161), the lowest corner's contacts' lengths jumping at every detection as the square rocks.
-- The rest of the balance's error is the zones' integration of the driven motion, printed.
local check = require "edem.check"

local amplitude, period, periods = 0.002, 8000, 2  -- m, cycles, how many periods
model{ title = "a corner rocked in a joint's mouth" }
block{ x = {-4, 0}, y = {-4, 0} }
block{ x = {0, 4}, y = {-4, 0} }
-- The square: lowest corner at (0.05, 0), its sides at 75 and 165 deg.
local turn, side = math.rad(75), 2
local function at(u, v)
  return {0.05 + u * math.cos(turn) - v * math.sin(turn), u * math.sin(turn) + v * math.cos(turn)}
end
local square = {at(0, 0), at(side, 0), at(side, side), at(0, side)}
block(square)
zone{ edge = 0.25 }
material{ "rock", density = 2700, young = 7.4e9, poisson = 0.14 }
assign{ material = "rock" }
joint_material{ "j", kn = 84e6, ks = 3.6e6, friction = 31.2 }
jassign{ material = "j" }
boundary{ polygon = {{-4.1, -4.1}, {4.1, -4.1}, {4.1, -3.9}, {-4.1, -3.9}}, fix = "xy" }
local top = square[3]
local cap = {{top[1] - 0.3, top[2] - 0.2}, {top[1] + 0.3, top[2] - 0.2}, {top[1] + 0.3, top[2] + 0.1},
             {top[1] - 0.3, top[2] + 0.1}}
set{ damping = "local", local_damping = 0.8 }
boundary{ polygon = cap, xvel = 0, yvel = -1e-4 }
cycle(300)
boundary{ polygon = cap, fix = "xy" }
solve{ ratio = 1e-6, max_cycles = 50000 }
local deepest = 0
for c in contacts() do
  if c.block == 3 and math.abs(c.x - 0.05) < 0.01 then deepest = math.max(deepest, c.overlap) end
end
print(("the lowest corner pressed in %.4f m"):format(deepest))

-- The switch to dynamic mode prepares the model again, which measures every contact afresh: the
-- square's corner, whose followed length strayed 12 % from the measure over the solve, takes the
-- measure there (-115 J/m). The balance starts after that first cycle: it checks the rocking.
set{ mode = "dynamic", damping = "none" }
local w, n = 2 * math.pi / period, 0
every(1, function()
  n = n + 1
  boundary{ polygon = cap, xvel = amplitude * w * math.cos(w * n) / info().step, yvel = 0 }
end)
cycle(1)
energy{ reset = true }
local worst = 0  -- the contacts' error at its largest, sampled every 100 cycles [J/m]
every(100, function() worst = math.max(worst, math.abs(energy().contact_error)) end)
cycle(periods * period - 1)
local e = energy()
print(("balance over %d periods [J/m]: kinetic %.4g, strain %.4g, contacts %.4g, boundary %.4g, slip %.4g; error "
       .. "%.4g (zones %.4g, contacts %.4g), largest term %.4g"):format(periods, e.kinetic, e.strain, e.contact,
       e.boundary, e.slip, e.error, e.zone_error, e.contact_error, e.largest))
check.report("the lowest corner pressed in at least 2 cm (1 = yes)", deepest > 0.02 and 1 or 0, 1, 0,
             { absolute = true })
check.report("the contacts' energy error at its largest / the largest term", worst / e.largest, 0, 0.005,
             { absolute = true })
check.finish()
