-- Kirsch's hole (kirsch.lua) reached by excavation, and elastic path independence: one stage
-- or four give the same final state.
--
-- Quarter model of a plate 40 a wide with a = 1 m, symmetry rollers on the axes, the far field
-- (p1 = 30 MPa vertical, p2 = K0 p1 horizontal) as in-situ stress and as traction on the outer
-- sides; G = 2.8 GPa, K = 3.9 GPa (as kirsch.lua). The hole is cut as four glued sectors of
-- 22.5 deg; the plate is solved in its in-situ state first, displacements are reset there, and
-- the hole is excavated:
--   at once (one stage, the four sectors together), checked against Kirsch with kirsch.lua's
--   tolerances: stresses at zone centroids 1.2 a <= r <= 5 a within 3 % of p1, wall u_r at the
--   crown and the springline within 2 %;
--   in four stages (one sector each, solved after each): the final state must equal the one-stage
--   state within 0.1 % (elastic: the path does not matter): every gridpoint's displacement
--   against the largest, every zone's stress against p1;
--   at once with release = 2000 cycles: the same final state within 0.1 % too.
-- Each state solved to ratio 1e-8: at 1e-7 the far field of the released run still differed by
-- 6e-4 p1 (it converges last), at 1e-8 by 3e-5; one and four stages then agree to 1e-7.
local check = require "edem.check"
local shapes = require "edem.shapes"
local kirsch = require "edem.kirsch"

local a, R, p1, G, K = 1.0, 40.0, 30e6, 2.8e9, 3.9e9
local K0 = 0.5
local p2 = K0 * p1
local RATIO = 1e-8

local hole = kirsch.new{ a = a, p1 = p1, p2 = p2, shear = G, bulk = K }

local HOLE = shapes.sector{ r1 = a, from = 0, to = 90, segments = 64 }

local function build(label)
  model{ title = label }
  block{ x = { 0, R }, y = { 0, R } }
  for k = 1, 4 do
    region{ name = "hole" .. k, polygon = shapes.sector{ r1 = a, from = 22.5 * (k - 1), to = 22.5 * k, segments = 16 } }
  end
  zone{ edge = 0.02, far = 4.0, growth = 0.06, near = { HOLE } }
  material{ "rock", density = 2600, bulk = K, shear = G }
  assign{ material = "rock" }
  insitu{ sxx = -p2, syy = -p1, szz = -p2 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "right", stress = "insitu" }
  boundary{ side = "top", stress = "insitu" }
  solve{ ratio = RATIO }
  reset{ "displacement", "velocity" }
end

local function state()
  local u, s, rock = {}, {}, {}
  for z in zones() do if not z.excavated then rock[z.block] = true end end
  for g in gridpoints() do  -- those of the rock left in place (the hole's wall is its own since
    if rock[g.block] then u[#u + 1] = { g.ux, g.uy } end  -- excavate unglued it)
  end
  for z in zones() do s[#s + 1] = { z.sxx, z.syy, z.sxy, z.excavated } end
  return { u = u, s = s, crown = -gp_near(0, a).uy, spring = -gp_near(a, 0).ux }
end

local function solved(label, cycles)
  local r = solve{ ratio = RATIO, max_cycles = 200000 }
  print(("  %s: stage %d, %d cycles to ratio %.2g"):format(label, stage(), r.cycles, r.ratio))
  if not r.converged then error(label .. ": not solved") end
  return cycles + r.cycles
end

-- One stage.
build("one stage")
local zones_before = info().zones
excavate{ region = HOLE }
local cycles = solved("one stage", 0)
local once = state()
local worst, worst_at = hole.worst_stress(1.2, 5)
local excavated = 0
for z in zones() do if z.excavated then excavated = excavated + 1 end end
print(("  %d zones, %d excavated (stage %d); %d cycles"):format(zones_before, excavated, stage(), cycles))
local _, _, _, ur_crown = hole.at(a, 0)
local _, _, _, ur_spring = hole.at(a, math.pi / 2)
check.report(("max |stress error| / p1, 1.2a <= r <= 5a (%s)"):format(worst_at), worst, 0, 0.03, { absolute = true })
check.report("wall u_r at the crown [m]", once.crown, ur_crown, 0.02)
check.report("wall u_r at the springline [m]", once.spring, ur_spring, 0.02)

-- The difference of two final states: displacements against the largest, stresses against p1.
local function difference(x, y)
  local umax, du, ds = 0, 0, 0
  for i, u in ipairs(x.u) do
    umax = math.max(umax, math.sqrt(u[1] ^ 2 + u[2] ^ 2))
    du = math.max(du, math.sqrt((u[1] - y.u[i][1]) ^ 2 + (u[2] - y.u[i][2]) ^ 2))
  end
  for i, s in ipairs(x.s) do
    for k = 1, 3 do ds = math.max(ds, math.abs(s[k] - y.s[i][k])) end
  end
  return du / umax, ds / p1
end

-- Four stages.
build("four stages")
cycles = 0
for k = 1, 4 do
  excavate("hole" .. k)
  cycles = solved("four stages", cycles)
end
local staged = state()
local du, ds = difference(once, staged)
check.report("four stages against one: displacement difference / largest", du, 0, 1e-3, { absolute = true })
check.report("four stages against one: stress difference / p1", ds, 0, 1e-3, { absolute = true })
check.report("four stages: stage() after them", stage(), 4, 0, { absolute = true })

-- Released over 2000 cycles.
build("released")
excavate{ region = HOLE, release = 2000 }
local r = solve{ ratio = RATIO, max_cycles = 200000 }
print(("  released over 2000 cycles: %d cycles to ratio %.2g"):format(r.cycles, r.ratio))
check.report("released: cycles before solve{} stopped (at least the release)", math.min(r.cycles, 2000), 2000, 0,
             { absolute = true })
local released = state()
du, ds = difference(once, released)
check.report("released against at once: displacement difference / largest", du, 0, 1e-3, { absolute = true })
check.report("released against at once: stress difference / p1", ds, 0, 1e-3, { absolute = true })
check.finish()
