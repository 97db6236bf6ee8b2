-- Tutorial 3: a tunnel in two stages, from an elastoplastic prepass to bolts and a settlement profile.
--
-- A 10 m horseshoe tunnel, 60 m deep, in jointed Mohr-Coulomb rock. The steps:
--   1. prepass{}: an implicit static elastoplastic run of both stages, to find where the rock yields;
--   2. crackseed{ auto = }: potential cracks only there, oriented by the yielded zones' stresses;
--   3. the explicit run: each stage excavated with its load released gradually, bolts laid after it,
--      a history of the crown, and a settlement profile above the roof (like the seed's Figure 12).
-- Run: edem run staged_tunnel.lua   (or with --out results to keep the pictures elsewhere)
local cavern = require "edem.cavern"
local rockbolts = require "edem.bolts"

local t = cavern.horseshoe{ width = 10, stages = 2 }  -- heading, then bench
model{ title = "Tutorial 3: a tunnel in two stages", tolerance = 1e-5 }
block{ x = {-40, 40}, y = {-40, 40} }
jset{ angle = 60, spacing = 12, origin = {3, 0} }
for _, s in ipairs(t.stages) do region(s) end
zone{ edge = 1, far = 6, near = { t.outline } }

-- Intact rock that yields around the opening (c = 0.5 MPa at 1.6 MPa overburden); joints bonded for
-- the prepass, as a UDEC user glues them for the continuum pre-analysis, then soft Coulomb joints.
material{ "rock", model = "mohr", density = 2600, young = 5e9, poisson = 0.25,
          cohesion = 0.5e6, friction = 35, tension = 0.2e6 }
assign{ material = "rock" }
joint_material{ "glued", kn = 5e11, ks = 5e11, friction = 30, cohesion = 1e12, tension = 1e12 }
jassign{ material = "glued" }
gravity{ 0, -9.81 }
insitu{ surface = 60, density = 2600, k0 = 0.8 }
boundary{ side = "left", fix = "x" }
boundary{ side = "right", fix = "x" }
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", stress = "insitu" }

-- 1. Where does the rock yield? Both stages, implicitly, one load step each.
local names = {}
for _, s in ipairs(t.stages) do names[#names + 1] = s.name end
local pre = prepass{ stages = names, joints = true, steps = 1 }
local yielded = 0
for _, z in ipairs(pre.zones) do if z.state ~= "none" then yielded = yielded + 1 end end
print(("prepass: %d zones yielded in %.2f s"):format(yielded, pre.seconds))
plot{ file = "tunnel_prepass.png", show = {"prepass", "joints"}, window = {-20, 20, -15, 20} }

-- 2. Potential cracks only where it yielded, spaced at a tenth of the tunnel's height.
local groups = crackseed{ auto = pre }
print(("crackseed: %d groups, %d sections"):format(#groups, info().sections))

-- 3. The explicit run: real joints now, the in-situ state, then the two stages with bolts.
joint_material{ "joint", kn = 5e9, ks = 1e9, friction = 30 }
jassign{ material = "joint" }
solve{ ratio = 1e-6 }
reset{ "displacement", "velocity" }
local crown = history{ "uy", at = t.crown, every = 50 }
bolt_material{ "rockbolt", young = 200e9, area = 5e-4, yield_tension = 0.2e6, failure_strain = 0.05,
               bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
for _, s in ipairs(t.stages) do
  excavate{ region = s.name, release = 1000 }
  local r = solve{ ratio = 1e-5, max_cycles = 30000 }
  if not r.converged then error(("%s did not reach equilibrium (ratio %.3g)"):format(s.name, r.ratio)) end
  local _, laid = rockbolts.pattern{ surface = rockbolts.exposed(s, t.outline), spacing = 1.5, length = 3,
                                     segments = 6, material = "rockbolt" }
  print(("%-18s balanced after %d cycles; %d cracks so far; %d bolts laid"):format(s.name, r.cycles,
    info().cracks, laid))
end

-- The settlement along a line 2 m above the crown, a chart of the crown's history, the cracks.
local above = t.crown[2] + 2
local p = profile{ from = {-20, above}, to = {20, above}, quantity = "uy", points = 41,
                   file = "tunnel_settlement.png", title = "settlement 2 m above the crown" }
local most = 0
for _, v in ipairs(p.value) do most = math.min(most, v) end
print(("largest settlement 2 m above the crown: %.2f mm"):format(-1000 * most))
chart{ file = "tunnel_crown.png", history = crown, title = "crown displacement" }
plot{ file = "tunnel_cracks.png", show = {"zones", "joints", "cracks"}, window = {-20, 20, -15, 20} }
