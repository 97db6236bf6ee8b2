-- Field output read back (tests/output/read_back.py): a jointed horseshoe tunnel in two stages with
-- potential cracks and bolts, a frame before each stage and at the end (output{ at = "stage" }) and
-- one every 400 cycles. Writes what the last frame must hold to expected.txt, as key = value.
local cavern = require "edem.cavern"
local rockbolts = require "edem.bolts"
local t = cavern.horseshoe{ width = 10, stages = 2 }
block{ x = {-40, 40}, y = {-40, 40} }
jset{ angle = 60, spacing = 12, origin = {3, 0} }
for _, s in ipairs(t.stages) do region(s) end
crackseed{ angles = {120, 30}, spacing = 2, region = {{-15, -15}, {15, -15}, {15, 15}, {-15, 15}},
           material = "intact" }
zone{ edge = 1, far = 6, near = { t.outline } }
material{ "rock", density = 2600, young = 5e9, poisson = 0.25 }
material{ "intact", model = "mohr", density = 2600, young = 5e9, poisson = 0.25, cohesion = 0.3e6,
          friction = 35, tension = 0.1e6 }
assign{ material = "rock" }
joint_material{ "j", kn = 5e10, ks = 5e9, friction = 30 }
jassign{ material = "j" }
gravity{ 0, -9.81 }
insitu{ surface = 60, density = 2600, k0 = 0.8 }
boundary{ side = "left", fix = "x" }
boundary{ side = "right", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", stress = "insitu" }
bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
               bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
output{ file = "stages.xdmf", at = "stage" }
output{ file = "every.xdmf", every = 400 }
for _, s in ipairs(t.stages) do
  excavate{ region = s.name, release = 300 }
  solve{ ratio = 1e-5, max_cycles = 3000 }
  rockbolts.pattern{ surface = rockbolts.exposed(s, t.outline), spacing = 1.5, length = 4, segments = 8,
                     material = "rebar" }
end
cycle(50)  -- the bolts take load

local out = io.open("expected.txt", "w")
local function put(key, value) out:write(("%s = %.17g\n"):format(key, value)) end
local i = info()
put("frames", 3)  -- before stage 1, before stage 2, at the end
put("every_frames", math.floor(i.cycle / 400))
put("cycle", i.cycle)
put("stage", i.stage)
put("gridpoints", i.gridpoints)
local in_place, first_sxx, last_s1, corners, points = 0, nil, nil, {}, 0
for z in zones() do
  if not z.excavated then
    in_place = in_place + 1
    first_sxx = first_sxx or z.sxx
    last_s1 = z.s1
    for _, id in ipairs(z.gridpoints) do
      if not corners[id] then corners[id], points = true, points + 1 end
    end
  end
end
put("zones", in_place)
put("zones_gridpoints", points)  -- the excavated zones' own gridpoints are not written
put("zone_first_sxx", first_sxx)
put("zone_last_s1", last_s1)
-- A gridpoint of the crown, which moved: where it was made, its displacement.
local crown = gp_near(t.crown[1], t.crown[2])
assert(corners[crown.id], "the crown's gridpoint is of rock in place")
put("crown_x", crown.x)
put("crown_y", crown.y)
put("crown_ux", crown.ux)
put("crown_uy", crown.uy)
put("materials", 2)  -- rock, intact
local contact_count, fn_sum, slipping = 0, 0, 0
for c in contacts() do
  contact_count = contact_count + 1
  fn_sum = fn_sum + c.fn
  if c.state == "slip" then slipping = slipping + 1 end
end
put("contacts", contact_count)
put("contact_fn_sum", fn_sum)
put("contact_slipping", slipping)
local crack_count, shear = 0, 0
for c in cracks() do
  crack_count = crack_count + 1
  if c.mode == "shear" then shear = shear + 1 end
end
put("cracks", crack_count)
put("cracks_shear", shear)
local segments, force_max = 0, 0
for b in bolts() do
  for _, s in ipairs(b.segments) do
    segments = segments + 1
    force_max = math.max(force_max, s.force)
  end
end
put("bolt_segments", segments)
put("bolt_force_max", force_max)
out:close()
assert(crack_count > 0 and segments > 0 and contact_count > 0, "the scene must have cracks, bolts and contacts")
