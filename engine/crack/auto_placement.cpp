#include "crack/auto_placement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <utility>

namespace edem {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Direction in [0, 180) [deg].
double as_direction(double angle) {
  double a = std::fmod(angle, 180.0);
  if (a < 0.0) a += 180.0;
  return a >= 180.0 ? 0.0 : a;
}

// Zones that share a corner's place, per zone (indices into `zones`).
std::vector<std::vector<size_t>> touching(const Mesh& mesh, const std::vector<YieldedZone>& zones) {
  std::map<std::pair<double, double>, std::vector<size_t>> at;
  for (size_t k = 0; k < zones.size(); ++k)
    for (int g : mesh.zone_gp[static_cast<size_t>(zones[k].zone)]) {
      const Vec2 p = mesh.gp_position[static_cast<size_t>(g)];
      at[{p.x, p.y}].push_back(k);
    }
  std::vector<std::vector<size_t>> out(zones.size());
  for (const auto& [place, list] : at)
    for (size_t a : list)
      for (size_t b : list)
        if (a != b) out[a].push_back(b);
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

// Area-weighted means of a region's principal direction (as axes), friction and centroid, and its
// mode: tension where its tension zones cover more than half its area.
void summarise(const Mesh& mesh, const std::vector<YieldedZone>& zones, const std::vector<size_t>& members,
               CrackRegion& region) {
  double c = 0.0, s = 0.0, friction = 0.0, area = 0.0, tension_area = 0.0;
  Vec2 moment;
  for (size_t k : members) {
    const double w = mesh.zone_area(zones[k].zone);
    if (zones[k].tension) tension_area += w;
    c += w * std::cos(2.0 * zones[k].angle * kDegree);
    s += w * std::sin(2.0 * zones[k].angle * kDegree);
    friction += w * zones[k].friction;
    moment = moment + w * mesh.zone_centroid(zones[k].zone);
    area += w;
    region.zones.push_back(zones[k].zone);
  }
  std::sort(region.zones.begin(), region.zones.end());
  double principal = 0.5 * std::atan2(s, c) / kDegree;  // (-90, 90]
  if (principal <= -90.0) principal += 180.0;
  region.principal = principal;
  region.friction = friction / area;
  region.origin = (1.0 / area) * moment;
  region.tension = tension_area > 0.5 * area;
}

// Mean edge length of the zones [m].
double mean_edge(const Mesh& mesh, const std::vector<int>& zones) {
  double sum = 0.0;
  for (int z : zones) {
    const auto& gp = mesh.zone_gp[static_cast<size_t>(z)];
    for (size_t i = 0; i < 3; ++i)
      sum += norm(mesh.gp_position[static_cast<size_t>(gp[(i + 1) % 3])] - mesh.gp_position[static_cast<size_t>(gp[i])]);
  }
  return zones.empty() ? 0.0 : sum / (3.0 * static_cast<double>(zones.size()));
}

// A cut ends on an outline edge, but rounded, never exactly on it: the cutter would see a gap and
// drop the cut as ending inside a block. So every outline edge (each once over all regions: regions
// that touch share edges) is split at the cut ends that lie on it, and the ends are its vertices.
void split_outlines_at_cut_ends(std::vector<CrackRegion>& regions) {
  struct Edge {
    Vec2 a, b;
    size_t owner;
    std::vector<std::pair<double, Vec2>> at;  // the cut ends on it, by their fraction of a -> b
  };
  std::vector<Edge> edges;
  std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, size_t> seen;
  double size = 0.0;
  for (size_t r = 0; r < regions.size(); ++r) {
    for (const Cut& e : regions[r].outline) {
      auto p = std::make_pair(e[0].x, e[0].y), q = std::make_pair(e[1].x, e[1].y);
      if (q < p) std::swap(p, q);
      if (seen.emplace(std::make_pair(p, q), edges.size()).second) edges.push_back({e[0], e[1], r, {}});
      size = std::max({size, std::abs(e[0].x), std::abs(e[0].y)});
    }
    regions[r].outline.clear();
  }
  const double near = 1e-9 * std::max(size, 1.0);
  for (const CrackRegion& region : regions)
    for (const Cut& cut : region.cuts)
      for (const Vec2 end : cut)
        for (Edge& e : edges) {
          const Vec2 d = e.b - e.a;
          const double t = dot(end - e.a, d) / dot(d, d);
          const double length = norm(d);
          if (t * length <= near || (1.0 - t) * length <= near) continue;  // at a vertex, or beyond
          if (std::abs(cross(d, end - e.a)) / length <= near) e.at.push_back({t, end});
        }
  for (Edge& e : edges) {
    std::sort(e.at.begin(), e.at.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    Vec2 from = e.a;
    for (const auto& [t, to] : e.at) {
      if (to == from) continue;  // two cuts ending at one point
      regions[e.owner].outline.push_back({from, to});
      from = to;
    }
    regions[e.owner].outline.push_back({from, e.b});
  }
}

}  // namespace

double axis_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

std::vector<CrackRegion> group_yielded(const Mesh& mesh, const std::vector<YieldedZone>& zones,
                                       double similar, bool by_mode) {
  std::vector<size_t> order(zones.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return zones[a].zone < zones[b].zone; });
  const auto neighbours = touching(mesh, zones);
  std::vector<char> taken(zones.size(), 0);
  std::vector<CrackRegion> regions;
  for (size_t first : order) {
    if (taken[first]) continue;
    const YieldedZone& seed = zones[first];
    std::vector<size_t> members{first}, frontier{first};
    taken[first] = 1;
    while (!frontier.empty()) {
      const size_t k = frontier.back();
      frontier.pop_back();
      for (size_t n : neighbours[k]) {
        if (taken[n] || (by_mode && zones[n].tension != seed.tension) ||
            axis_difference(zones[n].angle, seed.angle) > similar)
          continue;
        taken[n] = 1;
        members.push_back(n);
        frontier.push_back(n);
      }
    }
    CrackRegion region;
    summarise(mesh, zones, members, region);
    regions.push_back(std::move(region));
  }
  return regions;
}

std::vector<double> crack_angles(bool tension, double principal, double friction) {
  const double plane = principal + 90.0;  // the major principal plane's trace
  if (tension) return {as_direction(plane), as_direction(plane + 90.0)};
  const double off = 45.0 + 0.5 * friction;
  return {as_direction(plane + off), as_direction(plane - off)};
}

std::vector<Cut> cuts_in_zones(const Mesh& mesh, const std::vector<int>& zones, double angle, double spacing,
                               Vec2 origin, double shortest) {
  const Vec2 along{std::cos(angle * kDegree), std::sin(angle * kDegree)};
  const Vec2 across{-along.y, along.x};
  // Per line (k: offset k x spacing from origin), the intervals of `along` inside each zone.
  std::map<long, std::vector<std::pair<double, double>>> pieces;
  double size = 0.0;
  for (int z : zones) {
    const auto& gp = mesh.zone_gp[static_cast<size_t>(z)];
    std::array<Vec2, 3> v;
    std::array<double, 3> s{}, t{};
    for (size_t i = 0; i < 3; ++i) {
      v[i] = mesh.gp_position[static_cast<size_t>(gp[i])] - origin;
      s[i] = dot(v[i], across);
      t[i] = dot(v[i], along);
      size = std::max({size, std::abs(s[i]), std::abs(t[i])});
    }
    const long k0 = static_cast<long>(std::ceil(std::min({s[0], s[1], s[2]}) / spacing));
    const long k1 = static_cast<long>(std::floor(std::max({s[0], s[1], s[2]}) / spacing));
    for (long k = k0; k <= k1; ++k) {
      const double c = static_cast<double>(k) * spacing;
      double lo = INFINITY, hi = -INFINITY;
      for (size_t i = 0; i < 3; ++i) {
        const size_t j = (i + 1) % 3;
        if ((s[i] - c) * (s[j] - c) > 0.0) continue;  // the edge does not reach the line
        const double at = s[i] == s[j] ? t[i] : t[i] + (c - s[i]) / (s[j] - s[i]) * (t[j] - t[i]);
        const double tj = s[i] == s[j] ? t[j] : at;
        lo = std::min({lo, at, tj});
        hi = std::max({hi, at, tj});
      }
      if (hi > lo) pieces[k].push_back({lo, hi});
    }
  }
  // Join the intervals of each line that meet (neighbouring zones share their edges).
  const double gap = 1e-9 * std::max(size, 1.0);
  std::vector<Cut> cuts;
  for (auto& [k, list] : pieces) {
    std::sort(list.begin(), list.end());
    const Vec2 base = origin + (static_cast<double>(k) * spacing) * across;
    auto emit = [&](double lo, double hi) {
      if (hi - lo >= shortest) cuts.push_back({base + lo * along, base + hi * along});
    };
    double lo = list.front().first, hi = list.front().second;
    for (const auto& [a, b] : list) {
      if (a > hi + gap) {
        emit(lo, hi);
        lo = a;
      }
      hi = std::max(hi, b);
    }
    emit(lo, hi);
  }
  return cuts;
}

std::vector<Cut> union_outline(const Mesh& mesh, const std::vector<int>& zones) {
  using Place = std::pair<double, double>;
  auto place = [&](int g) {
    const Vec2 p = mesh.gp_position[static_cast<size_t>(g)];
    return Place{p.x, p.y};
  };
  std::map<std::pair<Place, Place>, int> uses;  // by its two places, smaller first
  auto key = [&](int a, int b) {
    Place p = place(a), q = place(b);
    if (q < p) std::swap(p, q);
    return std::make_pair(p, q);
  };
  for (int z : zones) {
    const auto& gp = mesh.zone_gp[static_cast<size_t>(z)];
    for (size_t i = 0; i < 3; ++i) ++uses[key(gp[i], gp[(i + 1) % 3])];
  }
  // Edges on a block's boundary are cut already (a joint, a region outline, the model's edge).
  std::set<int> blocks;
  for (int z : zones)
    if (static_cast<size_t>(z) < mesh.zone_block.size()) blocks.insert(mesh.zone_block[static_cast<size_t>(z)]);
  for (int b : blocks) {
    if (static_cast<size_t>(b) >= mesh.block_boundary.size()) continue;
    for (const BoundaryLoop& loop : mesh.block_boundary[static_cast<size_t>(b)])
      for (size_t i = 0; i < loop.gridpoints.size(); ++i) {
        auto it = uses.find(key(loop.gridpoints[i], loop.gridpoints[(i + 1) % loop.gridpoints.size()]));
        if (it != uses.end()) it->second = 0;
      }
  }
  std::vector<Cut> out;
  for (int z : zones) {
    const auto& gp = mesh.zone_gp[static_cast<size_t>(z)];
    for (size_t i = 0; i < 3; ++i)
      if (uses[key(gp[i], gp[(i + 1) % 3])] == 1)
        out.push_back({mesh.gp_position[static_cast<size_t>(gp[i])], mesh.gp_position[static_cast<size_t>(gp[(i + 1) % 3])]});
  }
  return out;
}

std::vector<CrackRegion> place_cracks(const Mesh& mesh, const std::vector<YieldedZone>& zones,
                                      double spacing, double similar,
                                      const std::optional<Vec2>& origin, bool by_mode) {
  std::vector<CrackRegion> placed;
  for (CrackRegion& region : group_yielded(mesh, zones, similar, by_mode)) {
    const Vec2 centroid = region.origin;
    region.angles = crack_angles(region.tension, region.principal, region.friction);
    const double shortest = mean_edge(mesh, region.zones);
    const auto lay = [&](Vec2 through) {
      region.origin = through;
      for (double angle : region.angles) {
        const auto cuts = cuts_in_zones(mesh, region.zones, angle, spacing, through, shortest);
        region.cuts.insert(region.cuts.end(), cuts.begin(), cuts.end());
      }
    };
    lay(origin ? *origin : centroid);
    // A group that no line of the common grid crosses is still cut through its own centroid:
    // whether yielded rock gets potential cracks must not hang on where the grid falls.
    if (region.cuts.empty() && origin) lay(centroid);
    if (region.cuts.empty()) continue;
    region.outline = union_outline(mesh, region.zones);
    placed.push_back(std::move(region));
  }
  split_outlines_at_cut_ends(placed);
  return placed;
}

}  // namespace edem
