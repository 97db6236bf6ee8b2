-- The plane-strain biaxial element test (Mohr-Coulomb, non-associated flow) by the implicit
-- prepass: constant s3, axial strain driven past yield. Checks (1 %): peak s1 = Kp s3 + sigma_c,
-- and the plastic strain ratio d eps3_p / d eps1_p = -K_psi
-- (K_psi = (1 + sin psi) / (1 - sin psi): 1, 1.4203, 2.0396, 3.0 for psi = 0, 10, 20, 30 deg).
--
-- A 1 m x 2 m sample of Mohr-Coulomb rock (the seed's c = 0.143 MPa, phi = 34 deg), E = 1 GPa,
-- nu = 0.25, in-situ s3 = 0.25 MPa all round; rollers under it, the sides loaded with s3, the top
-- held in x and driven down (boundary{ yvel }, prepass{ duration }: velocity x duration, in the
-- load steps). Two prepasses from the same start, to 4 mm and 6 mm of shortening, both past yield
-- (about 2.4 mm): on the yield surface the stress stays put, so between them the strain
-- increments are all plastic. eps1 = top displacement / height, eps3 = width change / width.
local check = require "edem.check"

local c, phi, s3 = 0.143e6, 34.0, 0.25e6
local sphi = math.sin(math.rad(phi))
local Kp = (1 + sphi) / (1 - sphi)
local sc = 2 * c * math.cos(math.rad(phi)) / (1 - sphi)
local RATE = -1e-6  -- m per cycle (static mode)

local function build(psi)
  model{ title = ("biaxial, psi = %g"):format(psi) }
  block{ x = { 0, 1 }, y = { 0, 2 } }
  zone{ edge = 0.25 }
  material{ "rock", model = "mohr", density = 2000, young = 1e9, poisson = 0.25, cohesion = c, friction = phi,
            dilation = psi, tension = 1e9 }
  assign{ material = "rock" }
  insitu{ sxx = -s3, syy = -s3, szz = -s3 }
  boundary{ side = "bottom", fix = "y" }
  boundary{ polygon = { { -0.1, -0.1 }, { 0.1, -0.1 }, { 0.1, 0.1 }, { -0.1, 0.1 } }, fix = "x" }
  boundary{ side = "left", stress = { -s3, -s3, 0 } }
  boundary{ side = "right", stress = { -s3, -s3, 0 } }
  boundary{ side = "top", yvel = RATE }
end

-- Axial stress (area mean of -syy), axial and lateral strain of a prepass result.
local function measure(pre)
  local area = {}
  for z in zones() do area[z.id] = z.area end
  local sum, total = 0, 0
  for _, z in ipairs(pre.zones) do sum, total = sum - z.syy * area[z.id], total + area[z.id] end
  local top, left, right, nt, nl, nr = 0, 0, 0, 0, 0, 0
  for g in gridpoints() do
    local u = pre.gridpoints[g.id]
    if g.y > 2 - 1e-9 then top, nt = top + u.uy, nt + 1 end
    if g.x < 1e-9 then left, nl = left + u.ux, nl + 1 end
    if g.x > 1 - 1e-9 then right, nr = right + u.ux, nr + 1 end
  end
  return sum / total, (top / nt) / 2.0, (right / nr - left / nl) / 1.0
end

for _, psi in ipairs({ 0, 10, 20, 30 }) do
  local spsi = math.sin(math.rad(psi))
  local Kpsi = (1 + spsi) / (1 - spsi)
  build(psi)
  local first = prepass{ duration = 4000, steps = 20 }
  local s1a, e1a, e3a = measure(first)
  local second = prepass{ duration = 6000, steps = 30 }
  local s1b, e1b, e3b = measure(second)
  print(("  psi = %g: s1 %.6g and %.6g Pa at eps1 = %.4g and %.4g; %d and %d Newton iterations"):format(
    psi, s1a, s1b, e1a, e1b, first.stages[1].iterations, second.stages[1].iterations))
  check.report(("psi = %g: peak s1 [Pa]"):format(psi), s1b, Kp * s3 + sc, 0.01)
  check.report(("psi = %g: plastic strain ratio d eps3 / d eps1"):format(psi), (e3b - e3a) / (e1b - e1a), -Kpsi, 0.01)
end
check.finish()
