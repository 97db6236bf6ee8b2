// Contact detection: a cell grid over the blocks' boxes (broad phase), then each boundary
// gridpoint against the edges of the blocks whose box it is in (narrow phase). Gridpoints are
// done independently (in parallel) and the results joined in gridpoint order, so the list is
// the same for any thread count.
#include "contact/detect.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "contact/contact_force.hpp"
#include "contact/edge_choice.hpp"
#include "contact/facing_length.hpp"
#include "core/error.hpp"
#include "geom/polygon.hpp"
#include "state/insitu.hpp"

namespace edem {
namespace {

// Stiffness rows count each direction with this bound on |n_x| (|n_x| + |n_y|).
constexpr double kRowBound = 1.21;
// A block whose boundary has moved this fraction of the smallest reach since it was last marked
// has its contacts found again, with those of the blocks near it (refresh_contacts).
constexpr double kStaleMotion = 0.125;
// A half-edge over two blocks' faces whose quarter point is nearer to one than to the other by
// this fraction of the half-edge or more is the nearer's alone; nearer by less, the two share it
// (a face the half-edge does not face counts as further off: half_edge_parts).
constexpr double kShareBand = 0.5;
// A half-edge over a face that is not near the nearest takes a share of it only where it faces
// it: none where the cosine between their normals (one turned round) is below this, all of it
// where it is above twice this (60 and 0 deg); a face about as near as the nearest, as the
// nearest does (kNearestFacing).
constexpr double kShareFacing = 0.5;
// The nearest face takes all its share from this cosine up (89.4 deg), none once it is behind the
// half-edge (90 deg and beyond). Narrow: a half-edge's length over a face already falls as the
// square of the cosine (its projection, as far as it faces it), so the ramp is there only to keep
// the change of nearest continuous; wider, it would cut the length of a corner that runs into a
// face near edge on, and the stress on it would grow without need.
constexpr double kNearestFacing = 0.01;
// Edges whose outward normals are within 10 degrees face the same way.
const double kSameFacing = std::cos(10.0 * M_PI / 180.0);

struct Box {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  void add(Vec2 p) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  bool contains(Vec2 p, double slack) const {
    return p.x >= x0 - slack && p.x <= x1 + slack && p.y >= y0 - slack && p.y <= y1 + slack;
  }
};

Vec2 at(const Mechanics& m, int node) {
  const size_t n = static_cast<size_t>(node);
  return {m.origin[2 * n] + m.u[2 * n], m.origin[2 * n + 1] + m.u[2 * n + 1]};
}

Vec2 outward(Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len = norm(d);
  return {d.y / len, -d.x / len};
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b, double* t_out = nullptr) {
  const Vec2 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  if (t_out) *t_out = t;
  return norm(p - (a + t * d));
}

// Blocks in a uniform grid of cells by their boxes, grown by the largest reach.
struct BlockGrid {
  double x0 = 0, y0 = 0, cell = 1;
  int nx = 1, ny = 1;
  std::vector<std::vector<int>> cells;
  std::vector<Box> boxes;

  int column(double x) const { return std::clamp(static_cast<int>((x - x0) / cell), 0, nx - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - y0) / cell), 0, ny - 1); }
  std::vector<int>& at(int i, int j) { return cells[static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i)]; }
  const std::vector<int>& at(int i, int j) const {
    return cells[static_cast<size_t>(j) * static_cast<size_t>(nx) + static_cast<size_t>(i)];
  }
  const std::vector<int>& near(Vec2 p) const { return at(column(p.x), row(p.y)); }
};

BlockGrid block_grid(const Mechanics& m, double slack) {
  const ContactBoundary& cb = m.faces;
  const int blocks = static_cast<int>(cb.block_first_edge.size()) - 1;
  BlockGrid grid;
  grid.boxes.assign(static_cast<size_t>(blocks), Box{});
  Box all;
  int live = 0;
  double size_sum = 0.0;
  for (int blk = 0; blk < blocks; ++blk) {
    if (!m.block_live[static_cast<size_t>(blk)]) continue;
    Box& box = grid.boxes[static_cast<size_t>(blk)];
    for (int e = cb.block_first_edge[static_cast<size_t>(blk)]; e < cb.block_first_edge[static_cast<size_t>(blk) + 1]; ++e) {
      const ContactEdge& edge = cb.edges[static_cast<size_t>(e)];
      if (!edge.touchable) continue;
      box.add(at(m, edge.a));
      box.add(at(m, edge.b));
    }
    if (box.x0 > box.x1) continue;
    all.add({box.x0, box.y0});
    all.add({box.x1, box.y1});
    size_sum += std::max(box.x1 - box.x0, box.y1 - box.y0);
    ++live;
  }
  if (live == 0) return grid;
  grid.cell = std::max(size_sum / live, 1e-12) + 2.0 * slack;
  grid.x0 = all.x0 - slack;
  grid.y0 = all.y0 - slack;
  grid.nx = std::clamp(static_cast<int>((all.x1 - all.x0 + 2 * slack) / grid.cell) + 1, 1, 4096);
  grid.ny = std::clamp(static_cast<int>((all.y1 - all.y0 + 2 * slack) / grid.cell) + 1, 1, 4096);
  grid.cell = std::max((all.x1 - all.x0 + 2 * slack) / grid.nx, (all.y1 - all.y0 + 2 * slack) / grid.ny) * (1 + 1e-12);
  grid.cells.assign(static_cast<size_t>(grid.nx) * static_cast<size_t>(grid.ny), {});
  for (int blk = 0; blk < blocks; ++blk) {
    const Box& box = grid.boxes[static_cast<size_t>(blk)];
    if (box.x0 > box.x1) continue;
    for (int j = grid.row(box.y0 - slack); j <= grid.row(box.y1 + slack); ++j)
      for (int i = grid.column(box.x0 - slack); i <= grid.column(box.x1 + slack); ++i) grid.at(i, j).push_back(blk);
  }
  return grid;
}

// A contact found for one gridpoint.
struct Found {
  int other = -1, edge = -1;
  double length = 0.0, wedge = 0.0;
  bool leads_past_a = false, leads_past_b = false;  // Contact::leads_past_a, leads_past_b
  double t = 0.0, gap = 0.0;
  Vec2 normal;
  // The traction given (the in-situ stress, or a fresh crack's section's) on this side's half of
  // its half-edges, each over its part that faces the face [N/m].
  Vec2 insitu_force;
  bool insitu = false;
  bool cracked = false;  // the traction is a fresh crack's (its section broke since the last)
  int face = 0;           // Contact::face
  bool split = false;     // one of a gridpoint's two contacts with the block (second_face)
  bool half_a = false, half_b = false;  // given the half-edge before (after) the gridpoint
  bool pair_at_a = false, pair_at_b = false;  // Contact::pair_at_a, pair_at_b
};

// A contact of the gridpoint at `p` with `block` on its edge `edge_index`: the edge's normal,
// where `p` projects on it and its gap (by the edge's own line: `split`, Contact::split).
Found found_on(const Mechanics& m, Vec2 p, int block, int edge_index, bool split = false) {
  const ContactBoundary& cb = m.faces;
  const ContactEdge& edge = cb.edges[static_cast<size_t>(edge_index)];
  Found f;
  f.other = block;
  f.edge = edge_index;
  const Vec2 a = at(m, edge.a), b = at(m, edge.b);
  f.normal = outward(a, b);
  distance_to_segment(p, a, b, &f.t);
  f.gap = dot(p - (a + f.t * (b - a)), f.normal);
  // Past a bent end and past the neighbour's end too: as contact_force sees it.
  const double along = dot(p - a, b - a);
  const bool at_a = along < 0.0 && edge.bent_a, at_b = along > dot(b - a, b - a) && edge.bent_b;
  f.split = split;
  if (!split && (at_a || at_b)) {
    const Vec2 vertex = at_a ? a : b, s = (1.0 / norm(b - a)) * (b - a);
    const Vec2 far = at(m, at_a ? cb.edges[static_cast<size_t>(edge.prev)].a : cb.edges[static_cast<size_t>(edge.next)].b);
    PastTheEnd end;
    if (past_the_end(p.x - vertex.x, p.y - vertex.y, far.x - vertex.x, far.y - vertex.y, s.x, s.y, at_a, end)) {
      f.normal = {end.nx, end.ny};
      f.gap = end.gap;
    }
  }
  return f;
}

// The nearest touchable edge of `block` within `search` of node k's gridpoint, or nothing: among
// the edges about as near as the nearest (within a tenth of the reach), the one that EdgeChoice
// picks (edge_choice.hpp), given `held`, the edge the gridpoint's contact with this block had (-1:
// none), and whether that contact presses. Matching gridpoints on the two faces of a joint
// (zoning.hpp) sit exactly at each other's corners.
std::optional<Found> nearest_edge(const Mechanics& m, int node, Vec2 p, Vec2 own_normal, int block,
                                  double reach, double search, int held, bool held_presses, double held_closure) {
  const ContactBoundary& cb = m.faces;
  const int first = cb.block_first_edge[static_cast<size_t>(block)];
  const int last = cb.block_first_edge[static_cast<size_t>(block) + 1];
  double nearest = search;
  for (int e = first; e < last; ++e) {
    const ContactEdge& edge = cb.edges[static_cast<size_t>(e)];
    if (!edge.touchable || edge.a == node || edge.b == node) continue;
    nearest = std::min(nearest, distance_to_segment(p, at(m, edge.a), at(m, edge.b)));
  }
  const double about = std::min(search, nearest + 0.1 * reach);
  // The held edge stays on offer a band further: a gridpoint whose nearest edges differ by about
  // the band's width would otherwise be offered the squarer one at one search and not at the
  // next, and its contact would swing between them (with its stress, made for one face, pressed
  // on the other), making energy at every swing. A contact that presses on a joint whose law
  // follows a measured curve keeps its edge on offer that curve's closure further
  // (`held_closure`, JointParams::curve_closure), as the overlap watchdog allows it: a block's
  // corner sunk that far into a soft joint's face lies on the other block's side face, at a
  // distance of nothing, and offered that face alone its contact would leave the face it presses
  // on, its load with it.
  const double held_about = std::min(search, nearest + 0.2 * reach + held_closure);
  EdgeChoice choice{.held = held, .own_size = norm(own_normal), .held_presses = held_presses};
  for (int e = first; e < last; ++e) {
    const ContactEdge& edge = cb.edges[static_cast<size_t>(e)];
    if (!edge.touchable || edge.a == node || edge.b == node) continue;
    const Vec2 a = at(m, edge.a), b = at(m, edge.b);
    const double d = distance_to_segment(p, a, b);
    if (d > (e == held ? held_about : about)) continue;
    const double along = dot(p - a, b - a);
    choice.offer(e, d, dot(outward(a, b), own_normal), along >= 0.0 && along <= dot(b - a, b - a));
  }
  const int best_edge = choice.chosen();
  if (best_edge < 0) return std::nullopt;
  return found_on(m, p, block, best_edge);
}

