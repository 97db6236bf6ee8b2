// Block cutting with CGAL's exact arrangement (see cutter.hpp for the contract).
//
// Per base polygon: pieces (base edges and cut polylines) go into an Arrangement_2 over an
// exact kernel; each edge carries the set of pieces it came from. Faces inside the base are
// blocks; edges with the same face on both sides are dangling cut pieces, dropped and counted.
// Before extracting blocks, features below the tolerance are removed by bending cut pieces
// through nearby vertices, rounded (never moving the base), rebuilding until none is left.
#include "geom/cutter.hpp"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "core/error.hpp"

namespace edem {

std::string_view to_string(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::boundary: return "boundary";
    case EdgeKind::joint: return "joint";
    case EdgeKind::crack: return "crack";
    case EdgeKind::region: return "region";
    case EdgeKind::potential: return "potential";
  }
  return "?";
}

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;
using Vertex = Arrangement::Vertex_const_handle;

constexpr int kMaxSnapRounds = 12;
constexpr int kMaxLeftOut = 200;  // optional pieces left out of one base before it fails all the same
constexpr int kMaxRestarts = 4;   // fresh starts of one base with the optional cuts near a spot left out
constexpr double kFirstRestartRadius = 8.0;  // [tolerances] the first restart's radius
constexpr int kMaxKeptSpots = 100;  // spots of one base where slivers below the zone-size tolerance are kept

// A polyline that goes into the arrangement: a base outline, a region outline (both
// closed) or one (clipped) cut.
struct Piece {
  std::vector<Point> points;
  EdgeOrigin origin;
  bool closed = false;  // the last point joins the first
  bool base = false;    // base outlines never move
  bool optional = false;  // may be left out (CutSegment::optional)
  bool last_resort = false;  // may be left out once no optional piece can be (CutSegment::last_resort)
  bool left_out = false;  // it was: not in the arrangement any more
  double min_angle = 0.0;  // [rad] an optional piece meeting another edge at a sharper corner is cut back
  size_t segment_count() const { return closed ? points.size() : points.size() - 1; }
  // Points that repeat the one before (or, closed, the first) go.
  void drop_repeats() {
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (closed && points.size() > 1 && points.front() == points.back()) points.pop_back();
  }
  Segment segment(size_t i) const { return Segment(points[i], points[(i + 1) % points.size()]); }
  // Distance from p to segment i, in doubles (for choosing, not for the geometry).
  double distance(size_t i, Vec2 p) const;
};

Point to_point(Vec2 p) { return Point(p.x, p.y); }
Vec2 to_vec(const Point& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

double Piece::distance(size_t i, Vec2 p) const {
  const Vec2 a = to_vec(points[i]), b = to_vec(points[(i + 1) % points.size()]);
  const Vec2 d = b - a;
  const double t = std::clamp(dot(p - a, d) / std::max(dot(d, d), 1e-300), 0.0, 1.0);
  return norm(a + t * d - p);
}

// Parts of segment ab strictly inside the polygon, computed exactly.
std::vector<std::pair<Point, Point>> clip_segment(const Point& a, const Point& b,
                                                   const std::vector<Point>& polygon) {
  std::vector<Point> cuts{a, b};
  const size_t n = polygon.size();
  const Segment s(a, b);
  for (size_t i = 0; i < n; ++i) {
    const Segment edge(polygon[i], polygon[(i + 1) % n]);
    const auto hit = CGAL::intersection(s, edge);
    if (!hit) continue;
    if (const Point* p = boost::get<Point>(&*hit)) {
      cuts.push_back(*p);
    } else if (const Segment* overlap = boost::get<Segment>(&*hit)) {
      cuts.push_back(overlap->source());
      cuts.push_back(overlap->target());
    }
  }
  // Sort along ab (exactly, by squared distance from a) and keep inside pieces.
  std::sort(cuts.begin(), cuts.end(), [&](const Point& p, const Point& q) {
    return CGAL::compare_distance_to_point(a, p, q) == CGAL::SMALLER;
  });
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<std::pair<Point, Point>> inside;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const Point mid = CGAL::midpoint(cuts[i], cuts[i + 1]);
    if (CGAL::bounded_side_2(polygon.begin(), polygon.end(), mid, Kernel()) ==
        CGAL::ON_BOUNDED_SIDE) {
      if (!inside.empty() && inside.back().second == cuts[i])
        inside.back().second = cuts[i + 1];
      else
        inside.emplace_back(cuts[i], cuts[i + 1]);
    }
  }
  return inside;
}

// Lower kinds take precedence; a joint along a glued outline is a joint, and so is a potential
// crack (a glued outline is intact rock, which the crack's bond stands for until it breaks; cuts
// bent onto an outline to avoid a sliver keep their section).
EdgeOrigin edge_origin(const Halfedge& h, const std::vector<Piece>& pieces) {
  auto rank = [](const EdgeOrigin& o) {
    if (o.kind == EdgeKind::region && o.glued) return static_cast<int>(EdgeKind::potential) + 1;
    return static_cast<int>(o.kind);
  };
  EdgeOrigin best;
  bool first = true;
  for (int id : h->curve().data()) {
    const EdgeOrigin& o = pieces[id].origin;
    if (first || rank(o) < rank(best) || (rank(o) == rank(best) && o.source < best.source)) best = o;
    first = false;
  }
  return best;
}

bool has_base_piece(const Halfedge& h, const std::vector<Piece>& pieces) {
  for (int id : h->curve().data())
    if (pieces[id].base) return true;
  return false;
}

