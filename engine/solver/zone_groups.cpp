// Pairing is a maximum-matching problem on the zones' adjacency graph; the greedy rule of Karp
// and Sipser (match a zone with the fewest free neighbours first, to its free neighbour with the
// fewest free neighbours) leaves few zones unmatched on triangulations. Ties go to the longer
// shared edge, which makes the better-shaped quadrilateral, then to the lower position.
#include "solver/zone_groups.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

namespace edem {
namespace {

struct Neighbour {
  int zone = -1;       // position
  double edge = 0.0;   // shared edge length [m]
};

std::vector<std::array<Neighbour, 3>> neighbours_of(const std::vector<ZoneGeometry>& geometry,
                                                    const std::vector<int>& zones,
                                                    const std::vector<double>& position) {
  // (low node, high node, position) for every zone edge; equal keys are neighbours.
  struct Side {
    int a, b, zone;
  };
  std::vector<Side> sides;
  sides.reserve(3 * zones.size());
  for (size_t k = 0; k < zones.size(); ++k) {
    const auto& node = geometry[static_cast<size_t>(zones[k])].node;
    for (int i = 0; i < 3; ++i) {
      const int a = node[static_cast<size_t>(i)], b = node[static_cast<size_t>((i + 1) % 3)];
      sides.push_back({std::min(a, b), std::max(a, b), static_cast<int>(k)});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& l, const Side& r) {
    return std::tie(l.a, l.b, l.zone) < std::tie(r.a, r.b, r.zone);
  });
  std::vector<std::array<Neighbour, 3>> out(zones.size());
  auto add = [&out](int zone, Neighbour n) {
    for (Neighbour& slot : out[static_cast<size_t>(zone)])
      if (slot.zone < 0) {
        slot = n;
        return;
      }
  };
  for (size_t i = 0; i + 1 < sides.size(); ++i) {
    const Side& s = sides[i];
    const Side& t = sides[i + 1];
    if (s.a != t.a || s.b != t.b) continue;
    // An edge shared by more than two zones (never in a valid mesh) pairs only the first two.
    if (i > 0 && sides[i - 1].a == s.a && sides[i - 1].b == s.b) continue;
    const double dx = position[2 * static_cast<size_t>(s.a)] - position[2 * static_cast<size_t>(s.b)];
    const double dy = position[2 * static_cast<size_t>(s.a) + 1] - position[2 * static_cast<size_t>(s.b) + 1];
    const double length = std::hypot(dx, dy);
    add(s.zone, {t.zone, length});
    add(t.zone, {s.zone, length});
  }
  return out;
}

}  // namespace

std::vector<std::array<int, 2>> group_zones(const std::vector<ZoneGeometry>& geometry,
                                            const std::vector<int>& zones,
                                            const std::vector<double>& position) {
  const auto near = neighbours_of(geometry, zones, position);
  const int count = static_cast<int>(zones.size());
  std::vector<int> mate(static_cast<size_t>(count), -1), free_degree(static_cast<size_t>(count), 0);
  for (int k = 0; k < count; ++k)
    for (const Neighbour& n : near[static_cast<size_t>(k)]) free_degree[static_cast<size_t>(k)] += n.zone >= 0;
  std::set<std::pair<int, int>> queue;  // (free neighbours, position) of unmatched zones
  for (int k = 0; k < count; ++k)
    if (free_degree[static_cast<size_t>(k)] > 0) queue.insert({free_degree[static_cast<size_t>(k)], k});

  auto retire = [&](int k) {  // k is matched: its free neighbours lose a free neighbour
    queue.erase({free_degree[static_cast<size_t>(k)], k});
    for (const Neighbour& n : near[static_cast<size_t>(k)]) {
      if (n.zone < 0 || mate[static_cast<size_t>(n.zone)] >= 0) continue;
      int& d = free_degree[static_cast<size_t>(n.zone)];
      queue.erase({d, n.zone});
      if (--d > 0) queue.insert({d, n.zone});
    }
  };
  while (!queue.empty()) {
    const int k = queue.begin()->second;
    int best = -1;
    for (const Neighbour& n : near[static_cast<size_t>(k)]) {
      if (n.zone < 0 || mate[static_cast<size_t>(n.zone)] >= 0) continue;
      if (best < 0) {
        best = n.zone;
        continue;
      }
      const int d = free_degree[static_cast<size_t>(n.zone)], db = free_degree[static_cast<size_t>(best)];
      double edge = 0.0, best_edge = 0.0;
      for (const Neighbour& o : near[static_cast<size_t>(k)]) {
        if (o.zone == n.zone) edge = o.edge;
        if (o.zone == best) best_edge = o.edge;
      }
      if (d < db || (d == db && (edge > best_edge || (edge == best_edge && n.zone < best)))) best = n.zone;
    }
    mate[static_cast<size_t>(k)] = best;
    mate[static_cast<size_t>(best)] = k;
    retire(k);
    retire(best);
  }

  std::vector<std::array<int, 2>> others(static_cast<size_t>(count), {-1, -1});
  for (int k = 0; k < count; ++k) others[static_cast<size_t>(k)][0] = mate[static_cast<size_t>(k)];
  // A zone left unmatched joins the pair across its longest edge that is still a pair.
  for (int k = 0; k < count; ++k) {
    if (mate[static_cast<size_t>(k)] >= 0) continue;
    int host = -1;
    double host_edge = -1.0;
    for (const Neighbour& n : near[static_cast<size_t>(k)]) {
      if (n.zone < 0 || mate[static_cast<size_t>(n.zone)] < 0) continue;
      if (others[static_cast<size_t>(n.zone)][1] >= 0) continue;  // already three
      if (n.edge > host_edge) host = n.zone, host_edge = n.edge;
    }
    if (host < 0) continue;
    const int partner = mate[static_cast<size_t>(host)];
    others[static_cast<size_t>(host)][1] = k;
    others[static_cast<size_t>(partner)][1] = k;
    others[static_cast<size_t>(k)] = {host, partner};
  }
  return others;
}

}  // namespace edem
