// Bolts tied to the rock: host zones found in the current configuration through a bucket grid,
// the grout's reaction gathered by the rock's nodes in a fixed order (the same bits for any
// thread count), the bolt nodes integrated along their axes.
#include "bolt/bolt_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

size_t at(int i) { return static_cast<size_t>(i); }

// A zone the bolts can be tied to: rock in place.
bool rock_zone(const Mechanics& m, int z) {
  const int material = m.zone_material[at(z)];
  return material >= 0 && !zone_law(m.params[at(material)].model).is_void && m.zone_excavated[at(z)] == 0;
}

// A bolt node tied to a zone that is no longer rock (its rock excavated or mucked out since it was
// tied; an untied node, on the free length outside the rock, has nothing to lose).
bool rock_gone_at(const Mechanics& m, int node) {
  const int z = m.bolt_hosts.zone[at(node)];
  return z >= 0 && !rock_zone(m, z);
}

// Where points are looked for: as the model was drawn (the mesh's positions, the frame of every
// point a script gives: regions, gp_near, zone_at, bolt{}'s ends), or as the rock stands now.
enum class Frame { drawn, now };

Vec2 node_at(const Mechanics& m, int n, Frame frame) {
  if (frame == Frame::drawn) return {m.position[2 * at(n)], m.position[2 * at(n) + 1]};
  return {m.origin[2 * at(n)] + m.u[2 * at(n)], m.origin[2 * at(n) + 1] + m.u[2 * at(n) + 1]};
}

Vec2 node_u(const Mechanics& m, int n) { return {m.u[2 * at(n)], m.u[2 * at(n) + 1]}; }

// Barycentric coordinates of p in zone z.
std::array<double, 3> barycentric(const Mechanics& m, int z, Vec2 p, Frame frame) {
  const auto& node = m.geometry[at(z)].node;
  const Vec2 a = node_at(m, node[0], frame), b = node_at(m, node[1], frame), c = node_at(m, node[2], frame);
  const double twice = cross(b - a, c - a);
  return {cross(b - p, c - p) / twice, cross(c - p, a - p) / twice, cross(a - p, b - p) / twice};
}

// The point of zone z nearest to p, as barycentric weights, and its distance from p.
std::pair<std::array<double, 3>, double> nearest_in(const Mechanics& m, int z, Vec2 p, Frame frame) {
  const std::array<double, 3> w = barycentric(m, z, p, frame);
  if (std::min({w[0], w[1], w[2]}) >= 0.0) return {w, 0.0};
  const auto& node = m.geometry[at(z)].node;
  const Vec2 corner[3] = {node_at(m, node[0], frame), node_at(m, node[1], frame), node_at(m, node[2], frame)};
  std::array<double, 3> best{};
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const Vec2 a = corner[i], b = corner[(i + 1) % 3], ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    const double distance = norm(a + t * ab - p);
    if (distance < best_distance) {
      best_distance = distance;
      best = {};
      best[at(i)] = 1.0 - t;
      best[at((i + 1) % 3)] = t;
    }
  }
  return {best, best_distance};
}

struct Hit {
  int zone = -1;
  std::array<double, 3> weight{};
};

