-- A corner of one block in the concave corner of another, for the verification scripts on it
-- (tests/verification/corner_in_corner.lua, contacts_found_again.lua): an 8 m x 8 m square cut
-- by two joints from its centre to (to[1], to[2]) and (to[1], -to[2]), a wedge with its apex at
-- the centre; glued: the rest in two blocks glued by a potential crack along y = 0 from the apex.
-- Zones of 0.5 m, the seed's consistent joints (kn = 84 MPa/m, ks = 3.6 MPa/m, friction 31.2 deg)
-- and the in-situ stress sxx, syy, sxy; no boundary conditions.
local M = { sxx = -3e6, syy = -5e6, sxy = -1e6, kn = 84e6 }

function M.build(title, to, glued)
  model{ title = title }
  block{ x = {-4, 4}, y = {-4, 4} }
  crack{ from = {0, 0}, to = {to[1], to[2]} }
  crack{ from = {0, 0}, to = {to[1], -to[2]} }
  if glued then
    material{ "strong", model = "mohr", density = 2700, young = 7.4e9, poisson = 0.14, cohesion = 1e9,
              friction = 30, tension = 1e9 }
    crackseed{ angle = 0, spacing = 10, origin = {0, 0}, material = "strong",
               region = {{0, -4}, {4, -4}, {4, 4}, {0, 4}} }
  end
  zone{ edge = 0.5 }
  material{ "rock", density = 2700, young = 7.4e9, poisson = 0.14 }
  assign{ material = "rock" }
  joint_material{ "j", kn = M.kn, ks = 3.6e6, friction = 31.2 }
  jassign{ material = "j" }
  insitu{ sxx = M.sxx, syy = M.syy, sxy = M.sxy }
end

return M
