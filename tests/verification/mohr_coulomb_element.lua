-- A Mohr-Coulomb sample in plane-strain uniaxial and triaxial compression yields at
-- UCS = 2 c cos(phi) / (1 - sin(phi)) and s1 = Kp s3 + UCS.
--
-- Seed values (the seed paper, Jiang et al., §3.2) c = 0.143 MPa, phi = 34 deg, tension 0.0546 MPa;
-- a 1 m x 2 m sample on a frictionless base (rollers), pressed by a top platen moving down slowly
-- (rollers too), the sides free or under a confining stress s3. The axial stress follows the
-- elastic line, then stays on the yield surface: its plateau is the strength.
local check = require "edem.check"

local c, phi, tension = 0.143e6, 34.0, 0.0546e6
local s = math.sin(math.rad(phi))
local Kp = (1 + s) / (1 - s)
local ucs = 2 * c * math.cos(math.rad(phi)) / (1 - s)

local function peak_axial(confining)
  model{ title = ("sample, s3 = %g"):format(confining) }
  block{ x = { 0, 1 }, y = { 0, 2 } }
  zone{ edge = 0.25 }
  material{ "rock", model = "mohr", density = 2000, young = 1e9, poisson = 0.25,
            cohesion = c, friction = phi, tension = tension }
  assign{ material = "rock" }
  insitu{ sxx = -confining, syy = -confining, szz = -confining }
  boundary{ side = "bottom", fix = "y" }
  boundary{ polygon = { { -0.1, -0.1 }, { 0.1, -0.1 }, { 0.1, 0.1 }, { -0.1, 0.1 } }, fix = "x" }
  boundary{ side = "top", yvel = -2e-7 }  -- m per cycle (static mode)
  if confining > 0 then
    boundary{ side = "left", stress = { -confining, -confining, 0 } }
    boundary{ side = "right", stress = { -confining, -confining, 0 } }
  end
  local peak, state = 0, "elastic"
  for _ = 1, 80 do
    cycle(250)
    local sum, area = 0, 0
    for z in zones() do sum, area = sum + z.syy * z.area, area + z.area end
    peak = math.max(peak, -sum / area)
    state = zone_at(0.5, 1.0).state
  end
  return peak, state
end

local peak, state = peak_axial(0)
check.report("uniaxial: peak axial stress [Pa]", peak, ucs, 0.01)
check.report("uniaxial: the sample yields in shear (1 = yes)", state:find("shear") and 1 or 0, 1, 0)
for _, s3 in ipairs({ 0.25e6, 0.5e6 }) do
  local p = peak_axial(s3)
  check.report(("triaxial s3 = %g MPa: peak axial stress [Pa]"):format(s3 / 1e6), p, Kp * s3 + ucs, 0.01)
end
check.finish()