// Rock zones bucketed by their bounding boxes in one frame.
class ZoneGrid {
 public:
  ZoneGrid(const Mechanics& m, Frame frame) : m_(m), frame_(frame) {
    double area = 0.0;
    std::vector<int> zones;
    lo_ = {INFINITY, INFINITY};
    Vec2 hi{-INFINITY, -INFINITY};
    for (int z = 0; z < static_cast<int>(m.geometry.size()); ++z) {
      if (!rock_zone(m, z)) continue;
      zones.push_back(z);
      area += m.geometry[at(z)].area;
      for (const int n : m.geometry[at(z)].node) {
        const Vec2 p = node_at(m, n, frame);
        lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
      }
    }
    if (zones.empty()) return;
    // About two zones per cell, and no more cells than zones.
    cell_ = std::sqrt(2.0 * area / static_cast<double>(zones.size()));
    nx_ = std::max(1, static_cast<int>((hi.x - lo_.x) / cell_) + 1);
    ny_ = std::max(1, static_cast<int>((hi.y - lo_.y) / cell_) + 1);
    first_.assign(at(nx_ * ny_) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill(first_.begin(), first_.end() - 1);
      for (const int z : zones) {
        const auto [x0, y0, x1, y1] = box(z);
        for (int j = y0; j <= y1; ++j)
          for (int i = x0; i <= x1; ++i) {
            if (pass == 0)
              ++first_[at(j * nx_ + i) + 1];
            else
              list_[at(fill[at(j * nx_ + i)]++)] = z;
          }
      }
      if (pass == 0) {
        for (size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
        list_.assign(at(first_.back()), 0);
      }
    }
    zone_size_ = cell_ / std::sqrt(2.0);
  }

  // The rock zone holding p; or the nearest one within `reach` [m] (p then taken to the
  // nearest point of it: a bolt's head on a wall that has moved a little). zone -1: none.
  Hit locate(Vec2 p, double reach) const {
    Hit hit;
    if (first_.empty()) return hit;
    const int ci = cell_index(p.x - lo_.x, nx_), cj = cell_index(p.y - lo_.y, ny_);
    double best = INFINITY;
    const int ring = std::max(1, static_cast<int>(std::ceil(reach / cell_)));
    for (int j = std::max(0, cj - ring); j <= std::min(ny_ - 1, cj + ring); ++j)
      for (int i = std::max(0, ci - ring); i <= std::min(nx_ - 1, ci + ring); ++i)
        for (int k = first_[at(j * nx_ + i)]; k < first_[at(j * nx_ + i) + 1]; ++k) {
          const int z = list_[at(k)];
          const auto [w, distance] = nearest_in(m_, z, p, frame_);
          if (distance < best || (distance == best && z < hit.zone)) {
            best = distance;
            hit = {z, w};
          }
        }
    if (!(best <= reach)) return {};
    return hit;
  }

  double zone_size() const { return zone_size_; }

 private:
  int cell_index(double offset, int count) const {
    return std::clamp(static_cast<int>(std::floor(offset / cell_)), 0, count - 1);
  }
  std::array<int, 4> box(int z) const {
    Vec2 a{INFINITY, INFINITY}, b{-INFINITY, -INFINITY};
    for (const int n : m_.geometry[at(z)].node) {
      const Vec2 p = node_at(m_, n, frame_);
      a = {std::min(a.x, p.x), std::min(a.y, p.y)};
      b = {std::max(b.x, p.x), std::max(b.y, p.y)};
    }
    return {cell_index(a.x - lo_.x, nx_), cell_index(a.y - lo_.y, ny_), cell_index(b.x - lo_.x, nx_),
            cell_index(b.y - lo_.y, ny_)};
  }

  const Mechanics& m_;
  Frame frame_;
  Vec2 lo_;
  double cell_ = 1.0, zone_size_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> first_, list_;
};

// How far outside the rock a bolt node may be given and still be tied to it: a fraction of the
// zone's size, for heads placed on a wall that has moved since the outline was drawn.
constexpr double kReachOfZone = 0.25;

double reach_of(const Mechanics& m, int zone) {
  return kReachOfZone * std::sqrt(2.0 * m.geometry[at(zone)].area);
}

Vec2 host_point_u(const Mechanics& m, int zone, const std::array<double, 3>& w) {
  const auto& node = m.geometry[at(zone)].node;
  return w[0] * node_u(m, node[0]) + w[1] * node_u(m, node[1]) + w[2] * node_u(m, node[2]);
}

// A bolt whose ground is gone: no grout, no segments, nothing moves.
void retire(Mechanics& m, int bolt) {
  BoltSet& set = m.bolts;
  BoltHosts& h = m.bolt_hosts;
  h.removed[at(bolt)] = 1;
  h.head_force[at(bolt)] = 0.0;
  for (int i = set.bolt_first_node[at(bolt)]; i < set.bolt_first_node[at(bolt) + 1]; ++i) {
    h.zone[at(i)] = -1;
    h.rate[at(i)] = 0.0;
    set.nodes.grout_stiffness[at(i)] = 0.0;
    set.nodes.grout_strength[at(i)] = 0.0;
    set.nodes.grout_force[at(i)] = 0.0;
    set.nodes.force[at(i)] = {};
  }
  for (int s = set.bolt_first_segment[at(bolt)]; s < set.bolt_first_segment[at(bolt) + 1]; ++s) {
    set.segments.force[at(s)] = 0.0;
    set.segments.state[at(s)] = SegmentState::removed;
  }
}

// Where a bolt's rock is gone (dug out, or a fallen block mucked away), the nodes tied to it let
// go and the segments that reach them, broken or not, are removed with that rock: they carry
// nothing, and keep the direction they had. The rest of the bolt, grouted in the rock still there,
// holds what it holds, as a bolt whose head block has fallen still pins the blocks behind it. A
// bolt with no node left in rock goes out of service whole.
void cut_where_the_rock_is_gone(Mechanics& m, int bolt) {
  BoltSet& set = m.bolts;
  BoltHosts& h = m.bolt_hosts;
  BoltNodes& n = set.nodes;
  BoltSegments& g = set.segments;
  const int head = set.bolt_first_node[at(bolt)];
  std::vector<char> gone(at(set.bolt_first_node[at(bolt) + 1] - head), 0);
  bool any = false;
  for (int i = head; i < set.bolt_first_node[at(bolt) + 1]; ++i) {
    if (!rock_gone_at(m, i)) continue;
    gone[at(i - head)] = 1;
    any = true;
    h.zone[at(i)] = -1;
    h.rate[at(i)] = 0.0;
    n.grout_stiffness[at(i)] = n.grout_strength[at(i)] = n.grout_force[at(i)] = 0.0;
    n.force[at(i)] = {};
  }
  if (!any) return;
  const int first_segment = set.bolt_first_segment[at(bolt)];
  for (int s = first_segment; s < set.bolt_first_segment[at(bolt) + 1]; ++s)
    if (gone[at(g.a[at(s)] - head)] || gone[at(g.b[at(s)] - head)]) {
      g.force[at(s)] = 0.0;
      g.state[at(s)] = SegmentState::removed;
    }
  if (g.state[at(first_segment)] == SegmentState::removed) {  // the head is no longer on the bolt
    h.drive[at(bolt)] = HeadDrive::none;
    h.drive_value[at(bolt)] = 0.0;
    h.head_force[at(bolt)] = 0.0;
  }
  bool in_rock = false;
  for (int i = head; i < set.bolt_first_node[at(bolt) + 1]; ++i)
    in_rock = in_rock || h.zone[at(i)] >= 0;
  if (!in_rock) retire(m, bolt);
}

// The force on node `node` of bolt `b` along the direction it slides in (towards the bolt's end),
// with the pull of a force-driven head [N/m].
double axial_force(const Mechanics& m, int b, int node) {
  const BoltHosts& h = m.bolt_hosts;
  double force = dot(m.bolts.nodes.force[at(node)], h.dir[at(node)]);
  if (node == m.bolts.bolt_first_node[at(b)] && h.drive[at(b)] == HeadDrive::force) force -= h.drive_value[at(b)];
  return force;
}

// A jack drives this node: it moves as told, whatever its forces.
bool driven(const Mechanics& m, int b, int node) {
  return node == m.bolts.bolt_first_node[at(b)] && m.bolt_hosts.drive[at(b)] == HeadDrive::velocity;
}

// A bolt's nodes, laid out along the points as drawn, moved to where their material points are
// now (a node without one, on the free tail outside the rock, moves as its nearest hosted node),
// its segments stress-free at their lengths there.
void lay_where_the_rock_is(Mechanics& m, int bolt, const std::vector<Hit>& hits) {
  BoltSet& set = m.bolts;
  BoltNodes& n = set.nodes;
  const size_t first = at(set.bolt_first_node[at(bolt)]), count = hits.size();
  std::vector<Vec2> shift(count);
  std::vector<char> known(count, 0);
  for (size_t i = 0; i < count; ++i) {
    if (hits[i].zone < 0) continue;
    const auto& node = m.geometry[at(hits[i].zone)].node;
    Vec2 now{};
    for (int c = 0; c < 3; ++c) now = now + hits[i].weight[at(c)] * node_at(m, node[at(c)], Frame::now);
    shift[i] = now - n.x[first + i];
    known[i] = 1;
  }
  for (size_t i = 0; i < count; ++i) {
    if (known[i]) continue;
    size_t best = count;
    for (size_t j = 0; j < count; ++j)
      if (known[j] && (best == count || (j > i ? j - i : i - j) < (best > i ? best - i : i - best))) best = j;
    if (best < count) shift[i] = shift[best];
  }
  for (size_t i = 0; i < count; ++i) n.x[first + i] = n.x[first + i] + shift[i];
  BoltSegments& g = set.segments;
  for (int s = set.bolt_first_segment[at(bolt)]; s < set.bolt_first_segment[at(bolt) + 1]; ++s) {
    const Vec2 d = n.x[at(g.b[at(s)])] - n.x[at(g.a[at(s)])];
    g.rest[at(s)] = norm(d);
    g.direction[at(s)] = (1.0 / norm(d)) * d;
  }
  update_axes(set);  // the other bolts' are what their last cycle made them anyway
}

}  // namespace

