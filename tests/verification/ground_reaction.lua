-- Issue 7, acceptance 3: VERIFICATION.md §13h, the ground reaction curve of the Salençon tunnel
-- (§2's model, psi = 0): the wall's support pressure Pi lowered from P0 to 0, the wall's inward
-- displacement at Pi / P0 = 0.8, 0.6, 0.4, 0.2 and 0 against the closed form (3 %), by the implicit
-- prepass and by the explicit solver.
--   Implicit: for each Pi, prepass{} from the in-situ state (it leaves the model as it was).
--   Explicit: Pi lowered in turn, solved to equilibrium at each (ratio 1e-6), as a ground reaction
--   curve is measured.
-- The wall is loaded by boundary{ polygon, stress = {-Pi, -Pi, 0} }; the support is elastic-
-- plastic from Pi = Pcr = (2 P0 - sigma_c) / (1 + Kp) = 0.4003 P0 down.
local check = require "edem.check"
local shapes = require "edem.shapes"

local EDGE = tonumber(arg and arg[1]) or 0.05
local a, R, P0, G, K, c, phi = 1.0, 40.0, 30e6, 2.8e9, 3.9e9, 3.45e6, 30.0
local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
local sphi = math.sin(math.rad(phi))
local Kp = (1 + sphi) / (1 - sphi)
local sc = 2 * c * math.cos(math.rad(phi)) / (1 - sphi)
local H = sc / (Kp - 1)
local Pcr = (2 * P0 - sc) / (1 + Kp)

-- Closed form (§2), psi = 0: the wall's inward displacement under a support pressure Pi.
local function wall_displacement(Pi)
  if Pi >= Pcr then return (P0 - Pi) * a / (2 * G) end
  local Kpsi, A = 1.0, Pi + H
  local R0 = a * ((2 / (Kp + 1)) * (P0 + H) / (Pi + H)) ^ (1 / (Kp - 1))
  local C1 = (1 - nu) * (1 + Kp * Kpsi) - nu * (Kp + Kpsi)
  return a / (2 * G) * ((P0 - Pcr) * (R0 / a) ^ (1 + Kpsi)
    - A * C1 / (Kp + Kpsi) * ((R0 / a) ^ (Kp - 1) * (R0 / a) ^ (Kpsi + 1) - 1)
    + (P0 + H) * (1 - 2 * nu) * ((R0 / a) ^ (Kpsi + 1) - 1))
end

model{ title = "ground reaction curve, Salencon, psi = 0" }
block(shapes.quarter_plate{ hole = a, size = R, segments = 64 })
zone{ edge = EDGE, far = 4.0, growth = 0.06, near = { shapes.sector{ r1 = a, from = 0, to = 90, segments = 32 } } }
material{ "rock", model = "mohr", density = 2600, bulk = K, shear = G, cohesion = c, friction = phi, dilation = 0,
          tension = 1e9 }
assign{ material = "rock" }
insitu{ sxx = -P0, syy = -P0, szz = -P0 }
boundary{ side = "left", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "right", stress = "insitu" }
boundary{ side = "top", stress = "insitu" }
local wall = { {-0.1, -0.1}, {1.01, -0.1}, {1.01, 1.01}, {-0.1, 1.01} }  -- the hole's wall only
local crown, side = gp_near(0, a).id, gp_near(a, 0).id
print(("%d zones; Pcr = %.4f P0"):format(info().zones, Pcr / P0))

local levels = { 0.8, 0.6, 0.4, 0.2, 0.0 }
local implicit_seconds = 0
for _, level in ipairs(levels) do
  local Pi = level * P0
  boundary{ polygon = wall, stress = { -Pi, -Pi, 0 } }
  local pre = prepass{ steps = 10 }
  implicit_seconds = implicit_seconds + pre.seconds
  local u = 0.5 * (-pre.gridpoints[side].ux - pre.gridpoints[crown].uy)
  check.report(("implicit: wall displacement at Pi / P0 = %.1f [m]"):format(level), u, wall_displacement(Pi), 0.03)
end

local clock = os.clock()
for _, level in ipairs(levels) do
  local Pi = level * P0
  boundary{ polygon = wall, stress = { -Pi, -Pi, 0 } }
  local r = solve{ ratio = 1e-6, max_cycles = 400000 }
  local ux, uy
  for g in gridpoints() do
    if g.id == side then ux = g.ux end
    if g.id == crown then uy = g.uy end
  end
  print(("  explicit, Pi / P0 = %.1f: %d cycles to ratio %.2g"):format(level, r.cycles, r.ratio))
  check.report(("explicit: wall displacement at Pi / P0 = %.1f [m]"):format(level), 0.5 * (-ux - uy),
               wall_displacement(Pi), 0.03)
end
print(("time: implicit %.1f s (5 prepasses of 10 load steps), explicit %.1f s cpu"):format(implicit_seconds,
                                                                                         os.clock() - clock))
check.finish()
