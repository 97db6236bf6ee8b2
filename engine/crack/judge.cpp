#include "crack/judge.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "constitutive/zone_law.hpp"
#include "contact/detect.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "crack/criteria.hpp"
#include "crack/section_stress.hpp"
#include "geom/polygon.hpp"

namespace edem {
namespace {

// Up to this many zones each side are fitted (the seed uses four).
constexpr size_t kZonesPerSide = 4;

// Per mesh gridpoint (CSR): the active zones at it.
struct GridpointZones {
  std::vector<int> first, zones;
};

GridpointZones gridpoint_zones(const Mechanics& m, const Mesh& mesh) {
  GridpointZones gz;
  gz.first.assign(static_cast<size_t>(mesh.gp_count()) + 1, 0);
  for (const int z : m.active)
    for (const int gp : mesh.zone_gp[static_cast<size_t>(z)]) ++gz.first[static_cast<size_t>(gp) + 1];
  for (size_t i = 1; i < gz.first.size(); ++i) gz.first[i] += gz.first[i - 1];
  gz.zones.resize(static_cast<size_t>(gz.first.back()));
  std::vector<int> fill(gz.first.begin(), gz.first.end() - 1);
  for (const int z : m.active)
    for (const int gp : mesh.zone_gp[static_cast<size_t>(z)])
      gz.zones[static_cast<size_t>(fill[static_cast<size_t>(gp)]++)] = z;
  return gz;
}

// The active zones of one face nearest the point, among those at the section's ends.
std::vector<int> side_zones(const Mesh& mesh, const GridpointZones& gz, const Section& s, int side) {
  std::vector<int> zones;
  for (const int gp : {s.a[static_cast<size_t>(side)], s.b[static_cast<size_t>(side)]})
    for (int i = gz.first[static_cast<size_t>(gp)]; i < gz.first[static_cast<size_t>(gp) + 1]; ++i)
      zones.push_back(gz.zones[static_cast<size_t>(i)]);
  std::sort(zones.begin(), zones.end());
  zones.erase(std::unique(zones.begin(), zones.end()), zones.end());
  const auto distance = [&](int z) { return norm(mesh.zone_centroid(z) - s.point); };
  std::stable_sort(zones.begin(), zones.end(), [&](int x, int y) { return distance(x) < distance(y); });
  if (zones.size() > kZonesPerSide) zones.resize(kZonesPerSide);
  return zones;
}

// With judge{ radius }: the active zones of the section's two blocks whose centroids lie within
// the radius of its point and that `zones` does not hold yet, in zone order. Only its own blocks:
// the cuts and joints around them bound the rock whose stress is averaged.
void add_zones_within(const Mesh& mesh, const std::vector<char>& active, const Section& s,
                      double radius, std::vector<int>& zones) {
  const size_t nearest = zones.size();
  for (size_t side = 0; side < 2; ++side) {
    const int block = s.block[side];
    if (block < 0 || (side == 1 && block == s.block[0])) continue;  // each block once
    const size_t b = static_cast<size_t>(block);
    for (int z = mesh.block_first_zone[b]; z < mesh.block_first_zone[b + 1]; ++z)
      if (active[static_cast<size_t>(z)] && norm(mesh.zone_centroid(z) - s.point) <= radius &&
          std::find(zones.begin(), zones.begin() + static_cast<long>(nearest), z) ==
              zones.begin() + static_cast<long>(nearest))
        zones.push_back(z);
  }
  std::sort(zones.begin() + static_cast<long>(nearest), zones.end());
}

RockStrength strength_of(const Mechanics& m, int material, int seed, Vec2 at) {
  const MaterialDef& def = m.materials[static_cast<size_t>(material)];
  if (!zone_law(def.model).has_strength)
    fail("crackseed {}: the rock at ({:.6g}, {:.6g}) is of material '{}', which has no strength "
         "({}); give crackseed{{ material = ... }} a material of model \"mohr\" whose cohesion, "
         "friction and tension judge it",
         seed + 1, at.x, at.y, def.name, zone_law(def.model).name);
  return {def.cohesion, def.friction, def.tension};
}

// The joint material of the cracks of section s: crackseed{ after }, else the one jassign{}
// gives joints (of no particular set) there.
int after_material(const Mechanics& m, const Section& s) {
  const CrackSeedDef& seed = m.crack_seeds[static_cast<size_t>(s.seed)];
  if (!seed.after.empty())
    return index_of_name(m.joint_materials, seed.after, "joint material", "joint_material{...}");
  ContactEdge as_joint;
  as_joint.a = m.gp_node[static_cast<size_t>(s.a[0])];
  as_joint.b = m.gp_node[static_cast<size_t>(s.b[0])];
  as_joint.touchable = true;
  as_joint.origin = {EdgeKind::joint, -1, -1, false};
  int material = -1;
  for (size_t r = 0; r < m.jassign.size(); ++r)
    if (jassign_selects(m.jassign[r], m.jassign_regions[r], as_joint, m.position)) material = m.jassign_material[r];
  if (material < 0)
    fail("crackseed {}: a crack at ({:.6g}, {:.6g}) would have no joint material: give "
         "crackseed{{ after = ... }} or a jassign{{...}} for joints there",
         s.seed + 1, s.point.x, s.point.y);
  return material;
}

Stress fitted_stress(const Mechanics& m, int section) {
  const SectionFits& f = m.fits;
  const size_t i = static_cast<size_t>(section);
  Stress s;
  double out[3] = {f.offset[i][0], f.offset[i][1], f.offset[i][2]};
  const int first = f.first[i], last = f.first[i + 1];
  for (int k = first; k < last; ++k) {
    const Stress& z = m.stress[static_cast<size_t>(f.zone[static_cast<size_t>(k)])];
    const auto& w = f.weight[static_cast<size_t>(k)];
    out[0] += w[0] * z.xx + w[1] * z.yy + w[2] * z.xy;
    out[1] += w[3] * z.xx + w[4] * z.yy + w[5] * z.xy;
    out[2] += w[6] * z.xx + w[7] * z.yy + w[8] * z.xy;
    s.zz += z.zz;
  }
  s.xx = out[0], s.yy = out[1], s.xy = out[2];
  if (last > first) s.zz /= static_cast<double>(last - first);
  return s;
}

SectionView view_of(const Mechanics& m, int section, const Stress& s) {
  const Section& sec = m.sections[static_cast<size_t>(section)];
  SectionView v;
  v.id = section;
  v.position = sec.point;
  v.angle = sec.angle;
  v.length = sec.length;
  v.sxx = s.xx, v.syy = s.yy, v.sxy = s.xy;
  const Principal p = in_plane_principal(s);
  v.s1 = p.s1, v.s3 = p.s3;
  const double a = sec.angle * std::numbers::pi / 180.0;
  const Vec2 t{std::cos(a), std::sin(a)}, n{-t.y, t.x};
  const Vec2 sn{s.xx * n.x + s.xy * n.y, s.xy * n.x + s.yy * n.y};
  v.sn = dot(sn, n);
  v.tau = dot(sn, t);
  v.strength = m.fits.strength[static_cast<size_t>(section)];
  v.overstress = overstress(p, v.strength);
  return v;
}

}  // namespace

void fit_sections(Mechanics& m, const Mesh& mesh) {
  SectionFits f;
  const size_t count = m.sections.size();
  f.first.assign(count + 1, 0);
  f.offset.assign(count, {});
  f.strength.assign(count, {});
  f.after.assign(count, -1);
  f.body.assign(count, {});
  if (count == 0) {
    m.fits = std::move(f);
    return;
  }
  const GridpointZones gz = gridpoint_zones(m, mesh);
  std::vector<char> active;
  if (m.judge.radius > 0.0) {
    active.assign(static_cast<size_t>(mesh.zone_count()), 0);
    for (const int z : m.active) active[static_cast<size_t>(z)] = 1;
  }
  // The weights depend on the zones and the body force only: a prepare() after a boundary or a
  // material changed keeps those of sections whose inputs are the same (after sections broke,
  // prepare() does not call this at all: only nodes changed).
  const SectionFits& old = m.fits;
  const bool have_old = old.first.size() == count + 1;
  for (size_t i = 0; i < count; ++i) {
    const Section& s = m.sections[i];
    const CrackSeedDef& seed = m.crack_seeds[static_cast<size_t>(s.seed)];
    std::vector<int> zones = side_zones(mesh, gz, s, 0);
    for (const int z : side_zones(mesh, gz, s, 1)) zones.push_back(z);
    if (m.judge.radius > 0.0 && !zones.empty())
      add_zones_within(mesh, active, s, m.judge.radius, zones);
    if (!zones.empty()) {
      // The body force of the rock at the point, rho g, for the fit's equilibrium.
      const int own = m.zone_material[static_cast<size_t>(zones.front())];
      const Vec2 body = m.params[static_cast<size_t>(own)].density * m.gravity;
      f.body[i] = body;
      const auto old_first = have_old ? old.zone.begin() + old.first[i] : old.zone.end();
      const auto old_last = have_old ? old.zone.begin() + old.first[i + 1] : old.zone.end();
      if (have_old && old.body[i] == body && std::equal(zones.begin(), zones.end(), old_first, old_last)) {
        f.offset[i] = old.offset[i];
        f.weight.insert(f.weight.end(), old.weight.begin() + old.first[i], old.weight.begin() + old.first[i + 1]);
      } else {
        std::vector<Vec2> centroids;
        for (const int z : zones) centroids.push_back(mesh.zone_centroid(z));
        const SectionWeights w = section_weights(s.point, centroids, body);
        f.offset[i] = w.offset;
        f.weight.insert(f.weight.end(), w.w.begin(), w.w.end());
      }
      f.zone.insert(f.zone.end(), zones.begin(), zones.end());
      const int rock = seed.material.empty()
                           ? own
                           : index_of_name(m.materials, seed.material, "material", "material{...}");
      f.strength[i] = strength_of(m, rock, s.seed, s.point);
      f.after[i] = after_material(m, s);
    }
    f.first[i + 1] = static_cast<int>(f.zone.size());
  }
  m.fits = std::move(f);
}

SectionView section_view(const Mechanics& m, int section) {
  return view_of(m, section, fitted_stress(m, section));
}

namespace {

struct Failed {
  int section;
  CrackMode mode;
  Stress stress;
  double overstress;
};

// Whether two sections touch: an end of one on the other (a row's next section, or one of a
// crossing cut's at the crossing).
bool touching(const Section& a, const Section& b) {
  const auto ends = [](const Section& s) {
    const double t = s.angle * std::numbers::pi / 180.0;
    const Vec2 half{0.5 * s.length * std::cos(t), 0.5 * s.length * std::sin(t)};
    return std::array<Vec2, 2>{s.point - half, s.point + half};
  };
  const auto ea = ends(a), eb = ends(b);
  const double tolerance = 1e-6 * std::max(a.length, b.length);
  for (const Vec2 p : ea)
    if (segment_distance(p, eb[0], eb[1]) <= tolerance) return true;
  for (const Vec2 p : eb)
    if (segment_distance(p, ea[0], ea[1]) <= tolerance) return true;
  return false;
}

// Keeps the failed sections that no touching failed section is further past its strength than
// (equal: the lower index), so that neighbours do not break together on one state: the worst
// breaks, and the others are judged again on the state its breaking leaves, as on a path of
// small load steps. Sections apart from each other still break in the same round. The choice
// reads only the state judged: the same on any thread count and in any order.
void keep_worst_of_neighbours(const Mechanics& m, std::vector<Failed>& failed) {
  const auto worse = [](const Failed& a, const Failed& b) {
    return a.overstress > b.overstress || (a.overstress == b.overstress && a.section < b.section);
  };
  std::vector<Failed> kept;
  for (const Failed& f : failed) {
    bool worst = true;
    for (const Failed& g : failed)
      if (g.section != f.section && worse(g, f) &&
          touching(m.sections[static_cast<size_t>(g.section)], m.sections[static_cast<size_t>(f.section)])) {
        worst = false;
        break;
      }
    if (worst) kept.push_back(f);
  }
  failed = std::move(kept);
}

}  // namespace

int judge_sections(Mechanics& m) {
  std::vector<Failed> failed;
  if (m.fits.first.size() != m.sections.size() + 1) return 0;  // not prepared
  const auto judged = [&](size_t i) {
    return m.sections[i].mode == CrackMode::none && m.fits.first[i] != m.fits.first[i + 1];
  };
  // Every section judged against the same state first. The built-in criteria on all threads
  // (each section on its own, so the answer is the same on any number): the cycle's other
  // threads would wait for this otherwise. A Lua criterion runs on the one Lua state.
  std::vector<CrackMode> modes(m.sections.size(), CrackMode::none);
  const long count = static_cast<long>(m.sections.size());
  if (m.judge.criterion) {
    for (int i = 0; i < static_cast<int>(count); ++i)
      if (judged(static_cast<size_t>(i)))
        modes[static_cast<size_t>(i)] = m.judge.criterion(view_of(m, i, fitted_stress(m, i)));
  } else {
#pragma omp parallel for num_threads(std::max(1, m.partition.threads)) schedule(static)
    for (long k = 0; k < count; ++k) {
      const size_t i = static_cast<size_t>(k);
      if (!judged(i)) continue;
      const Principal p = in_plane_principal(fitted_stress(m, static_cast<int>(k)));
      modes[i] = crack_mode(p, m.fits.strength[i]);
    }
  }
  for (size_t i = 0; i < modes.size(); ++i) {
    if (modes[i] == CrackMode::none) continue;
    const Stress s = fitted_stress(m, static_cast<int>(i));
    const double over = overstress(in_plane_principal(s), m.fits.strength[i]);
    failed.push_back({static_cast<int>(i), modes[i], s, over});
  }
  if (failed.empty()) return 0;
  if (m.judge.neighbours_wait) keep_worst_of_neighbours(m, failed);
  if (m.judge.most > 0 && failed.size() > static_cast<size_t>(m.judge.most)) {
    // Furthest past first; equal ones in section order, so that the choice is repeatable.
    std::stable_sort(failed.begin(), failed.end(),
                     [](const Failed& a, const Failed& b) { return a.overstress > b.overstress; });
    failed.resize(static_cast<size_t>(m.judge.most));
    std::sort(failed.begin(), failed.end(), [](const Failed& a, const Failed& b) { return a.section < b.section; });
  }
  for (const Failed& f : failed) {
    Section& s = m.sections[static_cast<size_t>(f.section)];
    s.mode = f.mode;
    s.crack = static_cast<int>(m.cracks.size());
    s.fresh = true;
    for (const int edge : s.edge) m.edge_glued[static_cast<size_t>(edge)] = 0;
    CrackView c;
    c.id = s.crack;
    c.section = f.section;
    c.position = s.point;
    c.angle = s.angle;
    c.length = s.length;
    c.mode = f.mode;
    c.cycle = m.info.cycle;
    c.stage = m.stage;
    c.sxx = f.stress.xx, c.syy = f.stress.yy, c.sxy = f.stress.xy;
    m.cracks.push_back(c);
  }
  m.fresh_cracks = true;
  return static_cast<int>(failed.size());
}

}  // namespace edem