int install_bolt(Mechanics& m, const BoltLine& given, int material) {
  // Lay the bolt out on its own first: nothing changes in the model if a node is not in rock.
  BoltSet alone;
  alone.laws = {m.bolts.laws[at(material)]};
  BoltLine line = given;
  line.material = 0;
  add_bolt(alone, line);
  const ZoneGrid grid(m, Frame::drawn);
  const size_t count = alone.nodes.size();
  std::vector<Hit> hits(count);
  for (size_t i = 0; i < count; ++i) {
    const Vec2 p = alone.nodes.x[i];
    hits[i] = grid.locate(p, kReachOfZone * grid.zone_size());
    if (hits[i].zone >= 0 && nearest_in(m, hits[i].zone, p, Frame::drawn).second > reach_of(m, hits[i].zone))
      hits[i] = {};
    if (hits[i].zone < 0 && alone.nodes.bond_length[i] > 0.0)
      fail("the bolt's point ({:.6g}, {:.6g}), {:.4g} m from its head, is not in the rock (outside the "
           "model, or in excavated or null zones): a grouted bolt must lie in rock",
           p.x, p.y, norm(p - given.head));
  }
  line.material = material;
  const int bolt = add_bolt(m.bolts, line);
  lay_where_the_rock_is(m, bolt, hits);
  BoltHosts& h = m.bolt_hosts;
  const size_t first = at(m.bolts.bolt_first_node[at(bolt)]);
  for (size_t i = 0; i < count; ++i) {
    h.zone.push_back(hits[i].zone);
    h.weight.push_back(hits[i].weight);
    h.u0.push_back(hits[i].zone >= 0 ? host_point_u(m, hits[i].zone, hits[i].weight) : Vec2{});
    h.host_u.push_back({});
    h.slide.push_back(0.0);
    h.dir.push_back(m.bolts.nodes.axis[first + i]);
    h.rate.push_back(0.0);
    h.mass.push_back(0.0);
  }
  h.material.push_back(material);
  h.stage.push_back(m.stage);
  h.removed.push_back(0);
  h.drive.push_back(HeadDrive::none);
  h.drive_value.push_back(0.0);
  h.head_force.push_back(0.0);
  m.dirty = true;
  return bolt;
}

