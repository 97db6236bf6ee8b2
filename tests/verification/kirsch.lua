-- VERIFICATION.md §1: circular hole in an elastic plate under biaxial stress (Kirsch).
--
-- Quarter model, a = 1 m, outer boundary at 40 a with the far-field stress as traction,
-- symmetry rollers on the axes. p1 = 30 MPa vertical, p2 = K0 p1 horizontal, G = 2.8 GPa,
-- K = 3.9 GPa. The in-situ stress is set and the hole is present from the start, so the
-- displacements are those of the excavation. Checks: stresses at zone centroids with
-- r >= 1.2 a (max |error| / p1 <= 3 %), wall u_r at crown and springline (<= 2 %); then
-- the ring around the hole cut into glued blocks changes u_r by <= 1 %.
local check = require "edem.check"
local shapes = require "edem.shapes"

local a, R, p1, G, K = 1.0, 40.0, 30e6, 2.8e9, 3.9e9
local nu = (3 * K - 2 * G) / (2 * (3 * K + G))

-- Kirsch, compression positive, theta from the vertical (the direction of p1).
local function kirsch(p2, r, theta)
  local q = a * a / (r * r)
  local c2, s2 = math.cos(2 * theta), math.sin(2 * theta)
  local sr = (p1 + p2) / 2 * (1 - q) + (p1 - p2) / 2 * (1 - 4 * q + 3 * q * q) * c2
  local st = (p1 + p2) / 2 * (1 + q) - (p1 - p2) / 2 * (1 + 3 * q * q) * c2
  local srt = -(p1 - p2) / 2 * (1 + 2 * q - 3 * q * q) * s2
  local ur = (p1 + p2) / (4 * G) * a * a / r + (p1 - p2) / (4 * G) * a * a / r * (4 * (1 - nu) - q) * c2
  return sr, st, srt, ur
end

local function run(k0, glued)
  local p2 = k0 * p1
  model{ title = ("Kirsch, K0 = %g%s"):format(k0, glued and ", glued ring" or "") }
  block(shapes.quarter_plate{ hole = a, size = R, segments = 64 })
  if glued then
    -- the ring a < r < 3a cut into three glued blocks
    region{ name = "ring1", polygon = shapes.sector{ r0 = a, r1 = 3 * a, from = 0, to = 30 } }
    region{ name = "ring2", polygon = shapes.sector{ r0 = a, r1 = 3 * a, from = 30, to = 60 } }
    region{ name = "ring3", polygon = shapes.sector{ r0 = a, r1 = 3 * a, from = 60, to = 90 } }
  end
  zone{ edge = 0.02, far = 4.0, growth = 0.06, near = { shapes.sector{ r1 = a, from = 0, to = 90, segments = 32 } } }
  material{ "rock", density = 2600, bulk = K, shear = G }
  assign{ material = "rock" }
  insitu{ sxx = -p2, syy = -p1, szz = -p2 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "right", stress = "insitu" }
  boundary{ side = "top", stress = "insitu" }
  local result = solve{ ratio = 1e-7, max_cycles = 200000 }
  print(("  %s: %d zones, %d cycles to ratio %.2g"):format(info().title, info().zones, result.cycles, result.ratio))

  local worst, worst_at = 0, ""
  for z in zones() do
    local r = math.sqrt(z.x * z.x + z.y * z.y)
    if r >= 1.2 * a and r <= 5 * a then
      local theta = math.atan(z.x, z.y)  -- from the vertical
      local sr, st, srt = kirsch(p2, r, theta)
      -- numerical stresses in polar components, compression positive
      -- e_r = (sin t, cos t), e_t = (cos t, -sin t); EDEM's stresses are tension positive
      local c, s = math.sin(theta), math.cos(theta)
      local nsr = -(z.sxx * c * c + z.syy * s * s + 2 * z.sxy * s * c)
      local nst = -(z.sxx * s * s + z.syy * c * c - 2 * z.sxy * s * c)
      local nsrt = -((z.sxx - z.syy) * c * s + z.sxy * (s * s - c * c))
      for _, e in ipairs({ math.abs(nsr - sr), math.abs(nst - st), math.abs(nsrt - srt) }) do
        if e / p1 > worst then worst, worst_at = e / p1, ("r = %.2f, theta = %.0f"):format(r, math.deg(theta)) end
      end
    end
  end
  local crown, spring = gp_near(0, a), gp_near(a, 0)
  local _, _, _, ur_crown = kirsch(p2, a, 0)
  local _, _, _, ur_spring = kirsch(p2, a, math.pi / 2)
  return { worst = worst, worst_at = worst_at, crown = -crown.uy, spring = -spring.ux,
           expected_crown = ur_crown, expected_spring = ur_spring }
end

for _, k0 in ipairs({ 0.5, 1.0 }) do
  local plain = run(k0, false)
  check.report(("K0 = %g: max |stress error| / p1, 1.2a <= r <= 5a (%s)"):format(k0, plain.worst_at), plain.worst, 0, 0.03, { absolute = true })
  check.report(("K0 = %g: wall u_r at the crown [m]"):format(k0), plain.crown, plain.expected_crown, 0.02)
  check.report(("K0 = %g: wall u_r at the springline [m]"):format(k0), plain.spring, plain.expected_spring, 0.02)
  local glued = run(k0, true)
  check.report(("K0 = %g: glued ring, change of crown u_r"):format(k0), glued.crown, plain.crown, 0.01)
  check.report(("K0 = %g: glued ring, change of springline u_r"):format(k0), glued.spring, plain.spring, 0.01)
end
check.finish()