std::optional<Stress> insitu_here(const Mechanics& m, Vec2 point) {
  if (m.insitu.empty()) return std::nullopt;
  return insitu_stress_if_any(m, point);
}

// A convex corner of a block is sharp where its boundary turns by 60 deg or more (the cosine of
// the turn at most this): beyond it a tip pressed in to d lies within the block for at most
// 0.58 d, and a half-edge reaching past it is beside the block. At a blunter corner the next edge
// runs on under the face's line, and the fade past a corner (contact_force.hpp) stays.
constexpr double kSharpTurn = 0.5;

// Whether a boundary running along `in` and then along `out` turns there at a sharp convex corner.
bool sharp_turn(Vec2 in, Vec2 out) {
  return cross(in, out) > 0.0 && dot(in, out) <= kSharpTurn * norm(in) * norm(out);
}

// Whether edge `on` ends, at its end b (`forward`) or a, in a sharp convex corner with the edge
// `beyond` it (sharp_turn).
bool sharp_corner(const Mechanics& m, const ContactEdge& on, bool forward, int beyond) {
  const ContactEdge& next = m.faces.edges[static_cast<size_t>(beyond)];
  const Vec2 d_on = at(m, on.b) - at(m, on.a), d_next = at(m, next.b) - at(m, next.a);
  return forward ? sharp_turn(d_on, d_next) : sharp_turn(d_next, d_on);
}

// How much of the segment p-q lies over the touchable edges `edge` and those beside it along
// its loop, measured along them (their projections, clipped to each edge's ends) [m]. The walk
// goes on in each direction while the segment still reaches past the end of the edge it is on:
// a long half edge (coarse zoning) can lie over many short ones of the other block, and past a
// blunt corner the next face runs on under it. Each edge beyond takes only the piece of the
// segment past that end, and the walk stops at a sharp corner (sharp_corner): past it the segment
// is beside the block. Projected on the side beyond, the piece past such a corner would count as
// length there, which the length a contact follows between detections (facing_length.hpp,
// clipped at the corner) does not: a gridpoint sliding past the corner would have its length, and
// its force, jump at every detection.
double covered_length(const Mechanics& m, Vec2 p, Vec2 q, int edge) {
  const ContactBoundary& cb = m.faces;
  // Of piece p-q: the part over edge e [m] and, past its end a (backward) or b (forward), the
  // piece of it beyond that end (empty: none).
  struct Over {
    double length = 0.0;
    Vec2 from, to;
    bool beyond = false;
  };
  const auto over = [&](int e, Vec2 from, Vec2 to, bool forward) {
    Over o;
    const ContactEdge& ce = cb.edges[static_cast<size_t>(e)];
    if (!ce.touchable) return o;
    const Vec2 a = at(m, ce.a), d = at(m, ce.b) - a;
    const double len2 = dot(d, d);
    const double tp = dot(from - a, d) / len2, tq = dot(to - a, d) / len2;
    const double lo = std::max(0.0, std::min(tp, tq)), hi = std::min(1.0, std::max(tp, tq));
    o.length = hi > lo ? (hi - lo) * std::sqrt(len2) : 0.0;
    const double end = forward ? 1.0 : 0.0;
    const auto past = [&](double t) { return forward ? t > end : t < end; };
    if (!past(tp) && !past(tq)) return o;
    o.beyond = true;
    o.from = from, o.to = to;
    if (past(tp) != past(tq)) {
      const Vec2 split = from + ((end - tp) / (tq - tp)) * (to - from);
      (past(tp) ? o.to : o.from) = split;
    }
    return o;
  };
  const double limit = norm(q - p);
  double covered = over(edge, p, q, true).length;
  for (const bool forward : {false, true}) {
    Over here = over(edge, p, q, forward);
    int e = edge;
    while (here.beyond && covered < limit) {
      const ContactEdge& on = cb.edges[static_cast<size_t>(e)];
      const int beyond = forward ? on.next : on.prev;
      if (sharp_corner(m, on, forward, beyond)) break;  // past it, beside the block
      e = beyond;
      if (e == edge) break;
      here = over(e, here.from, here.to, forward);
      if (!(here.length > 0.0)) break;
      covered += here.length;
    }
  }
  return std::min(covered, limit);
}

// Whether a half-edge of a gridpoint at the other block's corner runs on along that block's
// outline rather than against it: the other block's edge leaving its corner at the gridpoint
// faces the same way as the half-edge (where a joint meets the model's outline, or another
// joint, both blocks' outlines go on side by side). Such a half-edge carries nothing across the
// joint, neither length nor in-situ traction.
bool continues_outline(const Mechanics& m, const Found& to, Vec2 p, Vec2 n_e, double reach) {
  const ContactBoundary& cb = m.faces;
  const ContactEdge& target = cb.edges[static_cast<size_t>(to.edge)];
  const double near = 0.01 * reach;
  const auto same_facing = [&](int e) {
    const ContactEdge& other = cb.edges[static_cast<size_t>(e)];
    return dot(outward(at(m, other.a), at(m, other.b)), n_e) > kSameFacing;
  };
  if (norm(at(m, target.a) - p) < near && same_facing(target.prev)) return true;
  if (norm(at(m, target.b) - p) < near && same_facing(target.next)) return true;
  return false;
}

// The section edge `edge` belongs to, -1 for none.
int section_of(const Mechanics& m, int edge) {
  return m.edge_section.empty() ? -1 : m.edge_section[static_cast<size_t>(edge)];
}

// The stress whose traction a contact found new on edge `edge` takes: that of the section the
// edge belongs to if it broke since the last detection (its faces were carrying it), else the
// in-situ field (with_insitu: the first detection after insitu{}), else none.
std::optional<Stress> traction_source(const Mechanics& m, int edge, Vec2 point, bool with_insitu) {
  const int section = section_of(m, edge);
  if (section >= 0) {
    const Section& s = m.sections[static_cast<size_t>(section)];
    if (!s.fresh) return std::nullopt;
    const CrackView& c = m.cracks[static_cast<size_t>(s.crack)];
    return Stress{c.sxx, c.syy, c.sxy, 0.0};
  }
  if (with_insitu) return insitu_here(m, point);
  return std::nullopt;
}

// A contact's length per unit facing length is 1 where its half-edges lie over one straight face;
// a face that bends on, or turns at a blunt corner its half-edge reaches past, can give more
// (covered_length measures along each edge, facing_length along the first one's line). Larger,
// the length was not theirs.
constexpr double kMostPerFacing = 1.25;

// How far an edge at a corner may turn into a face and still count as along it: sin 10 deg [-].
constexpr double kAlongFace = 0.17364817766693033;

// A tip's length per unit overlap against the face of `to` (contacts.hpp): half the spread of
// the tangents of its edges' angles from the face's normal, so that pressed in by d its length
// is half the chord its boundary cuts on the face's line. 0 unless every edge at node k leaves
// the face outward and the block lies between them (its edges' summed outward normal,
// `own_normal`, points into the face: a corner pointing in). At most a quarter of the edges'
// span at the watchdog's depth, the length a face of them would have.
// At a convex corner of the block as built (ContactEdge::corner_a, corner_b), an edge along the
// face, up to kAlongFace into it, lies over the face all its length once pressed in: its tangent
// is infinite, and the tip has that most. Were such an edge no tip once it turned the least bit
// into the face, a corner pressed into the face of the block diagonally across a slipped joint
// crossing would be dropped whenever its edge along the joint rocked past parallel and found again
// when it rocked back, its force going on and off every few dozen cycles, and the crossing would
// not settle. Elsewhere on a face a gridpoint carries its half-edges' length, not a tip's.
// An edge clearly into the face is no tip's either: the face beside a tip's apex would take the
// tip's far edge, its line run on past the apex, as a face to press on (wedge_tip.lua).
double tip_wedge(const Mechanics& m, size_t k, Vec2 p, Vec2 own_normal, const Found& to, double reach) {
  const ContactBoundary& cb = m.faces;
  const int node = cb.nodes[k];
  bool corner = false;
  for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
    if (m.block_live[static_cast<size_t>(e.block)])
      corner = corner || (e.a == node ? e.corner_a : e.corner_b);
  }
  const Vec2 along{-to.normal.y, to.normal.x};
  double low = INFINITY, high = -INFINITY, span = 0.0;
  for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
    if (!m.block_live[static_cast<size_t>(e.block)]) continue;
    const Vec2 far_end = at(m, e.a == node ? e.b : e.a);
    const Vec2 d = far_end - p;
    const double out = dot(d, to.normal), side = dot(d, along);
    const double least = corner ? -kAlongFace * norm(d) : 0.0;
    if (!(out > least)) return 0.0;  // runs into the face (or, off a corner, along it): not a tip
    const double tangent = out > 0.0 ? side / out : std::copysign(INFINITY, side);
    low = std::min(low, tangent);
    high = std::max(high, tangent);
    span += norm(d);
  }
  if (!(high > low) || !(dot(own_normal, to.normal) < 0.0)) return 0.0;
  return std::min(0.5 * (high - low), span / (4.0 * reach));
}

// How far an edge of a tip may lean back, from the face's normal towards the rest of the face,
// and still not reach back over it: sin 10 deg [-].
constexpr double kLeansBack = 0.17364817766693033;
// For a tip, whether its edges all lead out past end a, and past end b, of the edge it is pressed
// into, where that end is a sharp convex corner: none of them leans back towards the rest of the
// edge by more than kLeansBack. Beyond such an end the tip is beside the block, not in it: at a
// slipped joint crossing, the corner of the block beyond the diagonal block's corner, standing on
// the block beside it. Judged for every tip, whatever length its half-edges give it: an edge
// running out of the face near its normal projects a sliver onto the face beyond the corner
// (covered_length), there at one detection and not at the next as the blocks rock, and a tip
// judged only without one would be pushed by the face's line run on past the corner at every
// other detection, its load taken off and put back deeper, energy made at each round. A corner
// whose edge beside is glued is none, the rock going on past it: a block's corner pressed 0.8 m
// in beside such a corner in Case 3 at 158 m, its edges rocking about kLeansBack, was judged
// past it at one detection and not at the next, and made and gave back 1.3e7 J/m each time.
void mark_leading_past(const Mechanics& m, size_t k, Vec2 p, Found& to) {
  const ContactBoundary& cb = m.faces;
  const int node = cb.nodes[k];
  const ContactEdge& target = cb.edges[static_cast<size_t>(to.edge)];
  const Vec2 a = at(m, target.a), b = at(m, target.b);
  const auto sharp = [](Vec2 from, Vec2 corner, Vec2 to_point) {
    return sharp_turn(corner - from, to_point - corner);
  };
  const ContactEdge& prev = cb.edges[static_cast<size_t>(target.prev)];
  const ContactEdge& next = cb.edges[static_cast<size_t>(target.next)];
  const Vec2 along{-to.normal.y, to.normal.x};  // from end a to end b
  bool back_to_a = false, back_to_b = false;
  for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
    if (!m.block_live[static_cast<size_t>(e.block)]) continue;
    const Vec2 d = at(m, e.a == node ? e.b : e.a) - p;
    back_to_a = back_to_a || dot(d, along) < -kLeansBack * norm(d);
    back_to_b = back_to_b || dot(d, along) > kLeansBack * norm(d);
  }
  // Past end a the block lies towards b. Where the edge beside is glued the rock goes on (at a
  // glued tip its outline turns there too).
  const bool free_a = prev.touchable || target.glued_tip_a;
  const bool free_b = next.touchable || target.glued_tip_b;
  to.leads_past_a = free_a && !back_to_b && sharp(at(m, prev.a), a, b);
  to.leads_past_b = free_b && !back_to_a && sharp(a, b, at(m, next.b));
}