template <typename Circulator>
std::vector<Halfedge> ccb_halfedges(Circulator start) {
  std::vector<Halfedge> ring;
  Circulator c = start;
  do ring.push_back(c);
  while (++c != start);
  return ring;
}

struct FaceRings {
  Face face;
  std::vector<Halfedge> outer;
  std::vector<std::vector<Halfedge>> holes;
};

class BaseCutter {
 public:
  BaseCutter(const Polygon& base, int base_index, std::vector<Piece> cut_pieces,
             const std::vector<Polygon>& regions, double tolerance, const std::function<double(Vec2)>& local)
      : base_index_(base_index), regions_(regions), tolerance_(tolerance), local_(local) {
    Piece outline;
    for (Vec2 p : base) outline.points.push_back(to_point(p));
    outline.origin = {EdgeKind::boundary, -1, base_index, false};
    outline.closed = true;
    outline.base = true;
    base_vertices_ = outline.points;
    pieces_.push_back(std::move(outline));
    for (auto& piece : cut_pieces) pieces_.push_back(std::move(piece));
  }

  // Lays the cuts into `out`; false (and nothing laid) where bending goes round in circles and
  // nothing is left to give way: stuck_at() says where, fail_stuck() throws the message.
  bool run(BlockSet& out) {
    int snapped = 0;
    // The cuts as laid first: each end within the tolerance of an edge reaches it (before the
    // bending below, whose dangling pieces are dropped).
    for (int pass = 0; pass < kMaxSnapRounds; ++pass) {
      build();
      inside_faces_ = find_inside_faces();
      fixed_at_.clear();
      const int reached = snap_free_ends();
      if (reached == 0) break;
      snapped += reached;
    }
    for (int round = 0;; ++round) {
      build();
      inside_faces_ = find_inside_faces();
      dropped_ = count_dangling_pieces();
      remove_dangling_edges();
      collect_rings();
      fixed_at_.clear();
      bent_in_round_.clear();
      const int fixes = snap_small_features();
      if (fixes == 0) {
        // Clean: now cut back the optional pieces that make a sharp corner, then clean again.
        const int cut = cut_back_sharp_corners();
        if (cut == 0) break;
        cut_back_ += cut;
        round = -1;
        continue;
      }
      snapped += fixes;
      if (round + 1 < kMaxSnapRounds) continue;
      // Bending goes round in circles: the optional cuts still being bent give way (else the
      // last-resort ones), and the rest get half the rounds again to settle.
      if (left_out_ < kMaxLeftOut &&
          (leave_out(bent_in_round_, false) || leave_out(bent_in_round_, true))) {
        round = kMaxSnapRounds / 2 - 1;
        continue;
      }
      return false;
    }
    out.snapped_vertices += snapped;
    out.dropped_cuts += dropped_;
    out.cuts_left_out += left_out_;
    out.cuts_cut_back += cut_back_;
    extract(out);
    return true;
  }

  Vec2 stuck_at() const { return last_fix_; }

  [[noreturn]] void fail_stuck() const {
    fail("cannot resolve geometry features smaller than the tolerance ({:.3g} m) in block {}: "
         "near ({:.4g}, {:.4g}) {} keep coming closer than that after being bent together "
         "(cuts crossing at a shallow angle?); move the cuts apart or change "
         "model{{tolerance=}} or zone{{ sliver = }}",
         tolerance_at(last_fix_), base_index_ + 1, last_fix_.x, last_fix_.y, describe_pieces(last_bent_));
  }

  // The tolerance at p [m], and its square as an exact number.
  double tolerance_at(Vec2 p) const { return local_ ? std::max(tolerance_, local_(p)) : tolerance_; }
  Kernel::FT tolerance2_at(const Point& p) const {
    const double t = tolerance_at(to_vec(p));
    return Kernel::FT(t * t);
  }

 private:
  // Leaves out, of each optional (or, with last_resort, each last-resort) piece bent at p, the
  // segment nearest to p: a piece that is one segment goes, a longer one splits in two there.
  // False if there was none.
  bool leave_out(const std::vector<std::pair<int, Vec2>>& bent, bool last_resort) {
    std::vector<int> done;
    for (const auto& [id, p] : bent) {
      const Piece& candidate = pieces_[static_cast<size_t>(id)];
      if (!(last_resort ? candidate.last_resort : candidate.optional) || candidate.left_out ||
          std::find(done.begin(), done.end(), id) != done.end())
        continue;
      done.push_back(id);
      ++left_out_;
      Piece& piece = pieces_[static_cast<size_t>(id)];
      size_t nearest = 0;
      double best = INFINITY;
      for (size_t i = 0; i < piece.segment_count(); ++i) {
        const double distance = piece.distance(i, p);
        if (distance < best) best = distance, nearest = i;
      }
      Piece after = piece;
      after.points.erase(after.points.begin(), after.points.begin() + static_cast<long>(nearest) + 1);
      piece.points.resize(nearest + 1);
      if (piece.points.size() < 2) piece.left_out = true;
      if (after.points.size() >= 2) pieces_.push_back(std::move(after));
    }
    return !done.empty();
  }

  void build() {
    arrangement_.clear();
    std::vector<Traits::Curve_2> curves;
    for (size_t id = 0; id < pieces_.size(); ++id) {
      const Piece& piece = pieces_[id];
      if (piece.left_out) continue;
      for (size_t i = 0; i < piece.segment_count(); ++i) {
        const Segment s = piece.segment(i);
        if (!s.is_degenerate()) curves.emplace_back(s, static_cast<int>(id));
      }
    }
    CGAL::insert(arrangement_, curves.begin(), curves.end());
  }

