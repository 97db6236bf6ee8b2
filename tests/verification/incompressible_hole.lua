-- The mixed discretisation against volumetric locking: a circular hole under hydrostatic P0 in
-- a nearly incompressible elastic medium (nu = 0.499; Mohr-Coulomb zones that never yield). The
-- closed form does not depend on nu:
-- u_r = P0 a^2 / (2 G r), sr = P0 (1 - a^2/r^2), st = P0 (1 + a^2/r^2) (compression +), here
-- with the outer boundary at R = 20 a loaded by P0 (the finite-R correction is included).
-- Checks with the mixed discretisation: wall displacement within 1 %, hoop and radial stress
-- averaged over rings of zones at r = 1.25, 1.5, 2 and 3 a within 1 % of P0. Plain triangles
-- are run too and printed, not checked: they lock (ring errors of order P0).
local check = require "edem.check"
local shapes = require "edem.shapes"

local a, R, P0, G, nu = 1.0, 20.0, 30e6, 2.8e9, 0.499
local K = 2 * G * (1 + nu) / (3 * (1 - 2 * nu))

-- Thick cylinder a <= r <= R, inner surface free, outer pressure P0, plane strain:
-- sr = -A (1 - a^2/r^2) (tension +), with A = P0 R^2 / (R^2 - a^2).
local A = P0 * R * R / (R * R - a * a)
local function exact(r) return A * (1 - a * a / (r * r)), A * (1 + a * a / (r * r)) end
local function wall() return A * a / (2 * G) * (1 + (1 - 2 * nu) * a * a / (R * R)) end

local function run(mixed)
  model{ title = "incompressible hole" }
  block(shapes.quarter_plate{ hole = a, size = R, segments = 64 })
  zone{ edge = 0.05, far = 3.0, growth = 0.1, near = { shapes.sector{ r1 = a, from = 0, to = 90, segments = 32 } } }
  material{ "rock", model = "mohr", density = 2600, bulk = K, shear = G, cohesion = 1e12, friction = 0, tension = 1e12 }
  assign{ material = "rock" }
  set{ mixed = mixed }
  insitu{ sxx = -P0, syy = -P0, szz = -P0 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "right", stress = "insitu" }
  boundary{ side = "top", stress = "insitu" }
  solve{ ratio = 1e-7 }
  local rings = { [1.25] = { 0, 0, 0 }, [1.5] = { 0, 0, 0 }, [2.0] = { 0, 0, 0 }, [3.0] = { 0, 0, 0 } }
  for z in zones() do
    local r = math.sqrt(z.x * z.x + z.y * z.y)
    local c, s = z.x / r, z.y / r
    local nsr = -(z.sxx * c * c + z.syy * s * s + 2 * z.sxy * c * s)
    local nst = -(z.sxx * s * s + z.syy * c * c - 2 * z.sxy * c * s)
    local sr, st = exact(r)
    for radius, sums in pairs(rings) do
      if math.abs(r - radius) <= 0.05 * a then
        sums[1], sums[2], sums[3] = sums[1] + (nsr - sr) * z.area, sums[2] + (nst - st) * z.area, sums[3] + z.area
      end
    end
  end
  local errors = {}
  for radius, sums in pairs(rings) do
    errors[radius] = math.max(math.abs(sums[1] / sums[3]), math.abs(sums[2] / sums[3])) / P0
  end
  return 0.5 * (-gp_near(a, 0).ux - gp_near(0, a).uy), errors
end

local u, errors = run(false)
print(("  plain triangles: wall u %.6g (%.2f %% off), ring errors / P0 %.3f %.3f %.3f %.3f"):format(
  u, 100 * (u / wall() - 1), errors[1.25], errors[1.5], errors[2.0], errors[3.0]))
u, errors = run(true)
check.report("mixed: wall displacement [m]", u, wall(), 0.01)
for _, radius in ipairs({ 1.25, 1.5, 2.0, 3.0 }) do
  check.report(("mixed: mean stress error / P0 over the ring r = %.2f a"):format(radius), errors[radius], 0,
               0.01, { absolute = true })
end
check.finish()