// The contact of `node` with `block` in the list as it stands, or nullptr.
const Contact* held_contact(const ContactSet& set, int node, int block) {
  const auto before = [](const Contact& x, std::pair<int, int> key) {
    return x.node != key.first ? x.node < key.first : x.other < key.second;
  };
  const auto c = std::lower_bound(set.list.begin(), set.list.end(), std::pair{node, block}, before);
  return c != set.list.end() && c->node == node && c->other == block ? &*c : nullptr;
}

// Whether a contact presses: closed, in compression.
bool presses(const Contact& c) { return c.state != ContactState::open && c.sn > 0.0; }

// The contact of `node` with `block` in the list as it stands if it presses, or null.
const Contact* pressed_contact(const ContactSet& set, int node, int block) {
  const Contact* c = held_contact(set, node, block);
  return c && presses(*c) ? c : nullptr;
}

// `f` takes the tip `c` had: its wedge and the sharp corners its edges lead past.
void take_tip(const Contact& c, Found& f) {
  f.wedge = c.wedge;
  f.leads_past_a = c.leads_past_a;
  f.leads_past_b = c.leads_past_b;
}

// A gridpoint pressed into a block that a detection finds no length and no tip over (its edges
// turning about the face's direction as it rocks: a tip at one detection, edges running into the
// face at the next) keeps the length and tip its contact had: the contact goes when its gap opens
// or it slides off the face's corner (contact_force.hpp), not by a turn of its edges. Dropped and
// made again, it would start with none of its load and take it from its overlap at once, energy
// made at every detection.
void keep_pressed(const ContactSet& set, int node, Found& f) {
  const Contact* c = pressed_contact(set, node, f.other);
  if (!c) return;
  f.length = c->length;
  take_tip(*c, f);
}

// A tip pressed into a block (its length growing with its overlap: Contact::wedge) that a
// detection finds with some length of its own but no longer a tip (an edge nearly along the face
// rocking past it: out of the face at one detection, into it at the next) stays a tip: its length
// is the larger of the two, as the part of its boundary within the block is at least the tip's
// chord. Dropped, its length would fall from the tip's to its half-edges' (a tenth of it or less)
// and come back at the next detection that finds a tip, deeper: the gridpoint rocking between
// the two, its contact would gain energy at every round.
void keep_tip(const ContactSet& set, int node, Found& f) {
  const Contact* c = pressed_contact(set, node, f.other);
  if (c && c->wedge > 0.0) take_tip(*c, f);
}

// How far `q` is from the found edge of `f` or those beside it along its block's outline [m].
// (A gridpoint where a joint ends on another block's face is as near to the face's piece on
// either side of it; either may have been found, and its half-edge lying over the other piece is
// that block's all the same.)
double distance_to_face(const Mechanics& m, Vec2 q, const Found& f) {
  const ContactBoundary& cb = m.faces;
  const ContactEdge& target = cb.edges[static_cast<size_t>(f.edge)];
  double d = distance_to_segment(q, at(m, target.a), at(m, target.b));
  for (const int beside : {target.prev, target.next}) {
    const ContactEdge& b = cb.edges[static_cast<size_t>(beside)];
    if (b.touchable) d = std::min(d, distance_to_segment(q, at(m, b.a), at(m, b.b)));
  }
  return d;
}

// The part of the half-edge from gridpoint p towards `far_end` (outward normal n_e) that each found
// block takes [m]: of the half-edge, the part over the block's found edge and those beside it
// along its outline (covered_length). Where two blocks' faces both lie under it (a gridpoint at
// the corner of two blocks), the nearer takes more: a block whose face is further from the
// half-edge's quarter point than the nearest one by kShareBand of the half-edge or more takes
// none, nearer by less a part that grows as it comes nearer; a face other than the nearest only
// as far as the half-edge faces it (kShareFacing), the nearest unless it is behind it
// (kNearestFacing), and one between by how near it is; together they take no more than the
// half-edge. A face the half-edge does not face counts as that much further off (by up to the
// band): behind it, it takes no share, and its nearness takes none from the face it presses on.
// So the length moves smoothly with the gridpoint: a half-edge sliding past a joint crossing goes
// from one block to the next as it goes over, a gridpoint at a corner does not lose a contact at
// one detection and make it again at the next, and a half-edge that runs along one block's face
// onto another's keeps its length as the two swap as the nearest (the length found again at
// each detection would jump, and its stress kept, its energy with it: made at every swap). All
// zero when no face is within `search` and a quarter of the edge of the quarter point.
// `distance` and `part` are the caller's, per found block, so that a gridpoint's half-edges
// reuse them.
void half_edge_parts(const Mechanics& m, Vec2 p, Vec2 far_end, Vec2 n_e, double reach, double search,
                     const std::vector<Found>& found, std::vector<double>& distance, std::vector<double>& part) {
  const double half = 0.5 * norm(far_end - p);
  const Vec2 quarter = p + 0.25 * (far_end - p);
  const Vec2 middle = p + 0.5 * (far_end - p);
  const double within = search + 0.5 * half;
  distance.resize(found.size());
  part.assign(found.size(), 0.0);
  const double band = kShareBand * half;
  // How far each face faces the half-edge, as the nearest (1: squarely enough) [-].
  const auto as_nearest = [&](size_t j) { return std::clamp(-dot(n_e, found[j].normal) / kNearestFacing, 0.0, 1.0); };
  const auto apart = [&](size_t j) { return distance[j] + (1.0 - as_nearest(j)) * band; };
  bool any = false;
  double nearest = INFINITY;
  for (size_t j = 0; j < found.size(); ++j) {
    distance[j] = distance_to_face(m, quarter, found[j]);
    any = any || distance[j] < within;
    nearest = std::min(nearest, apart(j));
  }
  if (!any) return;
  double total = 0.0;
  for (size_t j = 0; j < found.size(); ++j) {
    if (!(distance[j] < within)) continue;
    const double nearness = std::clamp(1.0 - (apart(j) - nearest) / band, 0.0, 1.0);
    const double as_other = std::clamp((-dot(n_e, found[j].normal) - kShareFacing) / kShareFacing, 0.0, 1.0);
    const double facing = as_other + (as_nearest(j) - as_other) * nearness;
    if (!(facing * nearness > 0.0) || continues_outline(m, found[j], p, n_e, reach)) continue;
    part[j] = facing * nearness * covered_length(m, p, middle, found[j].edge);
    total += part[j];
  }
  if (total > half)
    for (double& x : part) x *= half / total;
}

// A half-edge facing a face within 20 degrees lies along it [-].
const double kAlongOneFace = std::cos(20.0 * M_PI / 180.0);
// Two faces of a block meet at an angle where their directions differ by more than a degree (the
// sine of it) [-]. Less, the edges of one face whose gridpoints were snapped or cut a hair off its
// line (a potential crack's sections) would each carry half-edges of their own, and the faces'
// contacts along them would lose what a face's contacts share as the face slides (the lengths
// that follow their facing length).
const double kBent = std::sin(M_PI / 180.0);
// A gridpoint within this share of its reach of where two faces of another block meet is at
// their corner (second_face) [-]. Further off it lies along one of them: its half-edge reaching
// past their corner would have its contact with the other face pressed by that face's line run
// on past the corner, and a face bent by a few degrees would be offered to the gridpoints beside
// the bend.
constexpr double kAtTheVertex = 0.1;
// A pair made at a corner is kept while its gridpoint is within this share of its reach of it [-].
constexpr double kPairKept = 1.0;

// The edge beside the edge `to` found for node k, at the end of `to` where node k is
// (kAtTheVertex), that node k's half-edges lie along too, or -1: where a corner of one block sits
// in the corner of the other (a convex corner in the concave corner of a block, or of blocks
// glued together), or where the other's face bends at the gridpoint, each of the gridpoint's
// half-edges runs along its own face of the other block. One contact, with one face's normal,
// would carry the other half-edge's load only as far as its normal faces that one's, and in its
// direction: at a corner of 110 degrees a third of it, and in a stress field that is in
// equilibrium the gridpoint would be pushed by the rest (1.3e5 N/m in the seed's cavern model as
// built; 2e4 N/m where a face bends by 3 degrees). A second contact carries it on its own face.
int second_face(const Mechanics& m, size_t k, const Found& to) {
  const ContactBoundary& cb = m.faces;
  const int node = cb.nodes[k];
  const Vec2 p = at(m, node);
  const ContactEdge& target = cb.edges[static_cast<size_t>(to.edge)];
  const auto normal_of = [&](const ContactEdge& e) { return outward(at(m, e.a), at(m, e.b)); };
  // Whether one of the gridpoint's half-edges faces `face` squarely and runs along it, away from
  // its end nearer the gridpoint (not along its line run on past that end: at a joint crossing
  // the block diagonally across has its faces' lines there, not its faces).
  const auto lies_along = [&](const ContactEdge& face) {
    const Vec2 a = at(m, face.a), b = at(m, face.b), n_face = outward(a, b);
    const Vec2 onward = norm(a - p) < norm(b - p) ? b - a : a - b;
    for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
      const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
      if (!m.block_live[static_cast<size_t>(e.block)]) continue;
      const Vec2 far_end = at(m, e.a == node ? e.b : e.a);
      const Vec2 n_e = e.a == node ? outward(p, far_end) : outward(far_end, p);
      if (-dot(n_e, n_face) > kAlongOneFace && dot(far_end - p, onward) > 0.0) return true;
    }
    return false;
  };
  if (!lies_along(target)) return -1;
  const Vec2 n_to = normal_of(target);
  // A pair already made is kept further (kPairKept): dropped and made again as the gridpoint
  // rocks about the limit, the second contact's energy would go and come back (in the reduced
  // seed study's Case 3 the balance closed within 2.3 % with no more than kAtTheVertex, 1.4 %
  // with this).
  // (Only the two of a pair are split: the first of them says there is one.)
  const Contact* first = held_contact(m.contacts, node, to.other);
  const bool paired = first && first->split;
  const double near = (paired ? kPairKept : kAtTheVertex) * cb.reach[k];
  for (const int beside : {target.prev, target.next}) {
    const ContactEdge& b = cb.edges[static_cast<size_t>(beside)];
    if (!b.touchable || b.a == node || b.b == node) continue;
    const Vec2 w = at(m, beside == target.prev ? target.a : target.b);  // where the two faces meet
    if (!(norm(p - w) < near)) continue;
    if (std::fabs(cross(normal_of(b), n_to)) > kBent && lies_along(b)) return beside;
  }
  return -1;
}