  // Faces reachable from the unbounded face without crossing an edge for which `blocks`
  // is true. A closed outline of blocking edges keeps everything inside it unreached.
  template <typename Blocks>
  std::unordered_set<const void*> faces_reached_from_outside(Blocks blocks) const {
    std::unordered_set<const void*> reached{&*arrangement_.unbounded_face()};
    std::queue<Face> queue;
    queue.push(arrangement_.unbounded_face());
    auto visit_ccb = [&](auto start) {
      auto c = start;
      do {
        Halfedge h = c;
        Face other = h->twin()->face();
        if (!blocks(h) && reached.insert(&*other).second) queue.push(other);
      } while (++c != start);
    };
    while (!queue.empty()) {
      Face f = queue.front();
      queue.pop();
      if (!f->is_unbounded()) visit_ccb(f->outer_ccb());
      for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) visit_ccb(*ic);
    }
    return reached;
  }

  // Faces inside the base: those not reached without crossing a base edge.
  std::unordered_set<const void*> find_inside_faces() const {
    const auto outside =
        faces_reached_from_outside([&](const Halfedge& h) { return has_base_piece(h, pieces_); });
    std::unordered_set<const void*> inside;
    for (auto f = arrangement_.faces_begin(); f != arrangement_.faces_end(); ++f)
      if (!outside.count(&*f)) inside.insert(&*f);
    return inside;
  }

  bool is_dangling(const Halfedge& h) const {
    return h->face() == h->twin()->face() && inside_faces_.count(&*h->face());
  }

  // Connected groups of dangling edges inside the base: the cut pieces UDEC would drop.
  int count_dangling_pieces() const {
    std::unordered_map<const void*, int> index;  // vertex -> union-find slot
    std::vector<int> parent;
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    auto slot = [&](Vertex v) {
      auto [it, added] = index.try_emplace(&*v, static_cast<int>(parent.size()));
      if (added) parent.push_back(it->second);
      return it->second;
    };
    for (auto e = arrangement_.edges_begin(); e != arrangement_.edges_end(); ++e) {
      Halfedge h = e;
      if (is_dangling(h)) parent[find(slot(h->source()))] = find(slot(h->target()));
    }
    int groups = 0;
    for (size_t i = 0; i < parent.size(); ++i)
      if (find(static_cast<int>(i)) == static_cast<int>(i)) ++groups;
    return groups;
  }

  // Removing a dangling edge merges no faces; a piece that bridged an outer boundary to a
  // hole goes, and the hole becomes a boundary component of its own.
  void remove_dangling_edges() {
    std::vector<Arrangement::Halfedge_handle> dangling;
    for (auto e = arrangement_.edges_begin(); e != arrangement_.edges_end(); ++e)
      if (is_dangling(e)) dangling.push_back(e);
    for (auto h : dangling) arrangement_.remove_edge(h);
  }

  void collect_rings() {
    inside_.clear();
    for (auto f = arrangement_.faces_begin(); f != arrangement_.faces_end(); ++f) {
      if (!inside_faces_.count(&*f)) continue;
      Face face = f;
      FaceRings rings{face, ccb_halfedges(face->outer_ccb()), {}};
      for (auto ic = face->inner_ccbs_begin(); ic != face->inner_ccbs_end(); ++ic)
        rings.holes.push_back(ccb_halfedges(*ic));
      inside_.push_back(std::move(rings));
    }
  }

  bool is_base_vertex(const Point& p) const {
    return std::find(base_vertices_.begin(), base_vertices_.end(), p) != base_vertices_.end();
  }

  // Cut pieces that pass through vertex v.
  std::vector<int> cut_pieces_at(Vertex v) const {
    std::vector<int> ids;
    auto c = v->incident_halfedges();
    const auto start = c;
    do {
      for (int id : c->curve().data())
        if (!pieces_[id].base && std::find(ids.begin(), ids.end(), id) == ids.end())
          ids.push_back(id);
    } while (++c != start);
    return ids;
  }

  // Make piece `id` pass through q: move its nearest vertex there if that one is within
  // the tolerance, else insert q into the nearest segment.
  bool bend(int id, const Point& q) {
    Piece& piece = pieces_[id];
    auto& pts = piece.points;
    size_t nearest_vertex = 0;
    for (size_t i = 1; i < pts.size(); ++i)
      if (CGAL::compare_distance_to_point(q, pts[i], pts[nearest_vertex]) == CGAL::SMALLER)
        nearest_vertex = i;
    if (pts[nearest_vertex] == q) return drop_close_neighbours(id, nearest_vertex);
    if (CGAL::compare(CGAL::squared_distance(q, pts[nearest_vertex]), tolerance2_at(q)) ==
        CGAL::SMALLER) {
      pts[nearest_vertex] = q;
    } else {
      size_t nearest_segment = 0;
      Kernel::FT best = CGAL::squared_distance(q, piece.segment(0));
      for (size_t i = 1; i < piece.segment_count(); ++i) {
        const Kernel::FT d = CGAL::squared_distance(q, piece.segment(i));
        if (d < best) {
          best = d;
          nearest_segment = i;
        }
      }
      pts.insert(pts.begin() + static_cast<long>(nearest_segment) + 1, q);
    }
    piece.drop_repeats();
    return true;
  }

  // Piece `id` already has vertex k where it is bent to: its neighbours closer than the
  // tolerance to it go (a small feature the piece makes by itself), and so does a neighbour the
  // piece folds back at, running out to it along a segment and back to q beside that segment
  // (a spike: bent by its two ends in turn, a piece can fold so, and no bend through q unfolds
  // it). False if none went.
  bool drop_close_neighbours(int id, size_t k) {
    auto& pts = pieces_[static_cast<size_t>(id)].points;
    const Point q = pts[k];
    const auto close = [&](size_t i) {
      return CGAL::compare(CGAL::squared_distance(q, pts[i]), tolerance2_at(q)) == CGAL::SMALLER;
    };
    const auto near_segment = [&](size_t i, size_t j) {
      return CGAL::compare(CGAL::squared_distance(q, Segment(pts[i], pts[j])), tolerance2_at(q)) == CGAL::SMALLER;
    };
    const size_t before = pts.size();
    if (k + 1 < pts.size() && pts.size() > 2 &&
        (close(k + 1) || (k + 2 < pts.size() && near_segment(k + 1, k + 2))))
      pts.erase(pts.begin() + static_cast<long>(k) + 1);
    if (k > 0 && pts.size() > 2 && (close(k - 1) || (k > 1 && near_segment(k - 2, k - 1))))
      pts.erase(pts.begin() + static_cast<long>(k) - 1);
    return pts.size() != before;
  }

  // q as a point of few bits: on an edge of the base, the point along that edge at the nearest
  // parameter that is a double (so that it stays on the edge exactly); elsewhere q rounded to
  // doubles. Bending cuts to the exact crossings of cuts already bent would chain constructions
  // on constructions, whose exact numbers grow with every round of bending.
  Point rounded(const Point& q) const {
    if (is_base_vertex(q)) return q;
    const size_t n = base_vertices_.size();
    for (size_t i = 0; i < n; ++i) {
      const Point& a = base_vertices_[i];
      const Point& b = base_vertices_[(i + 1) % n];
      if (!Segment(a, b).has_on(q)) continue;
      // The parameter computed exactly, so that a point made here is its own rounding.
      const Kernel::Vector_2 d = b - a;
      const Kernel::FT t(std::clamp(CGAL::to_double(((q - a) * d) / d.squared_length()), 0.0, 1.0));
      return a + t * d;
    }
    return to_point(to_vec(q));
  }

  // Piece `id`, which passes through p, passes through q instead: its vertex at p moves to q, or
  // q goes into its segment through p. Nothing else of it moves.
  bool reroute(int id, const Point& p, const Point& q) {
    Piece& piece = pieces_[static_cast<size_t>(id)];
    auto& pts = piece.points;
    const auto at = std::find(pts.begin(), pts.end(), p);
    if (at != pts.end()) {
      *at = q;
    } else {
      size_t i = 0;
      while (i < piece.segment_count() && !piece.segment(i).has_on(p)) ++i;
      if (i == piece.segment_count()) return bend(id, q);
      pts.insert(pts.begin() + static_cast<long>(i) + 1, q);
    }
    piece.drop_repeats();
    return true;
  }

  // Bends the cuts `ids` to q, the rounded position of vertex `at` (if there is one), and moves
  // the cuts through `at` there too: all of them then meet exactly at q.
  bool bend_all(const std::vector<int>& ids, std::optional<Vertex> at, const Point& q) {
    bool changed = false;
    for (int id : ids) changed |= bend(id, q);
    if (at && (*at)->point() != q)
      for (int id : cut_pieces_at(*at))
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) changed |= reroute(id, (*at)->point(), q);
    return changed;
  }

  // Resolve a vertex v closer than the tolerance to an edge e it is not on.
  bool fix(Vertex v, Halfedge e) {
    const Point& p = v->point();
    const bool v_fixed = is_base_vertex(p);
    const bool e_base = has_base_piece(e, pieces_);
    // A nearby end of e: bring v's cuts to it (the two vertices become one).
    if (const std::optional<Vertex> w = end_near(p, e); w && !v_fixed)
      return bend_all(cut_pieces_at(v), *w, rounded((*w)->point()));
    if (!e_base) {
      // Bend e's cuts through v.
      const auto& on_e = e->curve().data();
      return bend_all(std::vector<int>(on_e.begin(), on_e.end()), v, rounded(p));
    }
    if (v_fixed) return false;  // the base's own features are the user's geometry
    // v (a cut vertex) near a base edge: move it onto the edge.
    return bend_all(cut_pieces_at(v), std::nullopt, foot(p, e));
  }

  // The foot of p's perpendicular on the line of edge e, rounded.
  Point foot(const Point& p, Halfedge e) const {
    const Segment s(e->source()->point(), e->target()->point());
    return rounded(s.supporting_line().projection(p));
  }

  // An end of e within the tolerance of p, if there is one.
  std::optional<Vertex> end_near(const Point& p, Halfedge e) const {
    for (Vertex w : {e->source(), e->target()})
      if (CGAL::compare(CGAL::squared_distance(p, w->point()), tolerance2_at(p)) == CGAL::SMALLER)
        return w;
    return std::nullopt;
  }

  // Whether p lies more than `slack` outside edge e's bounding box (in doubles).
  static bool outside_box(Vec2 p, const Halfedge& e, double slack) {
    const Vec2 a = to_vec(e->source()->point()), b = to_vec(e->target()->point());
    return p.x < std::min(a.x, b.x) - slack || p.x > std::max(a.x, b.x) + slack ||
           p.y < std::min(a.y, b.y) - slack || p.y > std::max(a.y, b.y) + slack;
  }

  // Brings the free end v of a cut onto edge e, within the tolerance of it: to an end of e that
  // near, else to the foot of its perpendicular, which e's pieces then pass through too. The cut
  // moves, not e: a joint keeps its line.
  bool reach(Vertex v, Halfedge e) {
    const Point& p = v->point();
    if (const std::optional<Vertex> w = end_near(p, e))
      return bend_all(cut_pieces_at(v), *w, rounded((*w)->point()));
    std::vector<int> ids = cut_pieces_at(v);
    if (!has_base_piece(e, pieces_)) ids.insert(ids.end(), e->curve().data().begin(), e->curve().data().end());
    return bend_all(ids, std::nullopt, foot(p, e));
  }

  // "joint set 1 and crackseed 2": the inputs the pieces come from, as a script names them.
  std::string describe_pieces(const std::vector<int>& ids) const {
    std::vector<std::string> names;
    for (int id : ids) {
      const EdgeOrigin& o = pieces_[id].origin;
      std::string name;
      switch (o.kind) {
        case EdgeKind::boundary: name = "the block's outline"; break;
        case EdgeKind::joint: name = fmt::format("joint set {}", o.set + 1); break;
        case EdgeKind::crack: name = fmt::format("crack {}", o.source + 1); break;
        case EdgeKind::region:
          name = o.source >= 0 ? fmt::format("region {}", o.source + 1) : "the outline of a crackseed{ auto } group";
          break;
        case EdgeKind::potential: name = fmt::format("crackseed {}", o.source + 1); break;
      }
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    if (names.empty()) return "cuts";
    if (names.size() == 1) return fmt::format("cuts of {}", names[0]);
    std::string out = names[0];
    for (size_t i = 1; i + 1 < names.size(); ++i) out += ", " + names[i];
    return fmt::format("cuts of {} and {}", out, names.back());
  }

  // Fixes every small feature not near one fixed earlier in this round: there the arrangement
  // is stale until it is rebuilt (a fix bends whole cuts, but elsewhere by less than the
  // tolerance, and the last round checks everything afresh). One fix a round ran out of rounds
  // where a crackseed{} lays its cuts across the joints.
  int snap_small_features() {
    const size_t before = fixed_at_.size();
    for (const FaceRings& face : inside_) {
      std::vector<Halfedge> edges = face.outer;
      for (const auto& hole : face.holes) edges.insert(edges.end(), hole.begin(), hole.end());
      for (const Halfedge& hv : edges) {
        const Vertex v = hv->source();
        const Vec2 pv = to_vec(v->point());
        const double tolerance = tolerance_at(pv), slack = 4.0 * tolerance;
        const Kernel::FT tolerance2(tolerance * tolerance);
        if (near_a_fix(pv, slack)) continue;
        for (const Halfedge& he : edges) {
          if (he->source() == v || he->target() == v) continue;
          if (outside_box(pv, he, slack)) continue;  // a cheap double-precision filter first
          const Segment s(he->source()->point(), he->target()->point());
          if (CGAL::compare(CGAL::squared_distance(v->point(), s), tolerance2) !=
              CGAL::SMALLER)
            continue;
          std::vector<int> ids = cut_pieces_at(v);
          for (int id : he->curve().data()) ids.push_back(id);
          if (fix(v, he)) {
            fixed_at_.push_back(pv);
            last_fix_ = pv;
            last_bent_ = ids;
            for (int id : ids) bent_in_round_.emplace_back(id, pv);
            break;
          }
        }
      }
    }
    return static_cast<int>(fixed_at_.size() - before);
  }

  // Whether p is within twice `slack` of a fix made in this round (in x and in y).
  bool near_a_fix(Vec2 p, double slack) const {
    return std::any_of(fixed_at_.begin(), fixed_at_.end(), [&](Vec2 q) {
      return std::abs(p.x - q.x) < 2.0 * slack && std::abs(p.y - q.y) < 2.0 * slack;
    });
  }

  // A cut that ends within the tolerance of an edge reaches it: otherwise a cut clipped to the
  // zones along a joint, its end a rounding short of the joint, would dangle and go whole. Ends
  // near one fixed earlier in this pass wait for the next.
  int snap_free_ends() {
    const size_t before = fixed_at_.size();
    for (auto v = arrangement_.vertices_begin(); v != arrangement_.vertices_end(); ++v) {
      if (v->degree() != 1) continue;
      const Halfedge into = v->incident_halfedges();
      if (!is_dangling(into)) continue;
      const Vec2 pv = to_vec(v->point());
      const double tolerance = tolerance_at(pv);
      if (near_a_fix(pv, 4.0 * tolerance)) continue;
      const Kernel::FT tolerance2(tolerance * tolerance);
      const Face face = into->face();
      std::vector<Halfedge> edges;
      if (!face->is_unbounded()) edges = ccb_halfedges(face->outer_ccb());
      for (auto ic = face->inner_ccbs_begin(); ic != face->inner_ccbs_end(); ++ic) {
        const std::vector<Halfedge> hole = ccb_halfedges(*ic);
        edges.insert(edges.end(), hole.begin(), hole.end());
      }
      Halfedge nearest;
      std::optional<Kernel::FT> best;
      for (const Halfedge& he : edges) {
        if (he->face() == he->twin()->face()) continue;  // dangling too: nothing to reach
        if (outside_box(pv, he, 2.0 * tolerance)) continue;  // a cheap double-precision filter first
        const Segment s(he->source()->point(), he->target()->point());
        const Kernel::FT d2 = CGAL::squared_distance(v->point(), s);
        if (d2 < tolerance2 && (!best || d2 < *best)) best = d2, nearest = he;
      }
      if (!best) continue;
      if (reach(v, nearest)) fixed_at_.push_back(pv);
    }
    return static_cast<int>(fixed_at_.size() - before);
  }

  // Whether the cut pieces of edge h are all optional ones that mind sharp corners (a joint or
  // an outline along the same line makes the edge theirs): then the smallest such piece, else -1.
  int sharp_minding_piece(const Halfedge& h) const {
    int found = -1;
    for (int id : h->curve().data()) {
      const Piece& piece = pieces_[static_cast<size_t>(id)];
      if (!piece.optional || !(piece.min_angle > 0.0)) return -1;
      if (found < 0 || id < found) found = id;
    }
    return found;
  }

  // An edge a wedge can come loose from: any but the glued outline of a crackseed{ auto } group.
  bool frees_a_wedge(const Halfedge& h) const {
    for (int id : h->curve().data()) {
      const EdgeOrigin& o = pieces_[static_cast<size_t>(id)].origin;
      if (!(o.kind == EdgeKind::region && o.source < 0 && o.glued)) return true;
    }
    return false;
  }

  // Where along piece `id` point q lies, as a length from its start, if it lies on it.
  std::optional<double> along(int id, const Point& q) const {
    const Piece& piece = pieces_[static_cast<size_t>(id)];
    double before = 0.0;
    for (size_t i = 0; i < piece.segment_count(); ++i) {
      const Segment s = piece.segment(i);
      if (s.has_on(q)) return before + std::sqrt(CGAL::to_double(CGAL::squared_distance(s.source(), q)));
      before += std::sqrt(CGAL::to_double(s.squared_length()));
    }
    return std::nullopt;
  }

  // Piece `id` less its stretch between the crossings on either side of vertex v (or its end
  // there): the sharp corner at v goes, and the rest of the piece still ends on other edges.
  // False if v is not on it (nothing done).
  bool cut_back(int id, Vertex v) {
    Piece& piece = pieces_[static_cast<size_t>(id)];
    const std::optional<double> at = along(id, v->point());
    if (!at) return false;
    // The crossings on the piece: vertices of degree 3 or more on one of its edges.
    std::optional<std::pair<double, Point>> before, after;
    for (auto e = arrangement_.edges_begin(); e != arrangement_.edges_end(); ++e) {
      const auto& ids = e->curve().data();
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) continue;
      for (Vertex w : {Vertex(e->source()), Vertex(e->target())}) {
        if (w == v || w->degree() < 3) continue;
        const std::optional<double> s = along(id, w->point());
        if (!s) continue;
        if (*s < *at && (!before || *s > before->first)) before = std::make_pair(*s, w->point());
        if (*s > *at && (!after || *s < after->first)) after = std::make_pair(*s, w->point());
      }
    }
    // Rebuild the two remaining parts from the polyline's own points.
    Piece first = piece, second = piece;
    first.points.clear();
    second.points.clear();
    double length = 0.0;
    for (size_t i = 0; i < piece.points.size(); ++i) {
      if (i > 0) length += std::sqrt(CGAL::to_double(CGAL::squared_distance(piece.points[i - 1], piece.points[i])));
      if (before && length < before->first) first.points.push_back(piece.points[i]);
      if (after && length > after->first) second.points.push_back(piece.points[i]);
    }
    if (before) first.points.push_back(before->second);
    if (after) second.points.insert(second.points.begin(), after->second);
    first.points.erase(std::unique(first.points.begin(), first.points.end()), first.points.end());
    second.points.erase(std::unique(second.points.begin(), second.points.end()), second.points.end());
    piece.left_out = true;
    if (first.points.size() >= 2) pieces_.push_back(std::move(first));
    if (second.points.size() >= 2) pieces_.push_back(std::move(second));
    return true;
  }

  // Corners of blocks sharper than an optional piece along them allows (a potential crack
  // crossing a joint at a shallow angle leaves a thin wedge that breaks loose and is driven
  // tip first into its neighbours): such a piece loses its stretch at that corner. Returns how
  // many were cut back.
  int cut_back_sharp_corners() {
    if (std::none_of(pieces_.begin(), pieces_.end(), [](const Piece& p) { return p.optional && p.min_angle > 0.0; }))
      return 0;  // nothing minds: every cut of the model, each time it is cut, goes without this pass
    std::vector<std::pair<int, Vertex>> to_cut;
    for (auto v = arrangement_.vertices_begin(); v != arrangement_.vertices_end(); ++v) {
      if (v->degree() < 2) continue;
      const Vec2 pv = to_vec(v->point());
      // Edges leaving v, by direction, counter-clockwise.
      std::vector<std::pair<double, Halfedge>> out;
      auto c = v->incident_halfedges();
      const auto start = c;
      do {
        const Halfedge leaving = c->twin();
        const Vec2 d = to_vec(leaving->target()->point()) - pv;
        out.emplace_back(std::atan2(d.y, d.x), leaving);
      } while (++c != start);
      std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (size_t i = 0; i < out.size(); ++i) {
        const auto& [angle0, h0] = out[i];
        const auto& [angle1, h1] = out[(i + 1) % out.size()];
        double corner = angle1 - angle0;
        if (corner <= 0.0) corner += 2.0 * std::numbers::pi;
        if (!inside_faces_.count(&*h0->face())) continue;  // the face between h0 and h1
        const int p0 = sharp_minding_piece(h0), p1 = sharp_minding_piece(h1);
        int id = -1;
        if (p0 >= 0 && frees_a_wedge(h1) && corner < pieces_[static_cast<size_t>(p0)].min_angle) id = p0;
        if (p1 >= 0 && frees_a_wedge(h0) && corner < pieces_[static_cast<size_t>(p1)].min_angle) id = std::max(id, p1);
        if (id < 0 || (p0 == p1)) continue;
        if (std::find(to_cut.begin(), to_cut.end(), std::make_pair(id, Vertex(v))) == to_cut.end())
          to_cut.emplace_back(id, v);
      }
    }
    // One cut a piece a round: the arrangement is stale for a piece once it is cut.
    std::vector<int> cut;
    for (const auto& [id, v] : to_cut)
      if (std::find(cut.begin(), cut.end(), id) == cut.end() && cut_back(id, v)) cut.push_back(id);
    return static_cast<int>(cut.size());
  }

  // Whether v is left over where a dangling cut crossed a piece: two edges of the same pieces meet
  // there, and v is none of their points (the two edges are one straight stretch).
  bool is_remnant(Vertex v) const {
    if (v->degree() != 2) return false;
    const Halfedge in = v->incident_halfedges(), other = in->next();
    const auto& ids = in->curve().data();
    if (!std::is_permutation(ids.begin(), ids.end(), other->curve().data().begin(), other->curve().data().end()))
      return false;
    return std::none_of(ids.begin(), ids.end(), [&](int id) {
      const auto& pts = pieces_[static_cast<size_t>(id)].points;
      return std::find(pts.begin(), pts.end(), v->point()) != pts.end();
    });
  }

  // A ring from its halfedges; a remnant vertex closer than the tolerance to the next or the
  // previous one is left out (the cut that made it is gone, and no fix can move what is not a point
  // of a cut: one can lie 2e-15 m from a crossing, an edge no zoning takes).
  Ring make_ring(const std::vector<Halfedge>& halfedges) const {
    Ring ring;
    const size_t n = halfedges.size();
    for (size_t i = 0; i < n; ++i) {
      const Halfedge& h = halfedges[i];
      const Vertex v = h->source();
      const auto near = [&](Vertex w) {
        return CGAL::compare(CGAL::squared_distance(v->point(), w->point()), tolerance2_at(v->point())) == CGAL::SMALLER;
      };
      if (n > 3 && is_remnant(v) && (near(h->target()) || near(halfedges[(i + n - 1) % n]->source()))) continue;
      ring.points.push_back(to_vec(v->point()));
      ring.edges.push_back(edge_origin(h, pieces_));
    }
    return ring;
  }

  // Which inside faces lie within region r: those not reached across its outline. (Where the
  // outline coincides with a base edge, the edge carries both pieces and still blocks.)
  std::vector<bool> faces_inside_region(int r) const {
    const auto outside = faces_reached_from_outside([&](const Halfedge& h) {
      for (int id : h->curve().data()) {
        const EdgeOrigin& o = pieces_[id].origin;
        if (o.kind == EdgeKind::region && o.source == r && !pieces_[id].base) return true;
      }
      return false;
    });
    std::vector<bool> inside(inside_.size());
    for (size_t i = 0; i < inside_.size(); ++i) inside[i] = !outside.count(&*inside_[i].face);
    return inside;
  }

  void extract(BlockSet& out) {
    std::vector<std::vector<bool>> in_region;
    for (size_t r = 0; r < regions_.size(); ++r)
      in_region.push_back(faces_inside_region(static_cast<int>(r)));

    for (size_t i = 0; i < inside_.size(); ++i) {
      const FaceRings& face = inside_[i];
      Block block;
      block.outer = make_ring(face.outer);
      for (const auto& hole : face.holes) block.holes.push_back(make_ring(hole));
      block.area = signed_area(block.outer.points);
      for (const Ring& hole : block.holes) block.area += signed_area(hole.points);
      block.centroid = block_centroid(block);
      block.base = base_index_;
      for (size_t r = 0; r < regions_.size(); ++r)
        if (in_region[r][i]) block.regions.push_back(static_cast<int>(r));
      out.blocks.push_back(std::move(block));
    }
    count_edges(out);
  }

  static Vec2 block_centroid(const Block& block) {
    // Area-weighted centroids of the outer ring and the (negative-area) holes.
    double area = signed_area(block.outer.points);
    Vec2 c = area * centroid(block.outer.points);
    for (const Ring& hole : block.holes) {
      const double a = signed_area(hole.points);
      c = c + a * centroid(hole.points);
      area += a;
    }
    return area != 0.0 ? (1.0 / area) * c : block.outer.points.front();
  }

  // Joint edges between two blocks.
  void count_edges(BlockSet& out) const {
    for (auto e = arrangement_.edges_begin(); e != arrangement_.edges_end(); ++e) {
      Halfedge h = e;
      if (inside_faces_.count(&*h->face()) && inside_faces_.count(&*h->twin()->face()) &&
          edge_origin(h, pieces_).kind == EdgeKind::joint)
        ++out.joint_edges;
    }
  }

  int base_index_;
  const std::vector<Polygon>& regions_;
  double tolerance_;
  const std::function<double(Vec2)>& local_;
  Vec2 last_fix_{};             // where the last small feature was, for the error message
  std::vector<int> last_bent_;  // the pieces its fix bent
  std::vector<std::pair<int, Vec2>> bent_in_round_;  // the pieces the last round's fixes bent, and where
  std::vector<Piece> pieces_;
  std::vector<Point> base_vertices_;
  Arrangement arrangement_;
  std::unordered_set<const void*> inside_faces_;
  std::vector<FaceRings> inside_;
  int dropped_ = 0;
  std::vector<Vec2> fixed_at_;  // this round's fixes: the arrangement is stale near them
  int left_out_ = 0;
  int cut_back_ = 0;
};

