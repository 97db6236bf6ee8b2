-- The ground reaction curve of the Salençon tunnel (Salençon 1969; salencon.lua's model,
-- psi = 0): the wall's support pressure Pi lowered from P0 to 0, the wall's inward
-- displacement at Pi / P0 = 0.8, 0.6, 0.4, 0.2 and 0 against the closed form (3 %), by the implicit
-- prepass and by the explicit solver.
--   Implicit: for each Pi, prepass{} from the in-situ state (it leaves the model as it was).
--   Explicit: Pi lowered in turn, solved to equilibrium at each (ratio 1e-6), as a ground reaction
--   curve is measured.
-- The wall is loaded by boundary{ polygon, stress = {-Pi, -Pi, 0} }; the support is elastic-
-- plastic from Pi = Pcr = (2 P0 - sigma_c) / (1 + Kp) = 0.4004 P0 down.
local check = require "edem.check"
local salencon = require "edem.salencon"

local EDGE = tonumber(arg and arg[1]) or 0.05
local a, P0 = salencon.a, salencon.P0
local function wall_displacement(Pi) return salencon.wall_displacement(0, Pi) end

salencon.build{ psi = 0, edge = EDGE }
local wall = { {-0.1, -0.1}, {1.01, -0.1}, {1.01, 1.01}, {-0.1, 1.01} }  -- the hole's wall only
local crown, side = gp_near(0, a).id, gp_near(a, 0).id
print(("%d zones; Pcr = %.4f P0"):format(info().zones, salencon.Pcr / P0))

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