// Gives the halves of node k's adjacent edges to the blocks found (half_edge_parts): their
// lengths, and where a stress acts on them (the in-situ field with with_insitu, or a section that
// broke since the last detection) its traction. A block's second face (second_face) is a contact
// of its own, appended to `found`, and takes the half-edges that face it more squarely than the
// first.
void give_half_edges(const Mechanics& m, size_t k, double search, bool with_insitu, std::vector<Found>& found) {
  const bool with_traction = with_insitu || m.fresh_cracks;
  const ContactBoundary& cb = m.faces;
  const int node = cb.nodes[k];
  const Vec2 p = at(m, node);
  // found[second[j]]: the second contact with found[j]'s block, or 0 for none.
  const size_t firsts = found.size();
  std::vector<size_t> second(firsts, 0);
  for (size_t j = 0; j < firsts; ++j) {
    const int edge = second_face(m, k, found[j]);
    if (edge < 0) continue;
    second[j] = found.size();
    const bool before = edge == cb.edges[static_cast<size_t>(found[j].edge)].prev;
    found[j] = found_on(m, p, found[j].other, found[j].edge, true);
    found.push_back(found_on(m, p, found[j].other, edge, true));
    found.back().face = 1;
    // Where the two faces meet: end a of the found edge and end b of the one before it, or the
    // other way round.
    (before ? found[j].pair_at_a : found[j].pair_at_b) = true;
    (before ? found.back().pair_at_b : found.back().pair_at_a) = true;
  }
  std::vector<double> distance, parts;
  std::vector<Found> offered(firsts);
  std::vector<size_t> to_face(firsts);
  for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
    const int own = cb.node_edges[static_cast<size_t>(i)];
    const ContactEdge& e = cb.edges[static_cast<size_t>(own)];
    if (!m.block_live[static_cast<size_t>(e.block)]) continue;
    const Vec2 far_end = at(m, e.a == node ? e.b : e.a);
    const Vec2 n_e = e.a == node ? outward(p, far_end) : outward(far_end, p);
    // Of a block's two faces, the half-edge is offered the one it faces the more squarely.
    for (size_t j = 0; j < firsts; ++j) {
      const bool squarer = second[j] > 0 && -dot(n_e, found[second[j]].normal) > -dot(n_e, found[j].normal);
      to_face[j] = squarer ? second[j] : j;
      offered[j] = found[to_face[j]];
    }
    half_edge_parts(m, p, far_end, n_e, cb.reach[k], search, offered, distance, parts);
    for (size_t j = 0; j < firsts; ++j) {
      if (!(parts[j] > 0.0)) continue;
      Found& to = found[to_face[j]];
      // This side's share, half; of the half edge, the part that lies over the other block, as
      // far as it faces it.
      const double facing_part = 0.5 * parts[j] * std::max(0.0, -dot(n_e, to.normal));
      to.length += facing_part;
      (e.b == node ? to.half_a : to.half_b) = true;
      if (!with_traction) continue;
      if (const auto s = traction_source(m, own, p + (1.0 / 3.0) * (far_end - p), with_insitu)) {
        // This side's share of the edge's consistent nodal force, half * sigma . n, for the
        // part that lies over the other block, as far as it faces it: over the length it adds.
        // (The whole part's force over the facing part's length would give a half-edge that meets
        // the face near edge on the traction's shear as a normal stress, without bound: 70 MPa on
        // a tip of 1e-6 m in Case 3, where the section broke at 21 MPa.)
        to.insitu_force = to.insitu_force + facing_part * Vec2{s->xx * n_e.x + s->xy * n_e.y, s->xy * n_e.x + s->yy * n_e.y};
        to.insitu = true;
        to.cracked = to.cracked || section_of(m, own) >= 0;
      }
    }
  }
  // A second face that got no length is none; one that got it all is the gridpoint's only
  // contact with the block. Of two, the first is on the edge that comes first: which one the
  // search found first may change from one detection to the next, and each contact is found again
  // (keeping its state) by its gridpoint, block and face.
  std::vector<char> drop(found.size(), 0);
  for (size_t j = 0; j < firsts; ++j) {
    if (second[j] == 0) continue;
    Found& other_face = found[second[j]];
    if (found[j].length > 0.0 && other_face.length > 0.0) {
      if (other_face.edge < found[j].edge) {
        std::swap(found[j], other_face);
        std::swap(found[j].face, other_face.face);
      }
      continue;
    }
    if (!(found[j].length > 0.0) && other_face.length > 0.0) std::swap(found[j], other_face);
    drop[second[j]] = 1;
    // One contact after all: its gap and normal as any lone contact's, its length as given.
    Found lone = found_on(m, p, found[j].other, found[j].edge);
    lone.length = found[j].length;
    lone.insitu_force = found[j].insitu_force;
    lone.insitu = found[j].insitu;
    lone.cracked = found[j].cracked;
    found[j] = lone;
  }
  for (size_t j = found.size(); j-- > firsts;)
    if (drop[j]) found.erase(found.begin() + static_cast<std::ptrdiff_t>(j));
}

// Contacts of node position k: the nearest edge of each block in reach, and their lengths.
std::vector<Found> contacts_of(const Mechanics& m, const BlockGrid& grid, size_t k, bool with_insitu) {
  const ContactBoundary& cb = m.faces;
  const int node = cb.nodes[k];
  const Vec2 p = at(m, node);
  const double reach = cb.reach[k];
  // A contact it already has is followed as deep as the watchdog lets a gridpoint sink, whatever
  // the length of its own edges, and one that presses twice as deep: found again past the
  // watchdog's limit (a detection just before a cycle, as a boundary{} given between cycles
  // makes), it is still there when the cycle's watchdog looks, which stops the run; dropped, its
  // gridpoint would sink on through the block unseen. A new one is made within its reach only
  // (further out, the nearest edge of a block can be one the gridpoint does not face: spurious
  // deep contacts).
  const double follow = std::max(reach, overlap_limit(m));
  double search = reach;
  const int* own_first = cb.node_blocks.data() + cb.block_first[k];
  const int* own_last = cb.node_blocks.data() + cb.block_first[k + 1];
  Vec2 own_normal;
  bool alive = false;
  for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
    if (!m.block_live[static_cast<size_t>(e.block)]) continue;
    alive = true;
    own_normal = own_normal + outward(at(m, e.a), at(m, e.b));
  }
  std::vector<Found> found;
  if (!alive) return found;
  for (const int block : grid.near(p)) {
    if (std::find(own_first, own_last, block) != own_last) continue;
    if (!grid.boxes[static_cast<size_t>(block)].contains(p, follow)) continue;
    const Contact* had = held_contact(m.contacts, node, block);
    const int held = had ? had->edge : -1;
    const bool pressing = had && presses(*had);
    const double radius = !had ? reach : pressing ? 2.0 * follow : follow;
    const double closure =
        pressing && had->material >= 0 ? m.joint_params[static_cast<size_t>(had->material)].curve_closure : 0.0;
    if (auto f = nearest_edge(m, node, p, own_normal, block, reach, radius, held, pressing, closure)) {
      found.push_back(*f);
      search = std::max(search, std::min(radius, follow));
    }
  }
  if (found.empty()) return found;
  give_half_edges(m, k, search, with_insitu, found);
  for (Found& f : found) {
    if (f.split) continue;  // a corner in a corner: along the faces, no tip
    f.wedge = tip_wedge(m, k, p, own_normal, f, reach);
    if (f.wedge > 0.0) mark_leading_past(m, k, p, f);
    if (!(f.length > 1e-12 * reach) && !(f.wedge > 0.0)) keep_pressed(m.contacts, node, f);
    else if (!(f.wedge > 0.0)) keep_tip(m.contacts, node, f);
  }
  std::erase_if(found, [&](const Found& f) { return !(f.length > 1e-12 * reach) && !(f.wedge > 0.0); });
  return found;
}

}  // namespace

std::string describe(const ContactEdge& e) {
  if (e.origin.kind == EdgeKind::joint) return fmt::format("a joint of set {}", e.origin.set + 1);
  if (e.origin.kind == EdgeKind::crack) return "a crack";
  if (e.origin.kind == EdgeKind::potential) return "a potential crack";
  if (e.origin.kind == EdgeKind::boundary) return "the outline of a block{}";
  return "a region outline";
}

std::string_view to_string(ContactState state) {
  switch (state) {
    case ContactState::bonded: return "bonded";
    case ContactState::elastic: return "elastic";
    case ContactState::slip: return "slip";
    case ContactState::open: return "open";
  }
  return "?";
}