bool head_on_bolt(const Mechanics& m, int bolt) {
  const BoltSet& set = m.bolts;
  const BoltHosts& h = m.bolt_hosts;
  const int first = set.bolt_first_segment[at(bolt)];
  if (h.removed[at(bolt)] || set.segments.state[at(first)] == SegmentState::removed) return false;
  return !rock_gone_at(m, set.segments.a[at(first)]) && !rock_gone_at(m, set.segments.b[at(first)]);
}

void tie_bolts(Mechanics& m) {
  BoltSet& set = m.bolts;
  BoltHosts& h = m.bolt_hosts;
  for (int b = 0; b < set.bolts(); ++b)
    if (!h.removed[at(b)]) cut_where_the_rock_is_gone(m, b);
  const size_t nodes = static_cast<size_t>(m.node_count);
  h.gather_first.assign(nodes + 1, 0);
  h.rows.assign(nodes, 0.0);
  // The rock carries the segments' pulls on the nodes it hosts as well as their grout's
  // (add_bolt_forces): their stiffness, a node's row, goes into its host's rows.
  const std::vector<double> k = bolt_node_stiffness(set);
  for (size_t i = 0; i < set.nodes.size(); ++i) {
    if (h.zone[i] < 0) continue;
    const auto& node = m.geometry[at(h.zone[i])].node;
    for (int c = 0; c < 3; ++c) {
      ++h.gather_first[at(node[at(c)]) + 1];
      h.rows[at(node[at(c)])] += std::fabs(h.weight[i][at(c)]) * k[i];
    }
  }
  for (size_t n = 0; n < nodes; ++n) h.gather_first[n + 1] += h.gather_first[n];
  h.gather.assign(at(h.gather_first.back()), 0);
  std::vector<int> fill(h.gather_first.begin(), h.gather_first.end() - 1);
  for (size_t i = 0; i < set.nodes.size(); ++i) {
    if (h.zone[i] < 0) continue;
    const auto& node = m.geometry[at(h.zone[i])].node;
    for (int c = 0; c < 3; ++c) h.gather[at(fill[at(node[at(c)])]++)] = static_cast<int>(3 * i) + c;
  }
}

