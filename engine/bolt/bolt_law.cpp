// The bolt laws and their loops over a BoltSet. Each loop is a plain pass over flat arrays: the
// segments (force from the current length), then the nodes (axis, grout), then the nodes again
// (sum of forces). Nothing here allocates during a cycle.
#include "bolt/bolt_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace edem {
namespace {

void check_positive(double value, const char* key, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0))
    fail("{} must be a finite number > 0 [{}], got {}", key, unit, value);
}

size_t index(int i) {
  return static_cast<size_t>(i);
}

}  // namespace

void check_bolt_params(const BoltParams& p) {
  check_positive(p.young, "young", "Pa");
  check_positive(p.area, "area", "m^2");
  check_positive(p.density, "density", "kg/m^3");
  check_positive(p.yield_tension, "yield_tension", "N");
  check_positive(p.yield_compression, "yield_compression", "N");
  check_positive(p.failure_strain, "failure_strain", "-");
  check_positive(p.bond_stiffness, "bond_stiffness", "N/m per m of bolt");
  check_positive(p.bond_strength, "bond_strength", "N/m");
  check_positive(p.spacing, "spacing", "m");
}

BoltLaw bolt_law(const BoltParams& p) {
  check_bolt_params(p);
  BoltLaw law;
  law.ea = p.young * p.area / p.spacing;
  law.yield_tension = p.yield_tension / p.spacing;
  law.yield_compression = p.yield_compression / p.spacing;
  law.failure_strain = p.failure_strain;
  law.bond_stiffness = p.bond_stiffness / p.spacing;
  law.bond_strength = p.bond_strength / p.spacing;
  law.line_mass = p.density * p.area / p.spacing;
  return law;
}

SegmentUpdate segment_law(const BoltLaw& law, double rest, double force, SegmentState state,
                          double elongation_old, double elongation_new) {
  if (!carries(state)) return {0.0, state};
  if (elongation_new > law.failure_strain * rest) return {0.0, SegmentState::broken};
  SegmentUpdate out{force + law.ea / rest * (elongation_new - elongation_old), state};
  if (out.force > law.yield_tension) {
    out.force = law.yield_tension;
    out.state = SegmentState::yielded;
  } else if (out.force < -law.yield_compression) {
    out.force = -law.yield_compression;
    out.state = SegmentState::yielded;
  }
  return out;
}

GroutUpdate grout_law(double stiffness, double strength, double force, double slip, double ds) {
  if (stiffness <= 0.0) return {0.0, slip, false};
  const double trial = force + stiffness * ds;
  if (std::fabs(trial) <= strength) return {trial, slip, false};
  const double held = std::copysign(strength, trial);
  // What the spring did not take is plastic slip.
  return {held, slip + ds - (held - force) / stiffness, true};
}