ContactBoundary contact_boundary(const Mesh& mesh, const std::vector<char>& edge_glued,
                                 const std::vector<int>& gp_node,
                                 const std::vector<double>& position) {
  ContactBoundary cb;
  cb.block_first_edge.push_back(0);
  for (size_t block = 0; block < mesh.block_boundary.size(); ++block) {
    for (const BoundaryLoop& loop : mesh.block_boundary[block]) {
      const size_t count = loop.gridpoints.size();
      const int loop_first = static_cast<int>(cb.edges.size()), n = static_cast<int>(count);
      for (size_t i = 0; i < count; ++i) {
        ContactEdge e;
        e.prev = loop_first + (static_cast<int>(i) + n - 1) % n;
        e.next = loop_first + (static_cast<int>(i) + 1) % n;
        e.a = gp_node[static_cast<size_t>(loop.gridpoints[i])];
        e.b = gp_node[static_cast<size_t>(loop.gridpoints[(i + 1) % count])];
        e.block = static_cast<int>(block);
        e.touchable = !edge_glued[cb.edges.size()];
        e.origin = loop.edges[i];
        cb.edges.push_back(e);
      }
    }
    cb.block_first_edge.push_back(static_cast<int>(cb.edges.size()));
  }
  // Convex corners: the boundary turns left (the block is on the left) by more than 10 deg; bent
  // ends: it turns, but less or the other way.
  const auto ref = [&](int node) {
    return Vec2{position[2 * static_cast<size_t>(node)], position[2 * static_cast<size_t>(node) + 1]};
  };
  const double sin10 = std::sin(10.0 * M_PI / 180.0);
  for (ContactEdge& e : cb.edges) {
    const ContactEdge& next = cb.edges[static_cast<size_t>(e.next)];
    const ContactEdge& prev = cb.edges[static_cast<size_t>(e.prev)];
    const Vec2 d = ref(e.b) - ref(e.a), dn = ref(next.b) - ref(next.a), dp = ref(prev.b) - ref(prev.a);
    e.corner_b = cross(d, dn) > sin10 * norm(d) * norm(dn);
    e.corner_a = cross(dp, d) > sin10 * norm(dp) * norm(d);
    // A turn above round-off (a millionth of a radian) that is no convex corner.
    e.bent_b = !e.corner_b && std::fabs(cross(d, dn)) > 1e-6 * norm(d) * norm(dn);
    e.bent_a = !e.corner_a && std::fabs(cross(dp, d)) > 1e-6 * norm(dp) * norm(d);
  }
  mark_glued_tips(cb, position);
  // Per node: its touchable edges, and every block whose boundary it is on.
  std::vector<std::pair<int, int>> node_edge, node_block;
  for (size_t e = 0; e < cb.edges.size(); ++e) {
    const ContactEdge& edge = cb.edges[e];
    node_block.push_back({edge.a, edge.block});
    if (!edge.touchable) continue;
    node_edge.push_back({edge.a, static_cast<int>(e)});
    node_edge.push_back({edge.b, static_cast<int>(e)});
  }
  std::sort(node_edge.begin(), node_edge.end());
  std::sort(node_block.begin(), node_block.end());
  node_block.erase(std::unique(node_block.begin(), node_block.end()), node_block.end());
  cb.edge_first.push_back(0);
  cb.block_first.push_back(0);
  size_t nb = 0;
  cb.min_reach = INFINITY;
  for (size_t i = 0; i < node_edge.size();) {
    const int node = node_edge[i].first;
    double shortest = INFINITY;
    for (; i < node_edge.size() && node_edge[i].first == node; ++i) {
      const ContactEdge& e = cb.edges[static_cast<size_t>(node_edge[i].second)];
      cb.node_edges.push_back(node_edge[i].second);
      const double dx = position[2 * static_cast<size_t>(e.b)] - position[2 * static_cast<size_t>(e.a)];
      const double dy = position[2 * static_cast<size_t>(e.b) + 1] - position[2 * static_cast<size_t>(e.a) + 1];
      shortest = std::min(shortest, std::hypot(dx, dy));
    }
    while (nb < node_block.size() && node_block[nb].first < node) ++nb;
    for (; nb < node_block.size() && node_block[nb].first == node; ++nb) cb.node_blocks.push_back(node_block[nb].second);
    cb.nodes.push_back(node);
    cb.edge_first.push_back(static_cast<int>(cb.node_edges.size()));
    cb.block_first.push_back(static_cast<int>(cb.node_blocks.size()));
    cb.reach.push_back(0.5 * shortest);
    cb.min_reach = std::min(cb.min_reach, 0.5 * shortest);
  }
  if (cb.nodes.empty()) cb.min_reach = 0.0;
  cb.median_edge = median_edge_length(cb, position);
  for (size_t block = 0; block + 1 < cb.block_first_edge.size(); ++block)
    for (int e = cb.block_first_edge[block]; e < cb.block_first_edge[block + 1]; ++e)
      if (cb.edges[static_cast<size_t>(e)].touchable) {
        ++cb.touchable_blocks;
        break;
      }
  return cb;
}

bool jassign_selects(const JassignDef& rule, const Polygon& region, const ContactEdge& e,
                     const std::vector<double>& position) {
  if (!e.touchable) return false;
  const EdgeKind kind = e.origin.kind;
  if (rule.kind == "joint" && !(kind == EdgeKind::joint || kind == EdgeKind::boundary || kind == EdgeKind::region))
    return false;
  if (rule.kind == "crack" && kind != EdgeKind::crack) return false;
  if (rule.set >= 0 && !(kind == EdgeKind::joint && e.origin.set == rule.set)) return false;
  if (region.empty()) return true;
  const size_t a = static_cast<size_t>(e.a), b = static_cast<size_t>(e.b);
  return contains(region, {0.5 * (position[2 * a] + position[2 * b]), 0.5 * (position[2 * a + 1] + position[2 * b + 1])});
}

void assign_joint_materials(Mechanics& m) {
  for (ContactEdge& e : m.faces.edges) {
    e.material = -1;
    for (size_t r = 0; r < m.jassign.size(); ++r)
      if (jassign_selects(m.jassign[r], m.jassign_regions[r], e, m.position)) e.material = m.jassign_material[r];
  }
  // A broken potential crack takes its own (crackseed{ after }, or the joints' there).
  if (m.fits.after.size() != m.sections.size()) return;
  for (size_t i = 0; i < m.sections.size(); ++i)
    if (m.sections[i].mode != CrackMode::none)
      for (const int edge : m.sections[i].edge) m.faces.edges[static_cast<size_t>(edge)].material = m.fits.after[i];
}

namespace {

// How far a pressed contact between the same two blocks may be from a new one's gridpoint, in
// the new one's reaches, to lend it the faces' state (LoadedFaces).
constexpr double kLendingReaches = 4.0;
// Faces along the same joint: their edges' normals within 20 degrees, parallel or opposed.
const double kSameJoint = std::cos(20.0 * M_PI / 180.0);

// Whether edges `a` and `b` of a block lie along the same face: their normals within 20 degrees.
bool same_face(const Mechanics& m, int a, int b) {
  if (a == b) return true;
  const ContactEdge& ea = m.faces.edges[static_cast<size_t>(a)];
  const ContactEdge& eb = m.faces.edges[static_cast<size_t>(b)];
  return dot(outward(at(m, ea.a), at(m, ea.b)), outward(at(m, eb.a), at(m, eb.b))) > kSameJoint;
}

// The contacts pressed together before a detection, by the pair of blocks they join: a contact
// made between two blocks where the same two already press on each other nearby takes their
// faces' state instead of starting from nothing (inherit_faces). A gridpoint that slides past a
// joint crossing onto the next block's face, or a face that slides onto more of its neighbour,
// then carries the joint's load at once; made with no prestress it would carry nothing until it
// had sunk in by the joint's closure (centimetres under soft joints), and the gridpoints around
// would carry its share meanwhile.
class LoadedFaces {
 public:
  explicit LoadedFaces(const std::vector<Contact>& list) : list_(list) {}

  // The pressed contact between blocks `a` and `b` (either way round) whose gridpoint is nearest
  // to `p` within `within`, along the same joint as the edge with outward normal `n`, or nullptr.
  const Contact* nearest(const Mechanics& m, int a, int b, Vec2 p, Vec2 n, double within) {
    if (!built_) build();
    const auto found = by_pair_.find(key(a, b));
    if (found == by_pair_.end()) return nullptr;
    const Contact* best = nullptr;
    double best_distance = within;
    for (const int i : found->second) {
      const Contact& c = list_[static_cast<size_t>(i)];
      const double d = norm(at(m, c.node) - p);
      if (!(d < best_distance)) continue;
      const ContactEdge& e = m.faces.edges[static_cast<size_t>(c.edge)];
      if (!(std::fabs(dot(outward(at(m, e.a), at(m, e.b)), n)) > kSameJoint)) continue;
      best = &c;
      best_distance = d;
    }
    return best;
  }

 private:
  static std::uint64_t key(int a, int b) {
    const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
    return lo << 32 | hi;
  }
  void build() {
    built_ = true;
    for (size_t i = 0; i < list_.size(); ++i) {
      const Contact& c = list_[i];
      if (c.state != ContactState::open && c.sn > 0.0) by_pair_[key(c.block, c.other)].push_back(static_cast<int>(i));
    }
  }
  const std::vector<Contact>& list_;
  bool built_ = false;
  std::unordered_map<std::uint64_t, std::vector<int>> by_pair_;
};

// Each node a released tie made since the last detection, with the node it split from, the old
// node a node split from in turn followed to the first (ContactSet::split_from).
std::unordered_map<int, int> nodes_split_from(const ContactSet& set) {
  std::unordered_map<int, int> from;
  for (size_t i = 0; i + 1 < set.split_from.size(); i += 2) {
    const auto earlier = from.find(set.split_from[i + 1]);
    from[set.split_from[i]] = earlier != from.end() ? earlier->second : set.split_from[i + 1];
  }
  return from;
}

// The first old contact of `node` with block `other` along the face of edge `edge` that `usable`
// accepts (given its place in the list), or the list's end.
template <class Usable>
std::vector<Contact>::iterator old_along_face(const Mechanics& m, ContactSet& set, int node, int other, int edge,
                                              Usable usable) {
  const Contact* held = held_contact(set, node, other);
  if (!held) return set.list.end();
  for (auto old = set.list.begin() + (held - set.list.data());
       old != set.list.end() && old->node == node && old->other == other; ++old)
    if (usable(old) && same_face(m, old->edge, edge)) return old;
  return set.list.end();
}

// A contact's energy changed from `had` to `now` by a detection, not by a cycle: the last booked
// point (EnergyLedger::last) moves with it, so that commands do not book the change again.
void book_at_last_point(Mechanics& m, const ContactEnergy& now, const ContactEnergy& had) {
  if (!m.energy.last_current) return;
  m.energy.last.normal += now.normal - had.normal;
  m.energy.last.shear += now.shear - had.shear;
}

// Books what a contact made with a given state stores (`now`, less `had` if it was there) as
// prestress: the joint's, not made by the method; at the last booked point too, so that commands
// do not book it again.
void book_prestress(Mechanics& m, const ContactEnergy& now, const ContactEnergy& had) {
  m.energy.prestress += now.normal + now.shear - had.normal - had.shear;
  book_at_last_point(m, now, had);
}

// What a contact stores a metre of the length that carries it [J/m^2]; with no length yet (a tip
// at a joint crossing, pressed in by round-off), what a metre of it would store at its closure.
// Given nothing there, the prestress its closure holds would be pushed on as its length grows.
double stored_per_metre(const Contact& c, const JointParams& p) {
  const double length = last_carrying_length(c);
  if (length > 0.0) return stored_in(c, p) / length;
  return c.closure > 0.0 ? normal_energy(p, c.closure) : 0.0;
}

// Books what a contact's energy changed by, from `had` to `now`, as taken away with rock dug out
// (at the last booked point too).
void book_taken_away(Mechanics& m, const ContactEnergy& now, const ContactEnergy& had) {
  m.energy.excavated.normal += had.normal - now.normal;
  m.energy.excavated.shear += had.shear - now.shear;
  book_at_last_point(m, now, had);
}

// A new contact `c` (its gridpoint at `gap` from its edge, whose direction is `s`) takes the
// state of the faces `from` presses together: their closure at zero gap (the prestress they carry
// beyond their real overlap: the new contact's own real overlap adds to it) and their shear
// traction, turned round if `from` is seen from the other block.
void inherit_faces(const Mechanics& m, Contact& c, const JointParams& p, const Contact& from, double gap, Vec2 s) {
  const ContactEdge& e = m.faces.edges[static_cast<size_t>(from.edge)];
  const Vec2 from_s = (1.0 / norm(at(m, e.b) - at(m, e.a))) * (at(m, e.b) - at(m, e.a));
  const double from_length = last_carrying_length(from);
  const double length = carrying_length(c, -gap);
  if (!(from_length > 0.0) || !(length > 0.0)) return;
  const double side = from.other == c.other ? 1.0 : -1.0;  // the same block's faces, or the other's
  const Vec2 traction = (side * from.fs / from_length) * from_s;
  c.closure0 = from.closure0 + from.dilation;
  c.closure = c.closure0 - gap;
  c.dilation = c.us = c.slip = c.opened = 0.0;
  const bool pressed = c.closure > 0.0;
  const double strength = shear_strength(c, p, length);
  c.sn = pressed ? normal_stress(p, c.closure) : 0.0;
  c.fs = pressed ? std::clamp(dot(traction, s) * length, -strength, strength) : 0.0;
  c.state = pressed ? ContactState::elastic : ContactState::open;
}

// A cohesive crack given its section's traction starts at most at its law's peak: tension at
// most its tensile strength, shear at most Coulomb's limit at that normal stress. A section
// judged past its strength (its stress passed it before the judgment came) then starts a crack
// not yet softened, as one judged the moment it reached its strength: the cracks a coarse load
// step breaks together reach the states a fine one reaches, where one may still unload while
// its neighbour softens. Taken whole, the overstress would be an opening past the peak, damage
// the bond keeps.
void cap_at_peak(Contact& c, const JointParams& p, double length) {
  c.sn = std::max(c.sn, -p.tension);
  const double limit = shear_limit(c, p, c.sn, p.cohesion, length);
  c.fs = std::clamp(c.fs, -limit, limit);
}

// Lets a contact's length follow its facing length between detections (facing_length.hpp,
// Contact::per_facing): the ends of the gridpoint's own edges, and its length per unit facing
// length now. Only a gridpoint with just two own edges, one on each side of it along its loop,
// and a length its half-edges gave (up to kMostPerFacing times the facing length); one where glued
// blocks meet, or one keeping its length while its edges turn away (keep_pressed), keeps the length
// found. One of a corner's two contacts in a corner (Contact::split) follows the half-edge it was
// given, along its own face and up to where that face meets the pair's other: held as found, its
// length would jump at the next detection (as a detection measures it, give_half_edges) once its
// gridpoint had moved along the face, and its force with it. Returns the facing length [m] (0: none
// measured).
double follow_facing(const Mechanics& m, size_t k, const Found& f, Contact& c) {
  const ContactBoundary& cb = m.faces;
  int before = -1, after = -1, own = 0;
  for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1]; ++i) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
    if (!m.block_live[static_cast<size_t>(e.block)]) continue;
    ++own;
    if (e.b == c.node) before = e.a;
    if (e.a == c.node) after = e.b;
  }
  if (own != 2 || before < 0 || after < 0) return 0.0;
  c.far_a = before;
  c.far_b = after;
  if (c.split) {
    if (f.half_a == f.half_b) return 0.0;  // both, or neither: not one half-edge's length
    c.half_a = f.half_a;
    c.half_b = f.half_b;
    c.pair_at_a = f.pair_at_a;
    c.pair_at_b = f.pair_at_b;
  }
  if (!(c.length > 0.0)) return 0.0;
  const ContactEdge& edge = cb.edges[static_cast<size_t>(c.edge)];
  const Vec2 p = at(m, c.node), fa = at(m, before), fb = at(m, after), a = at(m, edge.a), b = at(m, edge.b);
  const FacingNodes nodes{{p.x, p.y}, {fa.x, fa.y}, {fb.x, fb.y},  {a.x, a.y}, {b.x, b.y},
                          edge.corner_a || c.pair_at_a, edge.corner_b || c.pair_at_b, c.half_a, c.half_b};
  const double facing = facing_length(nodes, nullptr);
  if (facing > 0.0 && c.length <= kMostPerFacing * facing) c.per_facing = c.length / facing;
  return facing;
}