double bolt_masses(Mechanics& m, bool dynamic, double amplification, double fraction) {
  const BoltSet& set = m.bolts;
  BoltHosts& h = m.bolt_hosts;
  const std::vector<double> k = bolt_node_stiffness(set);
  double critical = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < k.size(); ++i) {
    if (!(k[i] > 0.0)) {
      h.mass[i] = 0.0;  // nothing to move against: it stays where it is
      continue;
    }
    critical = std::min(critical, 2.0 * std::sqrt(set.nodes.mass[i] / k[i]));
    h.mass[i] = dynamic ? set.nodes.mass[i] : amplification * k[i] / (4.0 * fraction * fraction);
  }
  h.critical_step = critical;
  return critical;
}

void bolt_cycle(Mechanics& m, const Motion& motion, bool record_start, bool measure, Measure& out) {
  BoltSet& set = m.bolts;
  BoltHosts& h = m.bolt_hosts;
  BoltNodes& n = set.nodes;
  const size_t count = n.size();
  if (count == 0) return;
  if (h.slide_start.size() != count) {
    h.slide_start = h.slide;
    h.r_start.assign(count, 0.0);
  }
  for (size_t i = 0; i < count; ++i) {
    if (h.zone[i] >= 0) h.host_u[i] = host_point_u(m, h.zone[i], h.weight[i]) - h.u0[i];
    n.u[i] = h.host_u[i] + h.slide[i] * h.dir[i];
  }
  m.energy.bolt_plastic += bolt_forces(set, h.host_u);

  double unbalanced = 0.0, applied = 0.0, kinetic = 0.0, num = 0.0, den = 0.0;
  bool finite = true;
  for (int b = 0; b < set.bolts(); ++b) {
    if (h.removed[at(b)]) continue;
    const int head = set.bolt_first_node[at(b)];
    for (int node = head; node < set.bolt_first_node[at(b) + 1]; ++node) {
      const size_t i = at(node);
      const double force = axial_force(m, b, node);
      const double internal = dot(n.force[i], h.dir[i]);  // the segments' and the grout's; the rest a head's pull
      if (node == head)
        h.head_force[at(b)] = h.drive[at(b)] == HeadDrive::velocity ? force
                              : h.drive[at(b)] == HeadDrive::force
                                  ? h.drive_value[at(b)]
                                  : set.segments.force[at(set.bolt_first_segment[at(b)])];
      double& rate = h.rate[i];
      if (driven(m, b, node)) {
        rate = -h.drive_value[at(b)];
        m.energy.by_bolts += internal * rate * motion.dt;
        m.energy.boundary -= internal * rate * motion.dt;  // the jack holds it against them
      } else if (h.mass[i] > 0.0) {
        if (record_start) h.r_start[i] = force;
        const double before = rate;
        if (motion.local) {
          const double damped = force - motion.alpha * std::fabs(force) * (rate > 0.0 ? 1.0 : rate < 0.0 ? -1.0 : 0.0);
          rate += motion.dt * damped / h.mass[i];
        } else {
          rate = motion.keep * rate + motion.push * force / h.mass[i];
        }
        const double step = 0.5 * (before + rate) * motion.dt;
        m.energy.by_bolts += internal * step;
        m.energy.boundary += (force - internal) * step;
        if (motion.damped) m.energy.damping += force * step - 0.5 * h.mass[i] * (rate * rate - before * before);
        if (measure) {
          unbalanced += std::fabs(force);
          const double ds = h.slide[i] - h.slide_start[i];  // where `force` was found
          num += ds * (h.r_start[i] - force);
          den += h.mass[i] * ds * ds;
          kinetic += 0.5 * h.mass[i] * rate * rate;
          finite = finite && std::isfinite(force) && std::isfinite(rate);
        }
      } else {
        rate = 0.0;
      }
      h.slide[i] += motion.dt * rate;
      if (measure) applied += std::fabs(n.grout_force[i]);
    }
    if (measure)
      for (int s = set.bolt_first_segment[at(b)]; s < set.bolt_first_segment[at(b) + 1]; ++s)
        applied += 2.0 * std::fabs(set.segments.force[at(s)]);
  }
  if (measure) {
    out.unbalanced += unbalanced;
    out.applied += applied;
    out.kinetic += kinetic;
    out.rayleigh_num += num;
    out.rayleigh_den += den;
    out.finite = out.finite && finite;
  }
}

