-- edem.salencon: the circular tunnel in an elastic-perfectly plastic Mohr-Coulomb medium
-- (Salençon 1969, "Contraction quasi-statique d'une cavité à symétrie sphérique ou cylindrique
-- dans un milieu élasto-plastique", Ann. Ponts Chaussées), its standard model (Itasca's
-- verification problem "Cylindrical hole in an infinite Mohr-Coulomb material") and closed form,
-- for verification scripts and benchmarks.
--
--   local salencon = require "edem.salencon"
--   local s = salencon                          -- a, R, P0, G, K, c, phi, nu, Kp, sc, H, Pcr, R0
--   salencon.build{ psi = 0, edge = 0.05 }      -- model, zones, material, in-situ state, boundaries
--   local sr, st = salencon.stresses(r)         -- Pi = 0; compression positive
--   local u = salencon.wall_displacement(psi, Pi)  -- inward, Pi default 0
--   local yielded, rings, worst, where = salencon.measure(zones_list, area_of)
--
-- Standard inputs (Itasca): a = 1 m, outer boundary at 40 a loaded with P0 = 30 MPa, G = 2.8 GPa,
-- K = 3.9 GPa, c = 3.45 MPa, phi = 30 deg; quarter model with rollers on the axes. The closed
-- form assumes szz stays the intermediate stress; with szz = -P0 initially it becomes the major one
-- within r < ~1.27 a, where the zones sit on the corner of the yield surface.
local shapes = require "edem.shapes"

local salencon = { a = 1.0, R = 40.0, P0 = 30e6, G = 2.8e9, K = 3.9e9, c = 3.45e6, phi = 30.0 }
local a, P0, G, K, c, phi = salencon.a, salencon.P0, salencon.G, salencon.K, salencon.c, salencon.phi
local nu = (3 * K - 2 * G) / (2 * (3 * K + G))
local sphi = math.sin(math.rad(phi))
local Kp = (1 + sphi) / (1 - sphi)
local sc = 2 * c * math.cos(math.rad(phi)) / (1 - sphi)
local H = sc / (Kp - 1)
local Pcr = (2 * P0 - sc) / (1 + Kp)
salencon.nu, salencon.Kp, salencon.sc, salencon.H, salencon.Pcr = nu, Kp, sc, H, Pcr

-- The plastic radius under a support pressure Pi (a when the wall stays elastic).
function salencon.plastic_radius(Pi)
  Pi = Pi or 0
  if Pi >= Pcr then return a end
  return a * ((2 / (Kp + 1)) * (P0 + H) / (Pi + H)) ^ (1 / (Kp - 1))
end
salencon.R0 = salencon.plastic_radius(0)

-- Radial and hoop stress at r with Pi = 0, compression positive.
function salencon.stresses(r)
  local R0 = salencon.R0
  if r <= R0 then return H * (r / a) ^ (Kp - 1) - H, Kp * H * (r / a) ^ (Kp - 1) - H end
  return P0 - (P0 - Pcr) * (R0 / r) ^ 2, P0 + (P0 - Pcr) * (R0 / r) ^ 2
end

-- Inward wall displacement under a support pressure Pi (default 0), dilation angle psi [deg]:
-- elastic above Pcr, else the plastic-zone displacement at r = a. That one integrates the
-- compatibility e_r = d(r e_t)/dr with the flow rule e_r^p + Kpsi e_t^p = 0, the elastic strains in
-- the plastic zone taken from the stress change through Hooke's law: the variant FLAC and UDEC
-- reproduce (Park & Kim 2006, IJRMMS 43:616-622, list three).
function salencon.wall_displacement(psi, Pi)
  Pi = Pi or 0
  if Pi >= Pcr then return (P0 - Pi) * a / (2 * G) end
  local spsi = math.sin(math.rad(psi))
  local Kpsi = (1 + spsi) / (1 - spsi)
  local A, R0 = Pi + H, salencon.plastic_radius(Pi)
  local C1 = (1 - nu) * (1 + Kp * Kpsi) - nu * (Kp + Kpsi)
  return a / (2 * G) * ((P0 - Pcr) * (R0 / a) ^ (1 + Kpsi)
    - A * C1 / (Kp + Kpsi) * ((R0 / a) ^ (Kp - 1) * (R0 / a) ^ (Kpsi + 1) - 1)
    + (P0 + H) * (1 - 2 * nu) * ((R0 / a) ^ (Kpsi + 1) - 1))
end

-- The standard model: quarter plate, zones `edge` at the wall growing to 4 m, Mohr-Coulomb rock
-- with dilation psi (no tension cut-off to speak of), in-situ -P0 everywhere, the outer sides
-- loaded with it, rollers on the axes; the wall free.
function salencon.build(t)
  model{ title = ("Salencon, psi = %g"):format(t.psi) }
  block(shapes.quarter_plate{ hole = a, size = salencon.R, segments = 64 })
  zone{ edge = t.edge, far = 4.0, growth = 0.06, near = { shapes.sector{ r1 = a, from = 0, to = 90, segments = 32 } } }
  material{ "rock", model = "mohr", density = 2600, bulk = K, shear = G, cohesion = c, friction = phi,
            dilation = t.psi, tension = 1e9 }
  assign{ material = "rock" }
  insitu{ sxx = -P0, syy = -P0, szz = -P0 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "right", stress = "insitu" }
  boundary{ side = "top", stress = "insitu" }
end

-- Over a list of zones (each with x, y, sxx, syy, sxy, state, and an area or area_of[id]): the
-- largest radius of a zone that yielded in shear; the mean error of radial and hoop stress over
-- rings of zones 0.1 a wide at r = 1.25, 1.5, 2 and 3 a, the larger of the two over P0; and the
-- worst single zone's error over P0 within 1.2 a .. 5 a and where it is.
function salencon.measure(list, area_of)
  local yielded, worst, worst_at = 0, 0, ""
  local rings = { [1.25] = { 0, 0, 0 }, [1.5] = { 0, 0, 0 }, [2.0] = { 0, 0, 0 }, [3.0] = { 0, 0, 0 } }
  for _, z in ipairs(list) do
    local r = math.sqrt(z.x * z.x + z.y * z.y)
    if z.state:find("shear") then yielded = math.max(yielded, r) end
    local sr, st = salencon.stresses(r)
    local cx, sy = z.x / r, z.y / r
    local nsr = -(z.sxx * cx * cx + z.syy * sy * sy + 2 * z.sxy * cx * sy)
    local nst = -(z.sxx * sy * sy + z.syy * cx * cx - 2 * z.sxy * cx * sy)
    if r >= 1.2 * a and r <= 5 * a then
      for _, e in ipairs({ math.abs(nsr - sr), math.abs(nst - st) }) do
        if e / P0 > worst then worst, worst_at = e / P0, ("r = %.2f"):format(r) end
      end
    end
    for radius, sums in pairs(rings) do
      if math.abs(r - radius) <= 0.05 * a then
        local w = z.area or area_of[z.id]
        sums[1], sums[2], sums[3] = sums[1] + (nsr - sr) * w, sums[2] + (nst - st) * w, sums[3] + w
      end
    end
  end
  local ring_error = {}
  for radius, sums in pairs(rings) do
    ring_error[radius] = math.max(math.abs(sums[1] / sums[3]), math.abs(sums[2] / sums[3])) / P0
  end
  return yielded, ring_error, worst, worst_at
end

return salencon