// How far a contact's length as a detection measures it may stray from the length it follows
// (Contact::per_facing) before the detection takes its measure [-]: see follows_as_before.
constexpr double kLengthStray = 0.1;

// Whether a contact found again goes on following its facing length at the share of it it had
// (Contact::per_facing) rather than at the share the detection finds (`c`): its gridpoint's own
// edges and the half-edges it counts are the same, and the detection's length is within
// kLengthStray of the one it follows. A detection measures a length otherwise than the facing
// length follows it (it shares a half-edge among the faces of the blocks it lies over, by how
// squarely it faces each, and counts a half-edge lying along the face); taken at every detection,
// a share that wavers as the blocks rock would make the length, the stored energy and the force
// jump at each, unpaid: a corner pressed into a corner makes energy at every detection and rings
// on. Strayed further (a half-edge come to lie over the block, another face come near), the
// detection's length holds, and its jump is booked as energy made.
bool follows_as_before(const Contact& old, const Contact& c, double facing) {
  if (!(old.per_facing > 0.0 && facing > 0.0)) return false;
  if (c.far_a != old.far_a || c.far_b != old.far_b || c.split != old.split || c.half_a != old.half_a ||
      c.half_b != old.half_b || c.pair_at_a != old.pair_at_a || c.pair_at_b != old.pair_at_b)
    return false;
  return std::fabs(c.length - old.per_facing * facing) <= kLengthStray * old.per_facing * facing;
}

// How far from a gridpoint its contacts are looked for, at most [m].
double largest_reach(const Mechanics& m) {
  double largest = overlap_limit(m);
  for (const double r : m.faces.reach) largest = std::max(largest, r);
  return largest;
}

// A contact found pressed in deeper than this share of its reach went in unseen: detection came
// too late for it (info().late_contacts).
constexpr double kLateDepth = 0.1;

// Whether point p, pressed behind edge e's line, lies outside the line of the face beside it at a
// convex corner of e's block near p (within kBesideCorner reaches of the corner): there it is
// beside the block, past its corner, not in it. A corner slid off a thin tip would otherwise be
// found anew on the tip's face, whose line runs on past the apex, and be pushed out sideways
// with the whole overlap it has behind that line. A corner whose edge beside is glued is no
// corner of the body the blocks glued there make: past that edge's line the gridpoint is in the
// block glued beside (at a glued tip, ContactEdge::glued_tip_a, its own faces carry it).
constexpr double kBesideCorner = 4.0;
bool beside_a_corner(const Mechanics& m, const ContactEdge& e, Vec2 p, double reach) {
  const ContactBoundary& cb = m.faces;
  const auto outside = [&](Vec2 corner, Vec2 from, Vec2 to) {
    const Vec2 d = to - from;
    const double out = cross(p - from, d) / norm(d);
    return out > 1e-3 * reach && norm(p - corner) < kBesideCorner * reach;
  };
  const ContactEdge& prev = cb.edges[static_cast<size_t>(e.prev)];
  const ContactEdge& next = cb.edges[static_cast<size_t>(e.next)];
  if (e.corner_a && prev.touchable && outside(at(m, e.a), at(m, prev.a), at(m, e.a))) return true;
  if (e.corner_b && next.touchable && outside(at(m, e.b), at(m, e.b), at(m, next.b))) return true;
  return false;
}

// Whether gridpoint `node` had a contact with a block other than `block` (list: sorted by node;
// block -1: with any block).
bool held_by_another(const std::vector<Contact>& list, int node, int block = -1) {
  auto c = std::lower_bound(list.begin(), list.end(), node, [](const Contact& x, int n) { return x.node < n; });
  for (; c != list.end() && c->node == node; ++c)
    if (c->other != block) return true;
  return false;
}