void measure_bolts(const Mechanics& m, Measure& out) {
  const BoltSet& set = m.bolts;
  const BoltHosts& h = m.bolt_hosts;
  for (int b = 0; b < set.bolts(); ++b) {
    if (h.removed[at(b)]) continue;
    for (int node = set.bolt_first_node[at(b)]; node < set.bolt_first_node[at(b) + 1]; ++node) {
      const size_t i = at(node);
      if (!driven(m, b, node) && h.mass[i] > 0.0) out.unbalanced += std::fabs(axial_force(m, b, node));
      out.applied += std::fabs(set.nodes.grout_force[i]);
    }
    for (int s = set.bolt_first_segment[at(b)]; s < set.bolt_first_segment[at(b) + 1]; ++s)
      out.applied += 2.0 * std::fabs(set.segments.force[at(s)]);
  }
}

bool rehost_bolts(Mechanics& m) {
  BoltSet& set = m.bolts;
  BoltHosts& h = m.bolt_hosts;
  BoltNodes& n = set.nodes;
  std::unique_ptr<ZoneGrid> grid;  // built only if a node has left its zone
  bool moved = false;
  for (size_t i = 0; i < n.size(); ++i) {
    if (h.zone[i] < 0 || (n.bond_length[i] > 0.0 && n.grout_stiffness[i] == 0.0)) continue;  // none, or out
    // Still within reach of its host zone (inside it, or just outside the rock's edge as a
    // head at a wall is): nothing to do, and no search (this runs every batch).
    const Vec2 p = n.x[i] + n.u[i];
    const double reach = reach_of(m, h.zone[i]);
    if (nearest_in(m, h.zone[i], p, Frame::now).second <= reach) continue;
    if (!grid) grid = std::make_unique<ZoneGrid>(m, Frame::now);
    const Hit hit = grid->locate(p, reach);
    if (hit.zone == h.zone[i]) continue;
    moved = true;
    if (hit.zone < 0) {
      // Pulled out of the hole: nothing to grip. Across the axis it still follows its last
      // host point, the rock at the hole's mouth.
      if (n.grout_stiffness[i] > 0.0)  // what its grout held is lost with it
        m.energy.bolt_plastic += n.grout_force[i] * n.grout_force[i] / (2.0 * n.grout_stiffness[i]);
      n.grout_stiffness[i] = n.grout_strength[i] = n.grout_force[i] = 0.0;
      continue;
    }
    // The point it is at now becomes its host, with nothing slid against it yet.
    h.zone[i] = hit.zone;
    h.weight[i] = hit.weight;
    h.u0[i] = host_point_u(m, hit.zone, hit.weight) - n.u[i];
    h.host_u[i] = n.u[i];
    if (h.slide_start.size() == n.size()) h.slide_start[i] -= h.slide[i];
    h.slide[i] = 0.0;
    h.dir[i] = n.axis[i];
    n.grout_rel[i] = {};
  }
  return moved;
}

void reset_bolt_displacements(Mechanics& m) {
  BoltHosts& h = m.bolt_hosts;
  for (size_t i = 0; i < h.zone.size(); ++i)
    if (h.zone[i] >= 0) h.u0[i] = h.u0[i] - host_point_u(m, h.zone[i], h.weight[i]);
}

void start_bolt_damping(Mechanics& m) {
  m.bolt_hosts.slide_start = m.bolt_hosts.slide;
  m.bolt_hosts.r_start.assign(m.bolt_hosts.slide.size(), 0.0);
}

}  // namespace edem
