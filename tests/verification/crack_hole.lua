-- Potential cracks around a circular opening in elastic-brittle rock.
--
-- Right half of a plate (symmetry about the vertical axis: x held on it), a = 1 m, plate 8 a
-- high each way, far-field stress p = 10 MPa vertical and K0 p horizontal as insitu{} and as
-- tractions on the right side and the top, the base held in y; the hole is there from the start
-- (displacements are those of the excavation). Elastic rock E = 10 GPa, nu = 0.25; potential
-- cracks in two sets (0 and 90 deg) a / 4 apart within 2.5 a of the hole, judged every 10 cycles
-- by c = 10 MPa, phi = 30 deg (UCS = 34.64 MPa), sigma_t = 2 MPa.
--
-- Kirsch's wall stress: 3 K0 p - p at the crown and invert, 3 p - K0 p at the sidewall
-- (compression positive). K0 = 0.2: -0.4 p = 4 MPa of tension at crown and invert, above
-- sigma_t, and 28 MPa of compression at the sidewall, below the UCS: tension cracks at the
-- crown and invert, none at the sidewall. K0 = 1: 2 p = 20 MPa of compression all round the
-- wall: no cracks at the crown (none anywhere).
--
-- Checks:
--   4. before any failure (the same model with strengths far above the stresses) the wall
--      displacements (at the wall's vertices, every 15 deg, the same points in both meshes)
--      differ from those of the model without potential cracks by at most 2 % of the largest;
--   5. K0 = 0.2: tension cracks within 20 deg of the vertical through the centre, above and
--      below, and none within 45 deg of the horizontal; K0 = 1: none within 20 deg of the crown;
--   6. a Lua criterion that reimplements the built-in one gives the same cracks (section, mode
--      and cycle) in the same order; its cost per judged section is printed.
local check = require "edem.check"

local a, R, P = 1.0, 8.0, 10e6
local E, NU = 10e9, 0.25

local function outline()
  local points = { { 0, -R }, { R, -R }, { R, R }, { 0, R } }
  for k = 0, 48 do  -- the wall, from the crown down to the invert, vertices every 3.75 deg
    local t = math.rad(90 - 3.75 * k)
    points[#points + 1] = { a * math.cos(t), a * math.sin(t) }
  end
  return points
end

local function build(k0, options)
  model{ title = ("hole, K0 = %g"):format(k0) }
  block(outline())
  region{ name = "near", polygon = { { 0, -2.5 * a }, { 2.5 * a, -2.5 * a }, { 2.5 * a, 2.5 * a }, { 0, 2.5 * a } } }
  if options.seed then
    crackseed{ region = "near", angles = { 0, 90 }, spacing = a / 4, origin = { a / 8, a / 8 },
               material = "strength", after = "crack" }
  end
  zone{ edge = 0.1, far = 1.0, growth = 0.3, near = { "near" } }
  material{ "rock", young = E, poisson = NU, density = 2600 }
  local strong = options.strong and 1000 or 1
  material{ "strength", model = "mohr", young = E, poisson = NU, cohesion = 10e6 * strong, friction = 30,
            tension = 2e6 * strong }
  assign{ material = "rock" }
  joint_material{ "crack", kn = 100e9, ks = 100e9, friction = 30 }
  judge{ every = 10, criterion = options.criterion }
  -- The far field is applied in 10 steps, each solved: a sudden load (or a hole opened at
  -- once in a stressed plate) rings, and sections judged while it rings see stresses the static
  -- state never has (with insitu{} and the hole there from the start, K0 = 1 gives 20 tension
  -- cracks at the wall, where the static state is in compression all round).
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  local r, cycles = nil, 0
  for step = 1, 10 do
    local p = P * step / 10
    boundary{ side = "right", stress = { -k0 * p, 0, 0 } }
    boundary{ side = "top", stress = { 0, -p, 0 } }
    r = solve{ ratio = 1e-5, max_cycles = 60000 }
    cycles = cycles + r.cycles
  end
  print(("  %s%s: %d zones, %d sections, %d cycles to ratio %.2g, %d cracks (%d tension, %d shear)"):format(
    info().title, options.seed and "" or ", no potential cracks", info().zones, info().sections, cycles,
    r.ratio, info().cracks, info().tension_cracks, info().shear_cracks))
end

-- Displacements at the wall's vertices every 15 deg from the crown.
local function wall()
  local u = {}
  for k = 0, 12 do
    local t = math.rad(90 - 15 * k)
    local g = gp_near(a * math.cos(t), a * math.sin(t))
    u[#u + 1] = { x = g.ux, y = g.uy }
  end
  return u
end

-- 4. Deformation before any failure.
build(0.2, { seed = false })
local plain = wall()
build(0.2, { seed = true, strong = true })
local seeded = wall()
local largest, worst = 0, 0
for k, u in ipairs(plain) do
  largest = math.max(largest, math.sqrt(u.x ^ 2 + u.y ^ 2))
  worst = math.max(worst, math.sqrt((seeded[k].x - u.x) ^ 2 + (seeded[k].y - u.y) ^ 2))
end
check.report("no failure: cracks made", info().cracks, 0, 0, { absolute = true })
check.report("wall displacement with potential cracks, worst difference / largest", worst / largest, 0, 0.02,
             { absolute = true })

-- 5. Where the cracks are, by their angle from the vertical through the centre.
local function census()
  local crown, invert, side, list = 0, 0, 0, {}
  for c in cracks() do
    local from_up = math.deg(math.atan(c.x, c.y))  -- 0 above, 180 below
    if c.mode == "tension" and from_up <= 20 then crown = crown + 1 end
    if c.mode == "tension" and from_up >= 160 then invert = invert + 1 end
    if from_up > 45 and from_up < 135 then side = side + 1 end
    list[#list + 1] = c
  end
  return { crown = crown, invert = invert, side = side, list = list }
end

build(0.2, { seed = true })
local low = census()
print(("  K0 = 0.2: tension cracks within 20 deg of the crown %d, of the invert %d; cracks within 45 deg "
       .. "of the sidewall %d"):format(low.crown, low.invert, low.side))
check.report("K0 = 0.2: tension cracks at the crown (1 = some)", low.crown > 0 and 1 or 0, 1, 0, { absolute = true })
check.report("K0 = 0.2: tension cracks at the invert (1 = some)", low.invert > 0 and 1 or 0, 1, 0, { absolute = true })
check.report("K0 = 0.2: cracks at the sidewall", low.side, 0, 0, { absolute = true })

build(1.0, { seed = true })
local even = census()
check.report("K0 = 1: cracks at the crown", even.crown, 0, 0, { absolute = true })

-- 6. The built-in criterion written in Lua: the same cracks, cycle for cycle.
local calls = 0
local function mohr_coulomb(s)
  calls = calls + 1
  if s.s3 > s.tension then return "tension" end
  local sin_phi = math.sin(math.rad(s.friction))
  if (1 - sin_phi) * s.s1 - (1 + sin_phi) * s.s3 + 2 * s.cohesion * math.cos(math.rad(s.friction)) < 0 then
    return "shear"
  end
  return nil
end
local started = os.clock()
build(0.2, { seed = true, criterion = mohr_coulomb })
local elapsed = os.clock() - started
local lua = census()
local same = #lua.list == #low.list
for k, c in ipairs(low.list) do
  local d = lua.list[k]
  same = same and d ~= nil and d.section == c.section and d.cycle == c.cycle and d.mode == c.mode
end
print(("  Lua criterion: %d cracks, %d calls in a run of %.2f s"):format(#lua.list, calls, elapsed))
check.report("Lua criterion: the same cracks in the same cycles (1 = yes)", same and 1 or 0, 1, 0, { absolute = true })
check.finish()
