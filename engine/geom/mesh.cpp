#include "geom/mesh.hpp"

namespace edem {

double Mesh::zone_area(int zone) const {
  const auto& gp = zone_gp[zone];
  const Vec2 a = gp_position[gp[0]], b = gp_position[gp[1]], c = gp_position[gp[2]];
  return 0.5 * cross(b - a, c - a);  // positive: zones are counter-clockwise
}

Vec2 Mesh::zone_centroid(int zone) const {
  const auto& gp = zone_gp[zone];
  const Vec2 a = gp_position[gp[0]], b = gp_position[gp[1]], c = gp_position[gp[2]];
  return {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
}

}  // namespace edem
