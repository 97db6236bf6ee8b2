// Model::add_auto_crackseed: crackseed{ auto = prepass result }, potential cracks where the prepass
// found the rock yielding (crack/auto_placement.hpp), all placed in one rebuild of the geometry.
#include <algorithm>
#include <cmath>
#include <set>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"
#include "model/model.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

// A tenth of the height of what the prepass excavated [m] (0: nothing).
double tenth_of_opening(const Mesh& mesh, const std::vector<PrepassZone>& zones) {
  double lo = INFINITY, hi = -INFINITY;
  for (const PrepassZone& z : zones) {
    if (!z.excavated) continue;
    for (int g : mesh.zone_gp[static_cast<size_t>(z.zone)]) {
      lo = std::min(lo, mesh.gp_position[static_cast<size_t>(g)].y);
      hi = std::max(hi, mesh.gp_position[static_cast<size_t>(g)].y);
    }
  }
  return hi > lo ? 0.1 * (hi - lo) : 0.0;
}

}  // namespace

std::vector<CrackRegion> Model::add_auto_crackseed(const AutoCrackSeedDef& def) {
  check_geometry_open();
  if (!zoned()) fail("auto: the model has no zones (zone{{}} and prepass{{}} first)");
  const Mechanics& m = *mechanics_;
  const double tolerance = this->tolerance();
  for (const PrepassZone& z : def.zones) {
    if (z.zone < 0 || z.zone >= mesh_.zone_count())
      fail("auto: the prepass result names zone {}, and the model has {} zones: the geometry changed after "
           "prepass{{}}; run prepass{{}} again",
           z.zone + 1, mesh_.zone_count());
    const Vec2 here = mesh_.zone_centroid(z.zone);
    if (norm(here - z.centroid) > tolerance)
      fail("auto: the prepass result has zone {} at ({:.6g}, {:.6g}), the model at ({:.6g}, {:.6g}): the geometry "
           "changed after prepass{{}}; run prepass{{}} again",
           z.zone + 1, z.centroid.x, z.centroid.y, here.x, here.y);
  }
  int strength = -1;
  if (!def.material.empty()) {
    for (size_t i = 0; i < m.materials.size(); ++i)
      if (m.materials[i].name == def.material) strength = static_cast<int>(i);
    if (strength < 0) fail("material '{}' is not defined (material{{}} first)", def.material);
    if (!zone_law(m.materials[static_cast<size_t>(strength)].model).has_strength)
      fail("material '{}' is elastic: its cohesion, friction and tension would judge the sections (model = \"mohr\")",
           def.material);
  }
  double spacing = def.spacing;
  if (spacing == 0.0) {
    spacing = tenth_of_opening(mesh_, def.zones);
    if (spacing == 0.0)
      fail("auto: the prepass excavated nothing, so there is no opening to take a tenth of; give spacing");
  }
  if (!(spacing > 0.0) || !std::isfinite(spacing)) fail("spacing must be > 0, got {}", spacing);
  if (!(def.similar > 0.0 && def.similar <= 90.0)) fail("similar must be in (0, 90], got {}", def.similar);
  if (!(def.min_angle >= 0.0 && def.min_angle <= 60.0)) fail("min_angle must be in [0, 60], got {}", def.min_angle);

  std::set<int> inside;
  if (!def.region.empty())
    for (int z : zones_in(def.region)) inside.insert(z);
  std::vector<YieldedZone> yielded;
  for (const PrepassZone& z : def.zones) {
    if (z.excavated || !(z.shear || z.tension)) continue;
    if (!def.region.empty() && !inside.count(z.zone)) continue;
    const int material = strength >= 0 ? strength : m.zone_material[static_cast<size_t>(z.zone)];
    const double friction = material >= 0 ? m.materials[static_cast<size_t>(material)].friction : 0.0;
    yielded.push_back({z.zone, z.tension, z.angle, friction});
  }
  std::vector<CrackRegion> regions =
      place_cracks(mesh_, yielded, spacing, def.similar, def.origin, def.by_mode);
  if (regions.empty()) return regions;
  Inputs next = inputs_;
  for (const CrackRegion& region : regions) {
    CrackSeedDef seed;
    seed.angles = region.angles;
    seed.spacing = spacing;
    seed.origin = region.origin;
    seed.material = def.material;
    seed.after = def.after;
    seed.cuts = region.cuts;
    seed.outline = region.outline;
    seed.min_angle = def.min_angle;
    next.crack_seeds.push_back(std::move(seed));
  }
  commit(std::move(next));
  return regions;
}

}  // namespace edem