int add_bolt(BoltSet& set, const BoltLine& line) {
  if (line.segments < 1) fail("a bolt needs at least 1 grouted segment, got {}", line.segments);
  if (line.material < 0 || index(line.material) >= set.laws.size())
    fail("bolt material {} does not exist ({} defined)", line.material, set.laws.size());
  const Vec2 along = line.end - line.head;
  const double length = norm(along);
  if (!(std::isfinite(length) && length > 0.0))
    fail("a bolt needs two distinct ends, got ({}, {}) and ({}, {})", line.head.x, line.head.y,
         line.end.x, line.end.y);
  if (!(std::isfinite(line.free_length) && line.free_length >= 0.0 && line.free_length < length))
    fail("free_length must be in [0, {}) m (the bolt's length), got {}", length, line.free_length);
  const BoltLaw& law = set.laws[index(line.material)];
  const Vec2 axis = (1.0 / length) * along;
  const bool free = line.free_length > 0.0;
  const double grouted = length - line.free_length;
  const double dx = grouted / line.segments;

  // Node positions along the bolt, from the head.
  std::vector<double> s;
  if (free) s.push_back(0.0);
  for (int i = 0; i <= line.segments; ++i) s.push_back(line.free_length + dx * i);
  s.back() = length;

  BoltNodes& n = set.nodes;
  BoltSegments& g = set.segments;
  const int first = static_cast<int>(n.size());
  const size_t count = s.size();
  for (size_t i = 0; i < count; ++i) {
    const double before = i > 0 ? s[i] - s[i - 1] : 0.0;
    const double after = i + 1 < count ? s[i + 1] - s[i] : 0.0;
    const double bonded_before = free && i == 1 ? 0.0 : before;  // the free segment has no grout
    const double bonded_after = free && i == 0 ? 0.0 : after;
    const double tributary = 0.5 * (before + after);
    const double bond = 0.5 * (bonded_before + bonded_after);
    n.x.push_back(line.head + s[i] * axis);
    n.u.push_back({});
    n.v.push_back({});
    n.force.push_back({});
    n.mass.push_back(law.line_mass * tributary);
    n.tributary.push_back(tributary);
    n.bond_length.push_back(bond);
    n.grout_stiffness.push_back(law.bond_stiffness * bond);
    n.grout_strength.push_back(law.bond_strength * bond);
    n.axis.push_back(axis);
    n.grout_force.push_back(0.0);
    n.grout_slip.push_back(0.0);
    n.slipping.push_back(0);
    n.grout_rel.push_back({});
    if (i > 0) {
      g.a.push_back(first + static_cast<int>(i) - 1);
      g.b.push_back(first + static_cast<int>(i));
      g.material.push_back(line.material);
      g.rest.push_back(before);
      g.elongation.push_back(0.0);
      g.direction.push_back(axis);
      g.force.push_back(0.0);
      g.state.push_back(SegmentState::elastic);
      g.broke.push_back(0);
    }
  }
  set.bolt_first_node.push_back(static_cast<int>(n.size()));
  set.bolt_first_segment.push_back(static_cast<int>(g.size()));
  return set.bolts() - 1;
}

double update_segments(BoltSet& set) {
  const BoltNodes& n = set.nodes;
  BoltSegments& g = set.segments;
  double dissipated = 0.0;
  for (size_t s = 0; s < g.size(); ++s) {
    // Its rock is gone and an end no longer moves: it keeps the direction it had when cut.
    if (g.state[s] == SegmentState::removed) continue;
    const size_t a = index(g.a[s]), b = index(g.b[s]);
    const Vec2 d = (n.x[b] + n.u[b]) - (n.x[a] + n.u[a]);
    const double length = norm(d);
    g.direction[s] = (1.0 / length) * d;
    const double elongation = length - g.rest[s];
    if (!carries(g.state[s])) {  // its force stays 0
      g.elongation[s] = elongation;
      continue;
    }
    const BoltLaw& law = set.laws[index(g.material[s])];
    const SegmentUpdate up = segment_law(law, g.rest[s], g.force[s], g.state[s], g.elongation[s], elongation);
    // Its mid-step work less the change of what it stores (elastic: nothing; broken: all it had).
    if (up.state != SegmentState::elastic)
      dissipated += 0.5 * (g.force[s] + up.force) * (elongation - g.elongation[s]) -
                    (up.force * up.force - g.force[s] * g.force[s]) * g.rest[s] / (2.0 * law.ea);
    g.force[s] = up.force;
    g.state[s] = up.state;
    if (up.state == SegmentState::broken) g.broke[s] = 1;
    g.elongation[s] = elongation;
  }
  return dissipated;
}

void update_axes(BoltSet& set) {
  BoltNodes& n = set.nodes;
  const BoltSegments& g = set.segments;
  std::fill(n.axis.begin(), n.axis.end(), Vec2{});
  // From the segments not cut (a cut one's far end stays where it was, and the rock may move past
  // it); a node with none left, which carries nothing, takes a cut one's direction as it was.
  for (size_t s = 0; s < g.size(); ++s) {
    if (g.state[s] == SegmentState::removed) continue;
    for (const size_t i : {index(g.a[s]), index(g.b[s])}) n.axis[i] = n.axis[i] + g.direction[s];
  }
  for (size_t s = 0; s < g.size(); ++s) {
    if (g.state[s] != SegmentState::removed) continue;
    for (const size_t i : {index(g.a[s]), index(g.b[s])})
      if (n.axis[i] == Vec2{}) n.axis[i] = g.direction[s];
  }
  for (size_t i = 0; i < n.size(); ++i) n.axis[i] = (1.0 / norm(n.axis[i])) * n.axis[i];
}

