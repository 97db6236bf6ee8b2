-- edem.seed: the seed paper's jointed region and its parameter sets, scaled as its similarity law says.
-- The seed paper: Jiang et al., "Simulation of Cracking near a Large Underground Cavern in a
-- Discontinuous Rock Mass using the Expanded Distinct Element Method"; its §3.2 lists the rock's
-- and the joints' values, its §4.2 the bolts'.
--
--   local seed = require "edem.seed"
--   seed.region{ cross_spacing = 16, edge = 4 }   -- builds, zones, loads; returns info()
--   seed.P.rock, seed.P.joint                      -- the parameter sets it uses (seed.S, seed.M too)
--   seed.intact("P")                               -- the set's rock as Mohr-Coulomb, "intact"
--   seed.elastoplastic{}                           -- Mohr-Coulomb rock, bonded joints (a prepass)
--
-- The region: 200 m x 180 m, centred on the origin, the joints of `case` (seed.cases; default 3:
-- 60 deg, spacing 16, 12, 8 m in turn) and a cross set at right angles (`cross_spacing`, default
-- 16 m as in scripts/examples/jointed_cavern.lua), zoned uniformly at `edge` (default 4 m),
-- elastic rock and Coulomb joints of `set` ("P", the default, "S" or "M": seed.P, seed.S, seed.M), gravity,
-- in-situ stress with the cavern roof (y = 24) `depth` below the ground (default 158 m) and K0
-- (default 0.6), rollers on the sides and the base, the top loaded by the in-situ stress.
--
-- mirror = true mirrors the joints about x = 0 (the main set at 180 deg - its angle, dipping
-- towards +x, its spacings in reverse order, so that every trace is the mirror image of one
-- without it); the region, the stress and the boundaries are symmetric already. With a cavern
-- whose stages are mirrored too (scripts/paper/case.lua's first = "right"), the whole model is the
-- mirror image of the one without: what differs between the two, side for side, comes from the
-- discretisation (the mesh, where crackseed{ auto } lays its cuts), not from the rock.
--
-- Optional keys for an excavation in the region (none given: the uniform model above):
--   regions  list of { name = ..., polygon = ... } (e.g. edem.cavern's stages), each cut with
--            region{} (glued outlines) after the joints, before zoning
--   near     zone{}'s near: region names or polygons where zones are `edge`; with `far` (default
--            edge) and `growth` (default zone{}'s 0.2) they coarsen with distance from them
--   far, growth, sliver   zone{}'s keys
--   tolerance     model{}'s (relative to the region's diagonal, 269 m): cuts passing closer than
--            that to a vertex are bent through it, so no block has a shorter edge
--
--   local c = require("edem.cavern").warhead{}
--   seed.region{ regions = c.stages, near = { c.outline }, edge = 1.5, far = 10 }
local seed = {}

-- The seed's similarity law: its physical model is the prototype at 1/400 (C_L, lengths) with
-- stresses at 1/17.86 (C_sigma). The values the seed lists are the model material's own test
-- results, so a full-scale model takes stresses x 17.86, lengths x 400 and stiffnesses per
-- length (stress / length) x 17.86 / 400; angles, Poisson's ratio and K0 are as listed.

-- Set P, the physically consistent prototype, the study's reading:
--   rock: young, cohesion, tension x 17.86 (415.5 MPa, 0.143 MPa, 0.0546 MPa listed); friction 34
--     and poisson 0.136 as listed; density 2688 kg/m3, the prototype's unit weight 26.88 kN/m3
--     that 17.86 = 26.88 / 1.505 x 10 was built from (the listed 1505 is the model material's);
--   joints: the seed's lab curve sn = f(v) (kn_law "seed-cubic") read at prototype scale,
--     sn(v) = 17.86 f(v / 400): its three stages 260 / 940 / 1880 MPa/m become 11.6 / 42.0 /
--     83.9 MPa/m, 5 to 8 cm of closure under the cavern's in-situ stress; ks 80.7 MPa/m x 17.86 /
--     400 = 3.60 MPa/m; friction 31.2, no cohesion or tension, as listed.
-- Bolts are full-scale steel in the seed already (E 190 GPa, 446 mm2): no set scales them.
seed.P = {
  rock = { density = 2688, young = 7.421e9, poisson = 0.136, cohesion = 2.554e6, friction = 34,
           tension = 0.975e6 },
  joint = { kn_law = "seed-cubic", stress_scale = 17.86, closure_scale = 400, ks = 3.60e6, friction = 31.2 },
}

-- Set S, a sensitivity: Set P with the joints' stiffness scaled by 17.86 only (a common
-- shortcut that leaves closures at lab size): sn(v) = 17.86 f(v), kn 4.6 to 34 GPa/m over the
-- three stages, ks 80.7 MPa/m x 17.86 = 1.44 GPa/m. The joints are 400 times stiffer against the
-- rock than in the physical model.
seed.S = {
  rock = seed.P.rock,
  joint = { kn_law = "seed-cubic", stress_scale = 17.86, closure_scale = 1, ks = 80.7e6 * 17.86, friction = 31.2 },
}

-- Set M, a sensitivity: the values the seed lists for its numerical model, unscaled, at full
-- geometry: the rock about ten times overstressed against the physical model (sigma_v / UCS 2.5
-- to 4.3 at 158 m; scripts/paper/README.md, "The parameters"). Its joints close by the lab
-- curve itself.
seed.M = {
  rock = { density = 1505, young = 415.5e6, poisson = 0.136, cohesion = 0.143e6, friction = 34,
           tension = 0.0546e6 },
  joint = { kn_law = "seed-cubic", ks = 80.7e6, friction = 31.2 },
}

-- The seed's three joint patterns (its Table 1): the main set's angle from +x (it dips towards -x,
-- the cavern's left side rising to the right) and its spacings in turn; each with the cross set
-- at right angles to it.
seed.cases = {
  { angle = 45, spacing = {16} },
  { angle = 60, spacing = {16} },
  { angle = 60, spacing = {16, 12, 8} },
}

function seed.region(t)
  t = t or {}
  local cross, edge = t.cross_spacing or 16, t.edge or 4
  local depth, k0 = t.depth or 158, t.k0 or 0.6
  local case = seed.cases[t.case or 3] or error(("seed.region: case must be 1, 2 or 3, got %s"):format(t.case), 2)
  local set = seed[t.set or "P"]
  if t.set ~= nil and t.set ~= "P" and t.set ~= "S" and t.set ~= "M" then
    error(("seed.region: set must be \"P\", \"S\" or \"M\", got %s"):format(tostring(t.set)), 2)
  end
  local rock, joint = set.rock, set.joint
  if t.mirror ~= nil and type(t.mirror) ~= "boolean" then
    error(("seed.region: mirror must be true or false, got %s"):format(tostring(t.mirror)), 2)
  end
  -- Traces at offsets d along the normal, mirrored, lie at -d along the mirrored set's normal:
  -- the spacing list in reverse (edem's jset{} takes the list in turn up from its origin).
  local angle, spacing = case.angle, case.spacing
  if t.mirror then
    angle, spacing = 180 - case.angle, {}
    for i = #case.spacing, 1, -1 do spacing[#spacing + 1] = case.spacing[i] end
  end
  local title = ("seed region, Case %d joints%s, cross joints every %g m"):format(
    t.case or 3, t.mirror and " mirrored" or "", cross)
  model{ title = title, tolerance = t.tolerance }
  block{ x = {-100, 100}, y = {-90, 90} }
  jset{ angle = angle, spacing = spacing }
  jset{ angle = angle - 90, spacing = cross }
  for _, r in ipairs(t.regions or {}) do region{ name = r.name, polygon = r.polygon } end
  zone{ edge = edge, near = t.near, far = t.far, growth = t.growth, sliver = t.sliver }
  material{ "rock", density = rock.density, young = rock.young, poisson = rock.poisson }
  assign{ material = "rock" }
  joint_material{ "joint", kn = joint.kn, kn_law = joint.kn_law, stress_scale = joint.stress_scale,
                  closure_scale = joint.closure_scale, ks = joint.ks, friction = joint.friction }
  jassign{ material = "joint" }
  gravity{ 0, -9.81 }
  insitu{ surface = 24 + depth, density = rock.density, k0 = k0 }
  boundary{ side = "left", fix = "x" }
  boundary{ side = "right", fix = "x" }
  boundary{ side = "bottom", fix = "y" }
  boundary{ side = "top", stress = "insitu" }
  return info()
end

-- The intact rock of a set (default "P") as Mohr-Coulomb, material "intact" in every zone: what a
-- prepass yields in and the strength crackseed{} gives the potential cracks. Call it after
-- seed.region{}.
function seed.intact(set)
  local rock = (seed[set or "P"] or error(("seed.intact: set must be \"P\", \"S\" or \"M\", got %s"):format(
    tostring(set)), 2)).rock
  material{ "intact", model = "mohr", density = rock.density, young = rock.young, poisson = rock.poisson,
            cohesion = rock.cohesion, friction = rock.friction, tension = rock.tension }
  assign{ material = "intact" }
end

-- The continuum an elastoplastic pre-analysis sees (prepass{}, and the explicit run it is checked
-- against): Set P's rock as Mohr-Coulomb in every zone and, unless `bonded = false`, the joints
-- bonded and stiff (kn = ks = 5e11 Pa/m, cohesion and tension 1e12 Pa), as a UDEC user glues
-- joints for such a run. Call it after seed.region{}.
function seed.elastoplastic(t)
  local P, J = seed.P.rock, seed.P.joint
  material{ "rock", model = "mohr", density = P.density, young = P.young, poisson = P.poisson,
            cohesion = P.cohesion, friction = P.friction, tension = P.tension }
  assign{ material = "rock" }
  if not (t and t.bonded == false) then
    joint_material{ "bonded", kn = 5e11, ks = 5e11, friction = J.friction, cohesion = 1e12, tension = 1e12 }
    jassign{ material = "bonded" }
  end
end

return seed
