#include "prepass/interfaces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "contact/joint_law.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

using Place = std::pair<double, double>;

Place place_of(const Mechanics& m, int node) {
  return {m.position[2 * static_cast<size_t>(node)], m.position[2 * static_cast<size_t>(node) + 1]};
}

// The zone of each zone edge, by its two nodes (smaller first).
std::map<std::pair<int, int>, int> zone_of_edge(const Mechanics& m) {
  std::map<std::pair<int, int>, int> out;
  for (int z : m.active) {
    const auto& node = m.geometry[static_cast<size_t>(z)].node;
    for (int i = 0; i < 3; ++i) {
      const int a = node[static_cast<size_t>(i)], b = node[static_cast<size_t>((i + 1) % 3)];
      out[{std::min(a, b), std::max(a, b)}] = z;
    }
  }
  return out;
}

}  // namespace

void make_interfaces(const Mechanics& m, std::vector<InterfacePair>& pairs, std::vector<InterfaceState>& state) {
  pairs.clear();
  state.clear();
  // Touchable edges by their two places, either way round.
  std::map<std::pair<Place, Place>, std::vector<int>> by_places;
  for (size_t e = 0; e < m.faces.edges.size(); ++e) {
    const ContactEdge& edge = m.faces.edges[e];
    if (!edge.touchable) continue;
    Place p = place_of(m, edge.a), q = place_of(m, edge.b);
    if (q < p) std::swap(p, q);
    by_places[{p, q}].push_back(static_cast<int>(e));
  }
  const auto zones = zone_of_edge(m);
  std::map<std::pair<int, int>, size_t> index;  // (a, b) -> pair
  for (const auto& [places, edges] : by_places) {
    if (edges.size() != 2) continue;  // a face with nothing across (or zoned differently)
    const ContactEdge* first = &m.faces.edges[static_cast<size_t>(edges[0])];
    const ContactEdge* other = &m.faces.edges[static_cast<size_t>(edges[1])];
    if (first->block == other->block) continue;
    if (other->block < first->block) std::swap(first, other);
    const int material = first->material >= 0 ? first->material : other->material;
    if (material < 0)
      fail("the joint between blocks {} and {} has no joint material (jassign{{}})", first->block + 1, other->block + 1);
    const JointParams& params = m.joint_params[static_cast<size_t>(material)];
    if (params.law != NormalLaw::linear)
      fail("joint material '{}' has a nonlinear normal law: the prepass's interface elements take a constant kn "
           "only (not built yet)",
           m.joint_materials[static_cast<size_t>(material)].name);
    const Place pa = place_of(m, first->a), pb = place_of(m, first->b);
    const Vec2 edge_vector{pb.first - pa.first, pb.second - pa.second};
    const double length = norm(edge_vector);
    const Vec2 normal{edge_vector.y / length, -edge_vector.x / length};  // the block is on the edge's left
    // The stress beside the joint gives the traction the pairs start with.
    const auto zone = zones.find({std::min(first->a, first->b), std::max(first->a, first->b)});
    const Stress s = zone == zones.end() ? Stress{} : m.stress[static_cast<size_t>(zone->second)];
    const Vec2 traction{s.xx * normal.x + s.xy * normal.y, s.xy * normal.x + s.yy * normal.y};
    // The node across from each end of `first`, at the same place (the edge across normally runs
    // the other way).
    const bool reversed = place_of(m, other->b) == pa;
    const int across_a = reversed ? other->b : other->a, across_b = reversed ? other->a : other->b;
    for (const auto& [here, across] : {std::pair{first->a, across_a}, std::pair{first->b, across_b}}) {
      auto [it, added] = index.try_emplace({here, across}, pairs.size());
      if (added) {
        pairs.push_back({here, across, 0.0, {0.0, 0.0}, material});
        state.push_back({});
      }
      InterfacePair& pair = pairs[it->second];
      InterfaceState& st = state[it->second];
      const double share = 0.5 * length;
      // Length-weighted sums, normalised below.
      pair.n = pair.n + share * normal;
      st.sn += share * dot(traction, normal);
      st.ss += share * dot(traction, along(normal));
      pair.length += share;
    }
  }
  for (size_t i = 0; i < pairs.size(); ++i) {
    InterfacePair& pair = pairs[i];
    pair.n = (1.0 / norm(pair.n)) * pair.n;
    state[i].sn /= pair.length;
    state[i].ss /= pair.length;
    state[i].d = opening(pair, m.u);
  }
}

InterfaceState interface_trial(const JointParams& p, const InterfacePair& pair, const InterfaceState& start, Vec2 d) {
  const Vec2 dd = d - start.d;
  InterfaceState now = start;
  now.d = d;
  now.mode = 0;
  now.sn = start.sn + p.kn * dot(dd, pair.n);
  now.ss = start.ss + p.ks * dot(dd, along(pair.n));
  const double tension = start.broken ? 0.0 : p.tension;
  if (now.sn > tension) {  // open: no traction
    now.sn = 0.0;
    now.ss = 0.0;
    now.mode = kTensionNow;
    now.broken = true;
    return now;
  }
  const double friction = start.broken ? p.tan_residual_friction : p.tan_friction;
  const double limit = coulomb_strength(p, !start.broken, -now.sn, p.cohesion);  // sn <= 0 in compression
  if (std::abs(now.ss) > limit) {
    now.ss = std::copysign(std::max(limit, 0.0), now.ss);
    now.mode = kShearNow;
    now.broken = true;
    now.slope = friction;
  }
  return now;
}

std::array<double, 4> interface_tangent(const JointParams& p, const InterfacePair& pair, const InterfaceState& now) {
  if (now.mode == kTensionNow) return {0.0, 0.0, 0.0, 0.0};
  const Vec2 n = pair.n, t = along(n);
  // In local axes: d sn / d dn = kn; d ss / d ds = ks, or, slipping, d ss / d dn = -sign tan(phi) kn.
  const double friction = now.slope;
  const double snn = p.kn, sst = now.mode == kShearNow ? 0.0 : p.ks;
  const double stn = now.mode == kShearNow ? -std::copysign(1.0, now.ss) * friction * p.kn : 0.0;
  // traction = sn n + ss t; d traction / d d = n (snn n^T) + t (stn n^T + sst t^T).
  return {n.x * snn * n.x + t.x * (stn * n.x + sst * t.x), n.x * snn * n.y + t.x * (stn * n.y + sst * t.y),
          n.y * snn * n.x + t.y * (stn * n.x + sst * t.x), n.y * snn * n.y + t.y * (stn * n.y + sst * t.y)};
}

}  // namespace edem