bool boxes_overlap(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

// Removes the optional and last-resort pieces that pass within `radius` of p; how many.
int leave_out_near(std::vector<Piece>& pieces, Vec2 p, double radius) {
  const auto near_p = [&](const Piece& piece) {
    if (!piece.optional && !piece.last_resort) return false;
    for (size_t i = 0; i < piece.segment_count(); ++i)
      if (piece.distance(i, p) <= radius) return true;
    return false;
  };
  const auto before = pieces.size();
  std::erase_if(pieces, near_p);
  return static_cast<int>(before - pieces.size());
}

}  // namespace

BlockSet cut_blocks(const CutInput& input) {
  // Clip once, exactly; pieces are then shared by every base they may cross.
  std::vector<std::vector<Point>> clip_polygons;
  for (const Polygon& polygon : input.clip_polygons) {
    std::vector<Point> points;
    for (Vec2 p : counter_clockwise(polygon)) points.push_back(to_point(p));
    clip_polygons.push_back(std::move(points));
  }
  std::vector<Piece> pieces;
  std::vector<Box> piece_boxes;
  for (const CutSegment& cut : input.cuts) {
    const Point a = to_point(cut.a), b = to_point(cut.b);
    if (a == b) continue;
    std::vector<std::pair<Point, Point>> parts;
    if (cut.clip >= 0)
      parts = clip_segment(a, b, clip_polygons.at(static_cast<size_t>(cut.clip)));
    else
      parts.emplace_back(a, b);
    for (auto& [p, q] : parts) {
      Piece piece;
      piece.points = {p, q};
      piece.origin = cut.origin;
      piece.optional = cut.optional;
      piece.last_resort = cut.last_resort;
      piece.min_angle = cut.min_angle * std::numbers::pi / 180.0;
      const Vec2 pv = to_vec(p), qv = to_vec(q);
      piece_boxes.push_back(bounding_box({pv, qv}));
      pieces.push_back(std::move(piece));
    }
  }

  // Region outlines stay closed polylines, so that bending keeps them closed.
  for (size_t r = 0; r < input.regions.size(); ++r) {
    Piece outline;
    for (Vec2 p : input.regions[r]) outline.points.push_back(to_point(p));
    outline.origin = {EdgeKind::region, -1, static_cast<int>(r), input.region_glued.at(r)};
    outline.closed = true;
    piece_boxes.push_back(bounding_box(input.regions[r]));
    pieces.push_back(std::move(outline));
  }

  BlockSet out;
  for (size_t i = 0; i < input.bases.size(); ++i) {
    const Polygon base = counter_clockwise(input.bases[i]);
    Box box = bounding_box(base);
    const double margin = 2.0 * std::max(input.tolerance, input.largest_tolerance);
    box = {box.x0 - margin, box.x1 + margin, box.y0 - margin, box.y1 + margin};
    std::vector<Piece> near;
    for (size_t k = 0; k < pieces.size(); ++k)
      if (boxes_overlap(box, piece_boxes[k])) near.push_back(pieces[k]);
    // Stuck with nothing left to give way, the required cuts there may be bent by optional ones
    // that were left out since: start again from the cuts as given, less the optional and
    // last-resort ones passing within a radius of the spot that grows with each try.
    // Where the cuts cannot be bent clear of a zone-size tolerance (required cuts crossing at a
    // shallow angle), the model's own tolerance holds within a spot around it, and the slivers
    // there are kept and counted.
    std::vector<std::pair<Vec2, double>> kept_spots;
    const std::function<double(Vec2)> local = !input.local_tolerance ? input.local_tolerance : [&](Vec2 p) {
      for (const auto& [spot, r] : kept_spots)
        if (norm(p - spot) <= r) return 0.0;
      return input.local_tolerance(p);
    };
    double radius = 0.0;
    for (int restart = 0;; ++restart) {
      BaseCutter cutter(base, static_cast<int>(i), near, input.regions, input.tolerance, local);
      if (cutter.run(out)) break;
      const Vec2 stuck = cutter.stuck_at();
      const double tolerance = cutter.tolerance_at(stuck);
      if (restart == 0) radius = kFirstRestartRadius * tolerance;
      const int left_out = restart < kMaxRestarts ? leave_out_near(near, stuck, radius) : 0;
      if (left_out > 0) {
        out.cuts_left_out += left_out;
        radius *= 2.0;
        continue;
      }
      if (!(tolerance > input.tolerance) || static_cast<int>(kept_spots.size()) >= kMaxKeptSpots) cutter.fail_stuck();
      kept_spots.emplace_back(stuck, kFirstRestartRadius * tolerance);
      ++out.slivers_kept;
    }
  }
  return out;
}

}  // namespace edem