// Finds again the contacts of the boundary nodes flagged in `redo` (per position in
// ContactBoundary::nodes; all of them when it is empty) and keeps the others' as they are;
// rebuilds the force gather and the stiffness rows.
void find_contacts(Mechanics& m, const BlockGrid& grid, const std::vector<char>& redo) {
  const ContactBoundary& cb = m.faces;
  ContactSet& set = m.contacts;
  const bool first = set.as_built;
  const bool with_insitu = set.from_insitu && !m.insitu.empty();
  const bool all = redo.empty();

  std::vector<size_t> to_search;
  for (size_t k = 0; k < cb.nodes.size(); ++k)
    if (all || redo[k]) to_search.push_back(k);
  set.searched += static_cast<long>(to_search.size());
  std::vector<std::vector<Found>> found(cb.nodes.size());
  if (!grid.cells.empty()) {
#pragma omp parallel for schedule(dynamic, 256) num_threads(thread_count(m))
    for (size_t i = 0; i < to_search.size(); ++i) found[to_search[i]] = contacts_of(m, grid, to_search[i], with_insitu);
  }

  // Join in node order, carrying the state of contacts that persist (same gridpoint and block);
  // a node not found again keeps its contacts whole.
  std::vector<Contact> list;
  list.reserve(set.list.size());
  // Contacts that book their own energy (ContactBook) carry their books along, and book what a
  // detection changes in what they store, less what is booked as prestress.
  std::vector<ContactBook> books;
  const bool booking = m.energy.by_contact;
  if (booking) set.books.resize(set.list.size());  // a set prepare() made anew has none yet
  long late = 0;
  LoadedFaces loaded(set.list);
  // The old contacts a new one keeps: a node split from another takes over only those its old
  // node kept none of (a split node's number is above its old node's, so found later).
  std::vector<char> taken(set.list.size(), 0);
  const std::unordered_map<int, int> split_from = nodes_split_from(set);
  auto kept_from = set.list.cbegin();
  for (size_t k = 0; k < cb.nodes.size(); ++k) {
    if (!all && !redo[k]) {
      const int node = cb.nodes[k];
      while (kept_from != set.list.cend() && kept_from->node < node) ++kept_from;
      for (; kept_from != set.list.cend() && kept_from->node == node; ++kept_from) {
        taken[static_cast<size_t>(kept_from - set.list.cbegin())] = 1;
        list.push_back(*kept_from);
        if (booking) books.push_back(set.books[static_cast<size_t>(kept_from - set.list.cbegin())]);
      }
      continue;
    }
    std::sort(found[k].begin(), found[k].end(),
              [](const Found& a, const Found& b) { return a.other != b.other ? a.other < b.other : a.face < b.face; });
    for (const Found& f : found[k]) {
      const double prestress_before = m.energy.prestress;
      Contact c;
      c.node = cb.nodes[k];
      c.block = cb.node_blocks[static_cast<size_t>(cb.block_first[k])];
      c.other = f.other;
      c.edge = f.edge;
      c.length = f.length;
      c.wedge = f.wedge;
      c.leads_past_a = f.leads_past_a;
      c.leads_past_b = f.leads_past_b;
      c.t = f.t;
      c.face = f.face;
      c.split = f.split;
      c.limit = cb.reach[k];
      const double facing = follow_facing(m, k, f, c);
      const ContactEdge& edge = cb.edges[static_cast<size_t>(f.edge)];
      c.material = edge.material;
      if (c.material < 0)  // the gridpoint's own side may have one
        for (int i = cb.edge_first[k]; i < cb.edge_first[k + 1] && c.material < 0; ++i)
          c.material = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])].material;
      if (c.material < 0 && f.gap > 0.0) continue;  // within reach but apart: nothing to carry yet
      if (c.material < 0) {
        const Vec2 p = at(m, c.node);
        fail("blocks {} and {} touch at ({:.6g}, {:.6g}) along {}, which has no joint material: "
             "define one with joint_material{{...}} and give it with jassign{{...}}",
             c.block + 1, c.other + 1, p.x, p.y, describe(edge));
      }
      const JointParams& p = m.joint_params[static_cast<size_t>(c.material)];
      auto old = std::lower_bound(set.list.begin(), set.list.end(), c, [](const Contact& x, const Contact& y) {
        if (x.node != y.node) return x.node < y.node;
        return x.other != y.other ? x.other < y.other : x.face < y.face;
      });
      // A contact found again keeps its state while its edge lies along the same face; found on
      // another face of the block (a side past a corner), it starts anew as any contact made
      // there: its closure, stress and length were the old face's (its in-situ closure,
      // decimetres under soft joints, pressed on a side it never touched), and carried over
      // they would make energy at the switch.
      bool found_again =
          old != set.list.end() && old->node == c.node && old->other == c.other && old->face == c.face;
      bool kept = found_again && same_face(m, old->edge, c.edge);
      // A corner pair made or undone (a crack broke at the gridpoint, or it slid off the corner)
      // numbers its faces afresh: the gridpoint's contact on this face under its other number is
      // this one. Taken for a new contact, it would be dropped and its state inherited with its
      // energy booked as given (inherit_faces): a prestress no contact stores, some 6 MJ/m in one
      // detection in the seed's Case 3.
      if (!kept)
        if (auto same = old_along_face(m, set, c.node, c.other, c.edge, [&](auto x) { return x->face != c.face; });
            same != set.list.end()) {
          old = same;
          found_again = kept = true;
        }
      // A node a released tie made carries on its old node's contact on this face, if the old
      // node kept it not: the load the joint carried there stays with the gridpoint that now
      // touches it. Taken for new, it would inherit its neighbours' state instead (LoadedFaces,
      // by pair of blocks: the old contact was the other block's) and the old one's energy be lost.
      bool carried_on = false;
      if (const auto source = split_from.find(c.node); !kept && source != split_from.end()) {
        const auto not_taken = [&](auto x) { return !taken[static_cast<size_t>(x - set.list.begin())]; };
        if (auto from = old_along_face(m, set, source->second, c.other, c.edge, not_taken); from != set.list.end()) {
          old = from;
          kept = carried_on = true;
        }
      }
      if (found_again || kept) taken[static_cast<size_t>(old - set.list.begin())] = 1;
      // Already pressed in deeper than a contact can get between two detections.
      const bool pressed_late = !first && f.gap < -kLateDepth * cb.reach[k];
      // Found so beside a corner, and held by no other block, the gridpoint came round the
      // corner: it is past the block, not in it, and no contact is made. (Held by another block,
      // it is in that one, whose face runs on along this face's line across a closed joint
      // crossing: its half-edge over this face is this face's to carry, however deep the joint
      // is closed.) Held on another face of this block before, what that contact stored goes
      // with it, booked as a restart is.
      if (!kept && pressed_late && !held_by_another(set.list, c.node, c.other) &&
          beside_a_corner(m, edge, at(m, c.node), cb.reach[k])) {
        if (found_again && m.energy.started && !m.energy.last_current)
          m.energy.restarted -= stored_in(*old, m.joint_params[static_cast<size_t>(old->material)]);
        continue;
      }
      // What it stores as a stress given below finds it, for the prestress that stress adds.
      ContactEnergy had = kept ? contact_energy(*old, m.joint_params[static_cast<size_t>(old->material)]) : ContactEnergy{};
      if (kept) {
        if (!carried_on && set.facing_known && follows_as_before(*old, c, facing)) {
          c.per_facing = old->per_facing;
          c.length = old->per_facing * facing;
        }
        keep_state(c, *old, p);
        // Its gridpoint's own boundary has changed: a crack broke at it (what that changes in its
        // length and energy goes with the crack's new faces, booked as the stress they are given
        // is), or a block that shared it was dug out (that block's part of it goes with it); or
        // the gridpoint is another, split from the old one.
        if (!set.facing_known) {
          // Read from a file without them: what it stores is taken as given, its far ends as found.
          c.given = stored_per_metre(c, p);
        } else if (carried_on || c.far_a != old->far_a || c.far_b != old->far_b) {
          had = contact_energy(c, p);
          const ContactEnergy before = contact_energy(*old, m.joint_params[static_cast<size_t>(old->material)]);
          if (m.fresh_cracks)
            book_prestress(m, had, before);
          else
            book_taken_away(m, had, before);
        }
      } else {
        // Already pressed in, and nothing held this gridpoint back before: it went into the other
        // block unseen. (At a junction a gridpoint held by one block may turn to its neighbour:
        // not lost.)
        if (pressed_late) {
          if (!held_by_another(set.list, c.node)) ++late;
        }
        // Joints as built keep their strength until they fail; blocks that touch later do not
        // stick together. A fresh crack whose joint material softens starts bonded: its
        // strength runs out over the opening or slip its fracture energies allow (a cohesive
        // crack), where one that does not soften has lost it already.
        c.intact = (first || (f.cracked && p.softens)) && (p.cohesion > 0.0 || p.tension > 0.0);
        c.state = c.intact ? ContactState::bonded : ContactState::elastic;
      }
      // A fresh crack's faces take the traction the section carried, if pressing (a crack
      // carries no tension; a cohesive one, bonded, takes it whole), on new contacts only: one
      // that was there keeps its own force for the part it had. insitu{} sets every contact's.
      // (A tip not yet pressed in, with none of its own length, has nothing to take it by.)
      const bool given = f.insitu && (with_insitu || !kept) && carrying_length(c, -f.gap) > 0.0;
      const Vec2 a = at(m, edge.a), b = at(m, edge.b);
      const Vec2 s = (1.0 / norm(b - a)) * (b - a);
      if (!kept && !given && !first) {
        const double within = kLendingReaches * cb.reach[k];
        if (const Contact* from = loaded.nearest(m, c.block, c.other, at(m, c.node), f.normal, within)) {
          inherit_faces(m, c, p, *from, f.gap, s);
          book_prestress(m, contact_energy(c, p), {});
          c.given = stored_per_metre(c, p);
        }
      }
      if (given) {
        const double gap = f.gap;
        // The half traction on this side, as the contact's force on its gridpoint.
        c.sn = dot(f.insitu_force, f.normal) / carrying_length(c, -gap);
        c.fs = dot(f.insitu_force, s);
        if (!with_insitu && c.sn < 0.0 && !c.intact) c.sn = c.fs = 0.0;
        if (c.intact && p.softens) cap_at_peak(c, p, carrying_length(c, -gap));
        c.closure0 = closure_at(p, c.sn) + gap;
        c.closure = c.closure0 - gap;
        c.dilation = c.us = c.slip = c.opened = 0.0;
        if (c.state == ContactState::open && c.sn != 0.0) c.state = c.intact ? ContactState::bonded : ContactState::elastic;
        // What the given stress stores in it is the stress's, not the method's: booked as such.
        book_prestress(m, contact_energy(c, p), had);
        c.given = stored_per_metre(c, p);
      }
      if (booking) {
        ContactBook book = kept ? set.books[static_cast<size_t>(old - set.list.begin())] : ContactBook{};
        const double stored = kept ? stored_in(*old, m.joint_params[static_cast<size_t>(old->material)]) : 0.0;
        book.made += stored_in(c, p) - stored - (m.energy.prestress - prestress_before);
        books.push_back(book);
      }
      // Found on another face, it starts anew: what that changes in its energy beyond a stress it
      // was given is the method's, named in the balance (EnergyLedger::restarted). (A detection
      // between cycling commands, a view's or a command's first, changes what commands are booked
      // with instead.)
      if (found_again && !kept && m.energy.started && !m.energy.last_current)
        m.energy.restarted += stored_in(c, p) - (m.energy.prestress - prestress_before) -
                              stored_in(*old, m.joint_params[static_cast<size_t>(old->material)]);
      list.push_back(c);
    }
  }

  // The stiffness rows.
  const size_t nodes = static_cast<size_t>(m.node_count);
  std::vector<double> rows(nodes, 0.0);
  for (const Contact& c : list) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(c.edge)];
    const JointParams& p = m.joint_params[static_cast<size_t>(c.material)];
    // A tip's force grows as its overlap squared: twice the stiffness of its length at the limit.
    const double k = kRowBound * (p.kn_max + p.ks) * std::max(c.length, 2.0 * c.wedge * c.limit);
    rows[static_cast<size_t>(c.node)] += 2.0 * k;
    rows[static_cast<size_t>(e.a)] += 2.0 * (1.0 - c.t) * k;
    rows[static_cast<size_t>(e.b)] += 2.0 * c.t * k;
    if (c.per_facing > 0.0 && c.length > 0.0) {
      // The push that pays for its length's changes (contact_force.hpp) stiffens it as well: by
      // its normal stress, and by its energy per metre over the shorter of its half-edges.
      const Vec2 q = at(m, c.node);
      const double half = 0.5 * std::min(norm(q - at(m, c.far_a)), norm(at(m, c.far_b) - q));
      const double turn = kRowBound * c.per_facing * (std::fabs(c.sn) + stored_in(c, p) / c.length / half);
      for (const int node : {c.node, e.a, e.b, c.far_a, c.far_b}) rows[static_cast<size_t>(node)] += 2.0 * turn;
    }
  }
  set.list = std::move(list);
  set.split_from.clear();
  if (booking) set.books = std::move(books);
  set.late += late;
  gather_contact_forces(set, cb, m.node_count);
  set.rows = std::move(rows);
  set.detected = true;
  set.as_built = false;
  if (all) set.facing_known = true;
  if (with_insitu) set.from_insitu = false;
  if (m.fresh_cracks) {
    for (Section& s : m.sections) s.fresh = false;
    m.fresh_cracks = false;
  }
}

// Per mesh block: the most any of its boundary nodes has moved from where it was last marked
// (ContactSet::x_detected), plus what it will move by `ahead` cycles at its speed now, twice.
std::vector<double> block_motion(const Mechanics& m, double ahead) {
  const ContactBoundary& cb = m.faces;
  std::vector<double> moved(cb.block_first_edge.size() - 1, 0.0);
  for (size_t k = 0; k < cb.nodes.size(); ++k) {
    const size_t n = static_cast<size_t>(cb.nodes[k]);
    const Vec2 now = at(m, cb.nodes[k]);
    const double dx = now.x - m.contacts.x_detected[2 * n], dy = now.y - m.contacts.x_detected[2 * n + 1];
    const double coming = 2.0 * ahead * m.step * std::sqrt(m.v[2 * n] * m.v[2 * n] + m.v[2 * n + 1] * m.v[2 * n + 1]);
    const double d = std::sqrt(dx * dx + dy * dy) + coming;
    for (int i = cb.block_first[k]; i < cb.block_first[k + 1]; ++i) {
      double& b = moved[static_cast<size_t>(cb.node_blocks[static_cast<size_t>(i)])];
      b = std::max(b, d);
    }
  }
  return moved;
}