double update_grout(BoltSet& set, std::span<const Vec2> host_u) {
  BoltNodes& n = set.nodes;
  double dissipated = 0.0;
  if (host_u.size() != n.size())
    fail("bolt grout: {} host displacements for {} bolt nodes", host_u.size(), n.size());
  update_axes(set);
  for (size_t i = 0; i < n.size(); ++i) {
    const Vec2 rel = n.u[i] - host_u[i];
    const double ds = dot(rel - n.grout_rel[i], n.axis[i]);
    n.grout_rel[i] = rel;
    const GroutUpdate up =
        grout_law(n.grout_stiffness[i], n.grout_strength[i], n.grout_force[i], n.grout_slip[i], ds);
    if (up.slipping)  // its mid-step work less the change of what it stores
      dissipated += 0.5 * (n.grout_force[i] + up.force) * ds -
                    (up.force * up.force - n.grout_force[i] * n.grout_force[i]) / (2.0 * n.grout_stiffness[i]);
    n.grout_force[i] = up.force;
    n.grout_slip[i] = up.slip;
    n.slipping[i] = up.slipping ? 1 : 0;
  }
  return dissipated;
}

void gather_node_forces(BoltSet& set) {
  BoltNodes& n = set.nodes;
  const BoltSegments& g = set.segments;
  for (size_t i = 0; i < n.size(); ++i) n.force[i] = -n.grout_force[i] * n.axis[i];
  for (size_t s = 0; s < g.size(); ++s) {
    const Vec2 pull = g.force[s] * g.direction[s];  // tension pulls a towards b, b towards a
    const size_t a = index(g.a[s]), b = index(g.b[s]);
    n.force[a] = n.force[a] + pull;
    n.force[b] = n.force[b] - pull;
  }
}

double bolt_forces(BoltSet& set, std::span<const Vec2> host_u) {
  const double dissipated = update_segments(set) + update_grout(set, host_u);
  gather_node_forces(set);
  return dissipated;
}

double bolt_energy(const BoltSet& set) {
  const BoltNodes& n = set.nodes;
  const BoltSegments& g = set.segments;
  double energy = 0.0;
  for (size_t s = 0; s < g.size(); ++s)
    if (carries(g.state[s]))
      energy += g.force[s] * g.force[s] * g.rest[s] / (2.0 * set.laws[index(g.material[s])].ea);
  for (size_t i = 0; i < n.size(); ++i)
    if (n.grout_stiffness[i] > 0.0) energy += n.grout_force[i] * n.grout_force[i] / (2.0 * n.grout_stiffness[i]);
  return energy;
}

std::vector<double> bolt_node_stiffness(const BoltSet& set) {
  const BoltNodes& n = set.nodes;
  const BoltSegments& g = set.segments;
  std::vector<double> k(n.size());
  for (size_t i = 0; i < n.size(); ++i) k[i] = 2.0 * n.grout_stiffness[i];
  for (size_t s = 0; s < g.size(); ++s) {
    if (!carries(g.state[s])) continue;
    const double twice = 2.0 * set.laws[index(g.material[s])].ea / g.rest[s];
    k[index(g.a[s])] += twice;
    k[index(g.b[s])] += twice;
  }
  return k;
}

double bolt_critical_step(const BoltSet& set) {
  const std::vector<double> k = bolt_node_stiffness(set);
  double step = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < k.size(); ++i)
    if (k[i] > 0.0) step = std::min(step, 2.0 * std::sqrt(set.nodes.mass[i] / k[i]));
  return step;
}

}  // namespace edem