// Marks the blocks whose boxes come within `slack` of block `of`'s.
void mark_near(const BlockGrid& grid, int of, double slack, std::vector<char>& near) {
  const Box& box = grid.boxes[static_cast<size_t>(of)];
  if (box.x0 > box.x1) return;
  for (int j = grid.row(box.y0 - slack); j <= grid.row(box.y1 + slack); ++j)
    for (int i = grid.column(box.x0 - slack); i <= grid.column(box.x1 + slack); ++i)
      for (const int other : grid.at(i, j)) {
        const Box& b = grid.boxes[static_cast<size_t>(other)];
        if (b.x0 <= box.x1 + slack && b.x1 >= box.x0 - slack && b.y0 <= box.y1 + slack && b.y1 >= box.y0 - slack)
          near[static_cast<size_t>(other)] = 1;
      }
}

void mark_positions(Mechanics& m, const std::vector<char>& moved_block) {
  const ContactBoundary& cb = m.faces;
  std::vector<double>& x = m.contacts.x_detected;
  if (moved_block.empty()) {
    x.resize(m.u.size());
    for (size_t dof = 0; dof < m.u.size(); ++dof) x[dof] = m.origin[dof] + m.u[dof];
    return;
  }
  for (size_t k = 0; k < cb.nodes.size(); ++k)
    for (int i = cb.block_first[k]; i < cb.block_first[k + 1]; ++i)
      if (moved_block[static_cast<size_t>(cb.node_blocks[static_cast<size_t>(i)])]) {
        const size_t n = static_cast<size_t>(cb.nodes[k]);
        x[2 * n] = m.origin[2 * n] + m.u[2 * n];
        x[2 * n + 1] = m.origin[2 * n + 1] + m.u[2 * n + 1];
        break;
      }
}

}  // namespace

void mark_glued_tips(ContactBoundary& cb, const std::vector<double>& position) {
  const auto ref = [&](int node) {
    return Vec2{position[2 * static_cast<size_t>(node)], position[2 * static_cast<size_t>(node) + 1]};
  };
  // Glued edges by their ends: the two faces of a glued cut have their gridpoints at exactly the
  // same places (zoning.hpp), in opposite order.
  std::map<std::array<double, 4>, int> glued;
  const auto key = [&](Vec2 from, Vec2 to) { return std::array<double, 4>{from.x, from.y, to.x, to.y}; };
  for (size_t i = 0; i < cb.edges.size(); ++i) {
    const ContactEdge& e = cb.edges[i];
    if (!e.touchable) glued.emplace(key(ref(e.a), ref(e.b)), static_cast<int>(i));
  }
  const auto twin = [&](int edge) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(edge)];
    const auto found = glued.find(key(ref(e.b), ref(e.a)));
    return found == glued.end() ? -1 : found->second;
  };
  // The touchable edge the outline of the rock glued together goes on along from `edge`'s end b
  // (at_b) or comes in by to its end a, turning round that end across the glued edges; -1 for
  // none (a glued edge with no twin, or more glued edges about the end than a fan can have).
  const auto goes_on = [&](const ContactEdge& edge, bool at_b) {
    int beside = at_b ? edge.next : edge.prev;
    for (int turn = 0; turn < 16; ++turn) {
      const ContactEdge& b = cb.edges[static_cast<size_t>(beside)];
      if (b.touchable) return beside;
      const int other = twin(beside);
      if (other < 0) return -1;
      beside = at_b ? cb.edges[static_cast<size_t>(other)].next : cb.edges[static_cast<size_t>(other)].prev;
    }
    return -1;
  };
  // A convex corner at `e`'s end b (at_b) or a whose edge beside is glued, where the outline of
  // the rock glued together turns outward too (by more than 10 deg, as a corner).
  const double sin10 = std::sin(10.0 * M_PI / 180.0);
  const auto glued_tip = [&](const ContactEdge& e, bool at_b) {
    if (!(at_b ? e.corner_b : e.corner_a) || cb.edges[static_cast<size_t>(at_b ? e.next : e.prev)].touchable)
      return false;
    const int on = goes_on(e, at_b);
    if (on < 0) return false;
    const ContactEdge& o = cb.edges[static_cast<size_t>(on)];
    const Vec2 along = ref(e.b) - ref(e.a), beyond = ref(o.b) - ref(o.a);
    const Vec2 in = at_b ? along : beyond, out = at_b ? beyond : along;  // into the end, out of it
    return cross(in, out) > sin10 * norm(in) * norm(out);
  };
  for (ContactEdge& e : cb.edges) {
    e.glued_tip_a = e.touchable && glued_tip(e, false);
    e.glued_tip_b = e.touchable && glued_tip(e, true);
    e.glued_line_a = e.glued_tip_a ? e.prev : -1;
    e.glued_line_b = e.glued_tip_b ? e.next : -1;
  }
  // Along a straight run of touchable edges (zone edges along one face) each edge leads to the
  // tip the run ends at: a gridpoint at a vertex inside the run, found on either edge there, is
  // inside by its depth inside the same glued line. Taken only on the tip's own edge, that depth
  // jumped at the vertex from out of the block to the depth behind the face's line: 1.3 m, found
  // on the next edge, in the seed cavern's Case 3 at 158 m.
  const auto straight_to = [&](const ContactEdge& e, bool at_b) {
    const int on = at_b ? e.next : e.prev;
    const bool straight = at_b ? !e.corner_b && !e.bent_b : !e.corner_a && !e.bent_a;
    return straight && cb.edges[static_cast<size_t>(on)].touchable ? on : -1;
  };
  for (size_t i = 0; i < cb.edges.size(); ++i)
    for (const bool at_b : {false, true}) {
      const int line = at_b ? cb.edges[i].glued_line_b : cb.edges[i].glued_line_a;
      if (line < 0 || !(at_b ? cb.edges[i].glued_tip_b : cb.edges[i].glued_tip_a)) continue;
      // Back along the run from the tip: each edge before leads on to it at its end towards it.
      int edge = straight_to(cb.edges[i], !at_b);
      for (size_t steps = 0; edge >= 0 && edge != static_cast<int>(i) && steps < cb.edges.size(); ++steps) {
        ContactEdge& run = cb.edges[static_cast<size_t>(edge)];
        (at_b ? run.glued_line_b : run.glued_line_a) = line;
        edge = straight_to(run, !at_b);
      }
    }
}

void gather_contact_forces(ContactSet& set, const ContactBoundary& cb, int node_count) {
  const size_t nodes = static_cast<size_t>(node_count);
  const auto roles = [&](const Contact& c) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(c.edge)];
    return std::array<int, kContactRoles>{c.node, e.a, e.b, c.far_a, c.far_b};
  };
  std::vector<int> first_slot(nodes + 1, 0);
  for (const Contact& c : set.list)
    for (const int node : roles(c))
      if (node >= 0) ++first_slot[static_cast<size_t>(node) + 1];
  for (size_t n = 0; n < nodes; ++n) first_slot[n + 1] += first_slot[n];
  std::vector<int> gather(static_cast<size_t>(first_slot[nodes]));
  std::vector<int> fill(first_slot.begin(), first_slot.end() - 1);
  for (size_t i = 0; i < set.list.size(); ++i) {
    const std::array<int, kContactRoles> node = roles(set.list[i]);
    for (int role = 0; role < kContactRoles; ++role)
      if (node[static_cast<size_t>(role)] >= 0)
        gather[static_cast<size_t>(fill[static_cast<size_t>(node[static_cast<size_t>(role)])]++)] =
            kContactRoles * static_cast<int>(i) + role;
  }
  set.gather_first = std::move(first_slot);
  set.gather = std::move(gather);
}

double median_edge_length(const ContactBoundary& cb, const std::vector<double>& position) {
  std::vector<double> lengths;
  for (const ContactEdge& e : cb.edges)
    if (e.touchable)
      lengths.push_back(std::hypot(position[2 * static_cast<size_t>(e.b)] - position[2 * static_cast<size_t>(e.a)],
                                   position[2 * static_cast<size_t>(e.b) + 1] - position[2 * static_cast<size_t>(e.a) + 1]));
  if (lengths.empty()) return 0.0;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<long>(lengths.size() / 2), lengths.end());
  return lengths[lengths.size() / 2];
}

double overlap_limit(const Mechanics& m) {
  if (m.settings.overlap > 0.0) return m.settings.overlap;
  double curve = 0.0;
  for (const JointParams& p : m.joint_params) curve = std::max(curve, p.curve_closure);
  return 0.5 * m.faces.median_edge + curve;
}

void detect_contacts(Mechanics& m) {
  find_contacts(m, block_grid(m, largest_reach(m)), {});
  mark_positions(m, {});
  m.contacts.partial = false;
}

bool refresh_contacts(Mechanics& m, double ahead) {
  const ContactBoundary& cb = m.faces;
  if (cb.touchable_blocks < 2) return false;  // nothing can ever touch
  const ContactSet& set = m.contacts;
  if (!set.detected || set.as_built || set.from_insitu || m.fresh_cracks || !set.facing_known) {
    detect_contacts(m);
    return true;
  }
  const double limit = kStaleMotion * cb.min_reach;
  const std::vector<double> moved = block_motion(m, ahead);
  // While every contact dates from one search, any two nodes have moved apart by no more than
  // twice the most either moved: nothing is due before a block moves twice the limit.
  double most = 0.0;
  for (size_t b = 0; b < moved.size(); ++b)
    if (m.block_live[b]) most = std::max(most, moved[b]);
  if (most <= (set.partial ? limit : 2.0 * limit)) return false;
  std::vector<char> stale(moved.size(), 0);
  for (size_t b = 0; b < moved.size(); ++b)
    if (m.block_live[b] && moved[b] > limit) stale[b] = 1;
  // A node kept may have lain within its reach of a block that has moved since, by up to four
  // limits relatively: the blocks that near are found again too.
  const double max_reach = largest_reach(m);
  const BlockGrid grid = block_grid(m, max_reach);
  if (grid.cells.empty()) return false;
  std::vector<char> redo_block(moved.size(), 0);
  for (size_t b = 0; b < stale.size(); ++b)
    if (stale[b]) {
      redo_block[b] = 1;
      mark_near(grid, static_cast<int>(b), max_reach + 4.0 * limit, redo_block);
    }
  std::vector<char> redo(cb.nodes.size(), 0);
  size_t count = 0;
  for (size_t k = 0; k < cb.nodes.size(); ++k) {
    for (int i = cb.block_first[k]; i < cb.block_first[k + 1] && !redo[k]; ++i)
      redo[k] = redo_block[static_cast<size_t>(cb.node_blocks[static_cast<size_t>(i)])];
    count += static_cast<size_t>(redo[k]);
  }
  if (2 * count > cb.nodes.size()) {  // most of the model: all, and every block marked afresh
    detect_contacts(m);
    return true;
  }
  find_contacts(m, grid, redo);
  mark_positions(m, stale);
  m.contacts.partial = true;
  return true;
}

}  // namespace edem
