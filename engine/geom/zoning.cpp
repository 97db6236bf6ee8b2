// Zoning with CGAL's constrained Delaunay refinement (Ruppert's algorithm, Shewchuk's clusters).
//
// Blocks joined by glued edges must share their gridpoints along those edges, and the two faces
// of a joint are best zoned alike (see touching_groups()), so blocks that touch along an edge are
// meshed together: union-find groups the zoned blocks over their shared edges, and each group
// goes into one CDT with all its rings as constraints. A flood fill over unconstrained edges,
// seeded left of every ring edge, labels each face with its block; the labelled faces are the
// domain. CGAL's mesher levels (assembled here rather than through Delaunay_mesher_2, see
// DomainGabriel and refine()) insert points one at a time until every face meets the size
// field and the shape bound, splitting a shared edge for both blocks at once. A zone budget
// stops runaway meshes. The refined CDT is labelled again and read out block by block:
// boundary gridpoints in loop order first, then interior gridpoints and zones in Z-order (only
// glued edges merge gridpoints, later, in the solver). A block touching no other is a group of
// one, meshed exactly as it would be alone; a group of several also gets its neighbours' rings
// as bare constraints, a frame of four points around it and its shared sharp corners lopped
// (see insert_neighbours(), insert_frame() and lop_sharp_corners()).
#include "geom/zoning.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>  // the mesher levels, assembled below
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace edem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
struct VertexInfo {
  int gp = -1;          // gridpoint index in the block being read out, -1 until numbered
  bool sharp = false;   // a block corner sharper than the shape bound (kShapeBoundAngle)
  bool shared = false;  // several blocks of the group meet here (see lop_sharp_corners)
  int block = -1;       // the first block (in the group) with a corner here
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
struct FaceInfo {
  int block = -1;       // the face's block in the group, -1 outside every zoned block
  bool frozen = false;  // in a lopped corner: a zone as it is, never refined (lop_sharp_corners)
};
using FaceInfoBase = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<
    Kernel, CGAL::Constrained_Delaunay_triangulation_face_base_2<
                Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfoBase>>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Rings of a valid block never cross; if they do we want an exception, not a constructed point.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using VertexHandle = Cdt::Vertex_handle;
using FaceHandle = Cdt::Face_handle;

// CGAL's default shape bound: squared sine of the smallest angle, sin^2(20.7 deg) = 0.125.
constexpr double kShapeBound = 0.125;
const double kShapeBoundAngle = std::asin(std::sqrt(kShapeBound)) * 180.0 / std::numbers::pi;

Vec2 to_vec(const Point& p) {
  return {p.x(), p.y()};
}

// A block's number in messages: from 1, as everywhere users see blocks.
int shown(int block) { return block + 1; }

// ---------------------------------------------------------------------------------------------
// Size field, evaluated fast: polygons flattened with their bounding boxes, and a cut-off
// distance `reach` beyond which the size is `far` whatever the geometry.

class SizeEvaluator {
 public:
  explicit SizeEvaluator(const SizeField& field)
      : edge_(field.edge), far_(field.far), growth_(field.growth) {
    constant_ = field.near.empty() || growth_ <= 0.0 || far_ <= edge_;
    if (constant_) {
      constant_size_ = field.near.empty() ? edge_ : std::min(edge_, far_);
      return;
    }
    reach_ = (far_ - edge_) / growth_;
    for (const Polygon& polygon : field.near) {
      if (polygon.empty()) continue;
      const int first = static_cast<int>(points_.size());
      points_.insert(points_.end(), polygon.begin(), polygon.end());
      polygons_.push_back({bounding_box(polygon), first, static_cast<int>(points_.size())});
    }
    if (polygons_.empty()) {
      constant_ = true;
      constant_size_ = edge_;
    }
  }

  // Target edge length at p [m].
  double at(Vec2 p) const {
    if (constant_) return constant_size_;
    const double d = near_distance(p);
    if (d >= reach_) return far_;
    return std::min(far_, edge_ + growth_ * d);
  }

 private:
  struct NearPolygon {
    Box box;
    int first, last;  // its vertices in points_
  };

  // Distance to the nearest polygon (0 inside), or reach_ when none is nearer [m].
  double near_distance(Vec2 p) const {
    double best = reach_;
    for (const NearPolygon& polygon : polygons_) {
      const double dx = std::max({polygon.box.x0 - p.x, 0.0, p.x - polygon.box.x1});
      const double dy = std::max({polygon.box.y0 - p.y, 0.0, p.y - polygon.box.y1});
      if (dx * dx + dy * dy >= best * best) continue;  // its box is already too far
      const double d = polygon_distance(polygon, p);
      if (d == 0.0) return 0.0;
      best = std::min(best, d);
    }
    return best;
  }

  // Distance to one polygon, 0 inside; one pass for the nearest edge and the crossing parity.
  double polygon_distance(const NearPolygon& polygon, Vec2 p) const {
    double best2 = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (int i = polygon.first, j = polygon.last - 1; i < polygon.last; j = i++) {
      const Vec2 a = points_[j], b = points_[i];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
        inside = !inside;
      const Vec2 ab = b - a, ap = p - a;
      const double length2 = dot(ab, ab);
      const double t = length2 > 0.0 ? std::clamp(dot(ap, ab) / length2, 0.0, 1.0) : 0.0;
      const Vec2 offset = ap - t * ab;
      best2 = std::min(best2, dot(offset, offset));
    }
    return inside ? 0.0 : std::sqrt(best2);
  }

  double edge_, far_, growth_;
  bool constant_ = true;
  double constant_size_ = 0.0;
  double reach_ = 0.0;
  std::vector<Vec2> points_;
  std::vector<NearPolygon> polygons_;
};

// The size field of a group of blocks zoned together: the pointwise minimum of their distinct
// size fields, so that every block's zones meet its own field (the shared edges must be split
// alike on both sides, so one field has to hold for the whole CDT).
class GroupSize {
 public:
  explicit GroupSize(const std::vector<const SizeField*>& fields) {
    std::vector<const SizeField*> distinct;
    for (const SizeField* field : fields)
      if (std::find(distinct.begin(), distinct.end(), field) == distinct.end())
        distinct.push_back(field);
    for (const SizeField* field : distinct) {
      evaluators_.emplace_back(*field);
      growth_ = std::max(growth_, field->growth);
    }
  }

  // Target edge length at p [m].
  double at(Vec2 p) const {
    double size = evaluators_.front().at(p);
    for (size_t i = 1; i < evaluators_.size(); ++i) size = std::min(size, evaluators_[i].at(p));
    return size;
  }

  // The fastest the size can change with position [-]: at() never changes by more than
  // growth() times the distance moved.
  double growth() const { return growth_; }

 private:
  std::vector<SizeEvaluator> evaluators_;
  double growth_ = 0.0;
};

// Whether the angle of `face` at its vertex i is a sharp block corner, spared by the shape
// rule because no mesh can do better there: the rule of a block meshed alone. Sharp corners at
// vertices several blocks share are lopped instead (see lop_sharp_corners()).
bool at_sharp_corner(const FaceHandle& face, int i) {
  const VertexInfo& info = face->vertex(i)->info();
  return info.sharp && !info.shared;
}

// ---------------------------------------------------------------------------------------------
// Refinement criteria, modelled on CGAL::Delaunay_mesh_size_criteria_2 but with a size field:
// a face is imperatively bad when its longest edge exceeds the size at its centroid, and bad
// when its smallest angle is below asin(sqrt(B)). Imperatively bad faces are split even next to
// small input angles, where CGAL's cluster rule spares merely bad ones (that is what keeps
// refinement from running forever at sharp corners).
//
// With `insist` set (the second pass, see refine()), a badly shaped face is imperatively bad
// too, unless its smallest angle sits at a sharp block corner (at_sharp_corner).

class SizeShapeCriteria : public CGAL::Delaunay_mesh_criteria_2<Cdt> {
 public:
  using Base = CGAL::Delaunay_mesh_criteria_2<Cdt>;
  using Face_handle = Cdt::Face_handle;

  SizeShapeCriteria(const GroupSize& size, double shape_bound = kShapeBound)
      : Base(shape_bound), size_(&size) {}

  void insist(bool on) { insist_ = on; }

  // Oversized faces first, largest first; then insisted ones, worst first; then the rest,
  // worst first (CGAL's order, plus the middle group).
  struct Quality {
    double sine = 1.0;    // squared sine of the smallest angle
    double size = 0.0;    // (longest edge / size field)^2
    bool insist = false;  // badly shaped and to be split even in a cluster
    bool operator<(const Quality& other) const {
      if (size > 1.0) return other.size > 1.0 ? size > other.size : true;
      if (other.size > 1.0) return false;
      if (insist != other.insist) return insist;
      return sine < other.sine;
    }
  };

  class Is_bad {
   public:
    Is_bad(double shape_bound, const GroupSize* size, bool insist)
        : bound_(shape_bound), size_(size), insist_(insist) {}

    CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
      if (q.size > 1.0 || q.insist) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      if (q.sine < bound_) return CGAL::Mesh_2::BAD;
      return CGAL::Mesh_2::NOT_BAD;
    }

    CGAL::Mesh_2::Face_badness operator()(const Face_handle& face, Quality& q) const {
      const Vec2 p[3] = {to_vec(face->vertex(0)->point()), to_vec(face->vertex(1)->point()),
                         to_vec(face->vertex(2)->point())};
      // l[i]: squared length of the edge opposite vertex i
      const double l[3] = {dot(p[1] - p[2], p[1] - p[2]), dot(p[2] - p[0], p[2] - p[0]),
                           dot(p[0] - p[1], p[0] - p[1])};
      const int shortest = l[0] <= l[1] ? (l[0] <= l[2] ? 0 : 2) : (l[1] <= l[2] ? 1 : 2);
      const int longest = l[0] > l[1] ? (l[0] > l[2] ? 0 : 2) : (l[1] > l[2] ? 1 : 2);
      const double size =
          size_->at({(p[0].x + p[1].x + p[2].x) / 3.0, (p[0].y + p[1].y + p[2].y) / 3.0});
      q = Quality{};
      q.size = l[longest] / (size * size);
      if (q.size > 1.0) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      // The smallest angle, opposite the shortest edge, lies between the two others:
      // sin = 2A / (product of their lengths).
      const double twice_area = cross(p[1] - p[0], p[2] - p[0]);
      double others = 1.0;
      for (int i = 0; i < 3; ++i)
        if (i != shortest) others *= l[i];
      q.sine = twice_area * twice_area / others;
      if (q.sine >= bound_) return CGAL::Mesh_2::NOT_BAD;
      q.insist = insist_ && !at_sharp_corner(face, shortest);
      return q.insist ? CGAL::Mesh_2::IMPERATIVELY_BAD : CGAL::Mesh_2::BAD;
    }

   private:
    double bound_;
    const GroupSize* size_;
    bool insist_;
  };

  Is_bad is_bad_object() const { return Is_bad(bound(), size_, insist_); }

 private:
  const GroupSize* size_;
  bool insist_ = false;
};

// ---------------------------------------------------------------------------------------------
// The mesher: CGAL::Delaunay_mesher_2's levels, with one change. CGAL calls a constrained edge
// encroached when a vertex on *either* side lies in its diametral circle, also a vertex outside
// the block. Across a narrow notch of the block (two edges at a small angle seen from outside)
// that makes both sides split each other, and CGAL's cluster rule then gives up and leaves
// skinny zones at a corner that is not sharp at all. Here only vertices of faces inside the
// block count, as in Shewchuk's Triangle, which deletes the outside before refining.

using CgalGabriel = CGAL::Mesh_2::Is_locally_conforming_Gabriel<Cdt>;

struct DomainGabriel : CgalGabriel {
  using CgalGabriel::operator();

  // Edge i of face: conforming when no vertex of an adjacent face inside the domain
  // encroaches it.
  bool operator()(const Cdt& cdt, const FaceHandle& face, int i) const {
    const VertexHandle a = face->vertex(Cdt::cw(i)), b = face->vertex(Cdt::ccw(i));
    const FaceHandle other = face->neighbor(i);
    const VertexHandle here = face->vertex(i), there = cdt.tds().mirror_vertex(face, i);
    const bool ok_here = !face->is_in_domain() || cdt.is_infinite(here) ||
                         CgalGabriel::operator()(cdt, a, b, here->point());
    const bool ok_there = !other->is_in_domain() || cdt.is_infinite(there) ||
                          CgalGabriel::operator()(cdt, a, b, there->point());
    return ok_here && ok_there;
  }

  bool operator()(const Cdt& cdt, const VertexHandle& a, const VertexHandle& b) const {
    FaceHandle face;
    int i = 0;
    cdt.is_edge(a, b, face, i);
    return (*this)(cdt, face, i);
  }
};

// CGAL restores the domain marks of the faces around a new boundary vertex only after it has
// checked the edges around it; DomainGabriel needs them before, so restore them first (the
// same walk as CGAL::Mesh_2::Refine_edges_visitor::after_insertion).
class DomainEdgesBase : public CGAL::Mesh_2::Refine_edges_base_with_clusters<Cdt, DomainGabriel> {
  using Super = CGAL::Mesh_2::Refine_edges_base_with_clusters<Cdt, DomainGabriel>;

 public:
  using Super::Super;

  void after_insertion_impl(const VertexHandle& v) {
    Cdt& cdt = this->triangulation_ref_impl();
    FaceHandle face;
    int i = 0;
    cdt.is_edge(this->visitor_va, v, face, i);
    auto around = cdt.incident_faces(v, face), first = around;
    do {
      if (!cdt.is_infinite(around)) around->set_in_domain(this->visitor_mark_at_right);
      ++around;
    } while (around->vertex(Cdt::ccw(around->index(v))) != this->visitor_vb);
    do {
      if (!cdt.is_infinite(around)) around->set_in_domain(this->visitor_mark_at_left);
      ++around;
    } while (around != first);
    Super::after_insertion_impl(v);
  }
};

using EdgesLevel = CGAL::Mesh_2::Refine_edges_with_clusters<Cdt, DomainGabriel, DomainEdgesBase>;
using FacesLevel = CGAL::Mesh_2::Refine_faces<Cdt, SizeShapeCriteria, EdgesLevel>;
using LevelsVisitor = CGAL::Mesh_2::Refine_edges_visitor_from_faces<FacesLevel>;

// ---------------------------------------------------------------------------------------------
// Checks on the input, block by block.

void check_size_field(const SizeField& field, int block) {
  if (!(std::isfinite(field.edge) && field.edge > 0.0))
    fail("block {}: zone edge must be a positive length, got {}", shown(block), field.edge);
  if (!(std::isfinite(field.far) && field.far >= field.edge))
    fail("block {}: zone far size {} must be at least the edge {}", shown(block), field.far,
         field.edge);
  if (!(std::isfinite(field.growth) && field.growth >= 0.0))
    fail("block {}: zone growth must be zero or positive, got {}", shown(block), field.growth);
}

void check_ring(const Ring& ring, int block, const char* what) {
  const size_t n = ring.points.size();
  if (n < 3) fail("block {}: its {} has {} vertices, at least 3 are needed", shown(block), what, n);
  if (ring.edges.size() != n)
    fail("block {}: its {} has {} vertices but {} edge origins", shown(block), what, n,
         ring.edges.size());
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = ring.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      fail("block {}: its {} has a non-finite vertex", shown(block), what);
    if (p == ring.points[(i + 1) % n])
      fail("block {}: its {} repeats vertex ({}, {})", shown(block), what, p.x, p.y);
  }
}

double ring_area(const Ring& ring) { return signed_area(ring.points); }

// Interior angle of a ring at vertex i, on the domain side (the left of the ring) [deg].
double interior_angle(const Ring& ring, size_t i) {
  const size_t n = ring.points.size();
  const Vec2 q = ring.points[i];
  const Vec2 out = ring.points[(i + 1) % n] - q, back = ring.points[(i + n - 1) % n] - q;
  const double angle = std::atan2(cross(out, back), dot(out, back)) * 180.0 / std::numbers::pi;
  return angle < 0.0 ? angle + 360.0 : angle;
}

// Everything zoning asks of one zoned block on its own.
void check_block(const Block& block, const SizeField& field, int index) {
  check_size_field(field, index);
  check_ring(block.outer, index, "outer boundary");
  for (const Ring& hole : block.holes) check_ring(hole, index, "hole");
  // The labelling and the boundary walk rely on the block lying left of every ring.
  if (!(ring_area(block.outer) > 0.0))
    fail("block {}: its outer boundary must be counter-clockwise", shown(index));
  for (const Ring& hole : block.holes)
    if (!(ring_area(hole) < 0.0)) fail("block {}: its holes must be clockwise", shown(index));
}

// ---------------------------------------------------------------------------------------------
// Groups: the zoned blocks joined through glued edges, each meshed in one CDT.

using Group = std::vector<int>;  // block indices, ascending

class DisjointSets {
 public:
  explicit DisjointSets(size_t count) : parent_(count) {
    for (size_t i = 0; i < count; ++i) parent_[i] = static_cast<int>(i);
  }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

// A ring edge, directed with its block on the left.
struct RingEdge {
  Vec2 a, b;
  int block = -1;
  bool glued = false;
};

bool by_end_points(const RingEdge& e, const RingEdge& f) {
  return std::tie(e.a.x, e.a.y, e.b.x, e.b.y) < std::tie(f.a.x, f.a.y, f.b.x, f.b.y);
}

bool is_finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Every ring edge of every block with finite end points, sorted by end points. Blocks without
// a size field are in too, so that a glued edge next to one still finds its twin.
std::vector<RingEdge> ring_edges(const BlockSet& blocks) {
  std::vector<RingEdge> edges;
  for (size_t b = 0; b < blocks.blocks.size(); ++b) {
    auto add = [&](const Ring& ring) {
      const size_t n = ring.points.size();
      if (ring.edges.size() != n) return;
      for (size_t i = 0; i < n; ++i) {
        const Vec2 a = ring.points[i], c = ring.points[(i + 1) % n];
        if (is_finite(a) && is_finite(c))
          edges.push_back({a, c, static_cast<int>(b), ring.edges[i].glued});
      }
    };
    add(blocks.blocks[b].outer);
    for (const Ring& hole : blocks.blocks[b].holes) add(hole);
  }
  std::sort(edges.begin(), edges.end(), by_end_points);
  return edges;
}

// Whether two ring edges run along each other in opposite directions over a stretch of
// positive length: one boundary seen from its two sides but split at a vertex only one side
// has. Exact for the collinearity.
bool overlap_opposite(const RingEdge& e, const RingEdge& f) {
  if (!on_line_exactly(f.a, e.a, e.b) || !on_line_exactly(f.b, e.a, e.b)) return false;
  if (!(dot(e.b - e.a, f.b - f.a) < 0.0)) return false;
  // Collinear points keep their order along the edge's dominant axis.
  const bool along_x = std::abs(e.b.x - e.a.x) >= std::abs(e.b.y - e.a.y);
  auto at = [along_x](Vec2 p) { return along_x ? p.x : p.y; };
  const double low = std::max(std::min(at(e.a), at(e.b)), std::min(at(f.a), at(f.b)));
  const double high = std::min(std::max(at(e.a), at(e.b)), std::max(at(f.a), at(f.b)));
  return low < high;
}

// The zoned blocks in groups joined through the edges they share, glued or not: each group
// ascending, the groups in the order of their first block. Two zoned blocks are joined when an
// edge of one runs along an edge of the other the other way. Meshed together, the two faces of a
// joint get gridpoints at the same places (still two gridpoints, one per block), so that a joint
// under uniform stress closes uniformly: node-to-edge contacts between faces zoned apart carry
// it with a scatter of several percent (the contact patch test fails on non-matching meshes).
// Cut blocks come from one exact arrangement, so a shared edge has the same end points on both
// sides and the sorted lookup finds its twin; the edges without a twin (the model's outline,
// blocks built by hand with a vertex only one side has) are compared with each other.
std::vector<Group> touching_groups(const BlockSet& blocks,
                                   const std::vector<const SizeField*>& size_of_block) {
  const size_t count = blocks.blocks.size();
  auto zoned = [&](int b) { return size_of_block[b] != nullptr; };
  const std::vector<RingEdge> edges = ring_edges(blocks);
  DisjointSets sets(count);
  std::vector<const RingEdge*> twinless;
  for (const RingEdge& edge : edges) {
    if (!zoned(edge.block)) continue;
    const RingEdge twin{edge.b, edge.a};
    const auto [first, last] = std::equal_range(edges.begin(), edges.end(), twin, by_end_points);
    for (auto other = first; other != last; ++other)
      if (zoned(other->block)) sets.join(edge.block, other->block);
    if (first == last) twinless.push_back(&edge);
  }
  for (size_t i = 0; i < twinless.size(); ++i)
    for (size_t j = i + 1; j < twinless.size(); ++j)
      if (twinless[i]->block != twinless[j]->block && overlap_opposite(*twinless[i], *twinless[j]))
        sets.join(twinless[i]->block, twinless[j]->block);
  std::vector<Group> groups;
  std::vector<int> group_of_root(count, -1);
  for (size_t b = 0; b < count; ++b) {
    if (!zoned(static_cast<int>(b))) continue;
    int& group = group_of_root[sets.find(static_cast<int>(b))];
    if (group < 0) {
      group = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group].push_back(static_cast<int>(b));
  }
  return groups;
}

// ---------------------------------------------------------------------------------------------
// Building a group's CDT and labelling its faces with their blocks.

using RingHandles = std::vector<std::vector<VertexHandle>>;  // per ring: outer, then holes

const Ring& ring_of(const Block& block, size_t r) {
  return r == 0 ? block.outer : block.holes[r - 1];
}

// Inserts the ring of block k (in the group) with its vertices and edges; returns the vertex
// handle of each ring point. A point or edge another block inserted already is reused (CGAL
// returns the existing vertex), and a vertex lying on another ring's edge splits it.
std::vector<VertexHandle> insert_ring(Cdt& cdt, const Ring& ring, int k) {
  std::vector<VertexHandle> handles;
  handles.reserve(ring.points.size());
  for (size_t i = 0; i < ring.points.size(); ++i) {
    const Vec2 p = ring.points[i];
    handles.push_back(cdt.insert(Point(p.x, p.y)));
    VertexInfo& info = handles.back()->info();
    if (interior_angle(ring, i) < kShapeBoundAngle) info.sharp = true;
    if (info.block < 0) info.block = k;
    if (info.block != k) info.shared = true;
  }
  for (size_t i = 0; i < handles.size(); ++i)
    cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
  return handles;
}

// A sharp vertex of one block that also lies on another block's ring edge (only one side of a
// shared edge has it) is shared too: more constrained edges meet there than its corner's two.
void mark_vertices_on_other_rings(Cdt& cdt) {
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (!v->info().sharp || v->info().shared) continue;
    int constrained = 0;
    auto edge = cdt.incident_edges(v);
    const auto first = edge;
    do {
      if (cdt.is_constrained(*edge)) ++constrained;
    } while (++edge != first);
    if (constrained != 2) v->info().shared = true;
  }
}

// The constrained edge leaving v closest to direction `along` among those accept(face, edge)
// takes, as (face on its left, edge index); a null face when there is none. Points the mesher
// adds on ring edges are rounded, so the direction matches only nearly. Backward edges are
// taken only when no forward one is.
template <typename Accept>
Cdt::Edge edge_leaving(const Cdt& cdt, VertexHandle v, Vec2 along, Accept accept) {
  Cdt::Edge best(FaceHandle(), -1);
  double best_deviation = std::numeric_limits<double>::infinity();
  auto face = cdt.incident_faces(v);
  const auto first = face;
  do {
    const int i = face->index(v);
    const int e = Cdt::cw(i);  // edge v -> vertex(ccw(i)), face on its left
    if (!cdt.is_infinite(face) && face->is_constrained(e) && accept(face, e)) {
      const Vec2 step = to_vec(face->vertex(Cdt::ccw(i))->point()) - to_vec(v->point());
      const double deviation = dot(step, along) > 0.0 ? std::abs(cross(along, step)) / norm(step)
                                                      : std::numeric_limits<double>::max();
      if (deviation < best_deviation) {
        best_deviation = deviation;
        best = Cdt::Edge(face, e);
      }
    }
  } while (++face != first);
  return best;
}

// Blocks by ring vertex, exact coordinates: the blocks around each vertex of the arrangement.
using BlocksAtVertex = std::map<std::pair<double, double>, std::vector<int>>;

BlocksAtVertex blocks_at_vertices(const BlockSet& blocks) {
  BlocksAtVertex at;
  for (size_t b = 0; b < blocks.blocks.size(); ++b)
    for (size_t r = 0; r <= blocks.blocks[b].holes.size(); ++r)
      for (Vec2 p : ring_of(blocks.blocks[b], r).points)
        if (is_finite(p)) {
          std::vector<int>& list = at[{p.x, p.y}];
          if (list.empty() || list.back() != static_cast<int>(b))
            list.push_back(static_cast<int>(b));
        }
  return at;
}

// Whether a ring can go into a CDT: three points or more, finite, none repeated next to itself.
bool well_formed(const Ring& ring) {
  const size_t n = ring.points.size();
  if (n < 3) return false;
  for (size_t i = 0; i < n; ++i)
    if (!is_finite(ring.points[i]) || ring.points[i] == ring.points[(i + 1) % n]) return false;
  return true;
}

// The blocks outside the group around it inserted as bare constraints, outside the domain: the
// triangulation outside the group's boundary then follows the blocks there instead of forming
// slivers across a straight cut the group has on one side only, which a point rounded onto the
// group's boundary could turn over.
void insert_neighbours(Cdt& cdt, const BlockSet& blocks, const Group& group,
                       const BlocksAtVertex& blocks_at) {
  std::vector<int> neighbours;
  for (int b : group)
    for (size_t r = 0; r <= blocks.blocks[b].holes.size(); ++r)
      for (Vec2 p : ring_of(blocks.blocks[b], r).points)
        for (int other : blocks_at.at({p.x, p.y}))
          if (!std::binary_search(group.begin(), group.end(), other)) neighbours.push_back(other);
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  for (int b : neighbours)
    for (size_t r = 0; r <= blocks.blocks[b].holes.size(); ++r) {
      const Ring& ring = ring_of(blocks.blocks[b], r);
      if (!well_formed(ring)) continue;
      std::vector<VertexHandle> handles;
      for (Vec2 p : ring.points) handles.push_back(cdt.insert(Point(p.x, p.y)));
      try {
        for (size_t i = 0; i < handles.size(); ++i)
          cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
      } catch (const Cdt::Intersection_of_constraints_exception&) {
        fail("block {}: its boundary crosses a block glued to block {} and cannot be zoned",
             shown(b), shown(group.front()));
      }
    }
}

// Four points around everything in the CDT, so that the triangulation outside the group, too,
// has something to follow. Where a cut ends on a straight outer edge of the model, its end point
// is rounded a hair off that edge; rounded inside, with nothing beyond the edge, it lets Delaunay
// join the edge's two ends outside the blocks: a sliver as thin as the rounding. A lid's end
// (lop_point()) rounded onto either half of the edge can then land beyond the sliver's long side
// and turn it over. A frame point lies beyond every edge of the convex hull, inside any such
// sliver's vast circumcircle, so the outside is triangulated towards the frame instead.
void insert_frame(Cdt& cdt) {
  Polygon points;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    points.push_back(to_vec(v->point()));
  const Box box = bounding_box(points);
  const double margin = std::max(box.x1 - box.x0, box.y1 - box.y0);
  for (const double x : {box.x0 - margin, box.x1 + margin})
    for (const double y : {box.y0 - margin, box.y1 + margin}) cdt.insert(Point(x, y));
}

// ---------------------------------------------------------------------------------------------
// Lopping sharp corners where blocks meet.
//
// A sharp corner of a block meshed alone is one zone at its apex. Where the corner meets other
// blocks of its group, their zones at the apex split the corner's edges, the corner then needs
// points ever nearer its apex and gives them back to its neighbours, and refinement descends
// towards the apex without end (down to rounding, where CGAL breaks). So such a corner is cut
// off first: a point on each of its edges at a small distance from the apex, and a constrained
// lid between them. The triangle cut off is a zone of its block kept out of the refinement's
// domain: nothing refines it and its vertices encroach on no edge (a neighbour may still split
// its edges, which divides it into a few zones). Beyond the lid the block has no sharp corner.

// A sharp corner to lop: its apex, the directions of its first and last edge, its block.
struct Lop {
  VertexHandle apex;
  Vec2 out, back;
  int k = -1;         // its block in the group
  VertexHandle a, b;  // the lid's ends on the first and the last edge, once lopped
};

// The sharp corners at vertices that several blocks of the group share.
std::vector<Lop> corners_to_lop(const BlockSet& blocks, const Group& group,
                                const std::vector<RingHandles>& rings) {
  std::vector<Lop> lops;
  for (size_t k = 0; k < group.size(); ++k)
    for (size_t r = 0; r < rings[k].size(); ++r) {
      const Ring& ring = ring_of(blocks.blocks[group[k]], r);
      const size_t n = ring.points.size();
      for (size_t i = 0; i < n; ++i) {
        if (!rings[k][r][i]->info().shared || !(interior_angle(ring, i) < kShapeBoundAngle))
          continue;
        lops.push_back({rings[k][r][i], ring.points[(i + 1) % n] - ring.points[i],
                        ring.points[(i + n - 1) % n] - ring.points[i], static_cast<int>(k),
                        VertexHandle(), VertexHandle()});
      }
    }
  return lops;
}

const auto any_edge = [](FaceHandle, int) { return true; };

// The constrained edge at v closest to direction `along`, its block on either side, as (a
// finite face, edge index), and its other end.
std::pair<Cdt::Edge, VertexHandle> constrained_edge_towards(const Cdt& cdt, VertexHandle v,
                                                            Vec2 along) {
  std::pair<Cdt::Edge, VertexHandle> best;
  double best_deviation = std::numeric_limits<double>::infinity();
  auto edge = cdt.incident_edges(v);
  const auto first = edge;
  do {
    if (cdt.is_infinite(*edge) || !cdt.is_constrained(*edge)) continue;
    const Cdt::Edge e = cdt.is_infinite(edge->first) ? cdt.mirror_edge(*edge) : *edge;
    const VertexHandle a = e.first->vertex(Cdt::cw(e.second));
    const VertexHandle w = a == v ? e.first->vertex(Cdt::ccw(e.second)) : a;
    const Vec2 step = to_vec(w->point()) - to_vec(v->point());
    if (!(dot(step, along) > 0.0)) continue;
    const double deviation = std::abs(cross(along, step)) / norm(step);
    if (deviation < best_deviation) {
      best_deviation = deviation;
      best = {e, w};
    }
  } while (++edge != first);
  return best;
}

// The point at distance `radius` from v on its constrained edge in direction `along`, inserted
// into that edge; the one already there when the lop on the other side of the edge made it.
VertexHandle lop_point(Cdt& cdt, VertexHandle v, Vec2 along, double radius) {
  const auto [edge, far] = constrained_edge_towards(cdt, v, along);
  const Vec2 a = to_vec(v->point()), b = to_vec(far->point());
  const double length = norm(b - a);
  if (length < 1.5 * radius) return far;  // the ring's own vertices are 4 radii away or more
  const Vec2 p = a + (radius / length) * (b - a);
  return cdt.insert(Point(p.x, p.y), Cdt::EDGE, edge.first, edge.second);
}

// Distance from the apex to the nearest edge across it in the faces of its corner [m]: a
// ball that wide holds no other vertex or edge of the corner.
double corner_clearance(const Cdt& cdt, const Lop& lop) {
  const Vec2 c = to_vec(lop.apex->point());
  double nearest = std::numeric_limits<double>::infinity();
  FaceHandle face = edge_leaving(cdt, lop.apex, lop.out, any_edge).first;
  for (;;) {  // counter-clockwise from the corner's first edge to its last
    const int i = face->index(lop.apex);
    nearest = std::min(nearest, segment_distance(c, to_vec(face->vertex(Cdt::ccw(i))->point()),
                                                 to_vec(face->vertex(Cdt::cw(i))->point())));
    if (face->is_constrained(Cdt::ccw(i))) return nearest;
    face = face->neighbor(Cdt::ccw(i));
  }
}

// Distance from each apex to its lids' ends [m], the same for all corners at one apex: a
// quarter of their clearance, so that a lid crosses nothing and the lids at the two ends of an
// edge stay apart; and small enough that the zone cut off (edges that long at most) meets the
// size field anywhere in it, which half the size at the apex does after the field's change.
std::vector<double> lop_radii(const Cdt& cdt, const std::vector<Lop>& lops,
                              const GroupSize& size) {
  std::vector<double> radius;
  for (const Lop& lop : lops) {
    const Vec2 c = to_vec(lop.apex->point());
    radius.push_back(
        std::min(0.25 * corner_clearance(cdt, lop), size.at(c) / (2.0 + size.growth())));
  }
  for (size_t l = 0; l < lops.size(); ++l)
    for (size_t m = 0; m < lops.size(); ++m)
      if (lops[m].apex == lops[l].apex) radius[l] = std::min(radius[l], radius[m]);
  return radius;
}

// Whether the faces around v are all counter-clockwise. A lop point is rounded off its edge by
// a unit in the last place; next to a sliver that could turn a face over, which would leave
// CGAL working on a broken triangulation (insert_neighbours() and insert_frame() keep such
// slivers off the group's outline).
bool star_turns_left(const Cdt& cdt, VertexHandle v) {
  auto face = cdt.incident_faces(v);
  const auto first = face;
  do {
    if (!cdt.is_infinite(face) &&
        CGAL::orientation(face->vertex(0)->point(), face->vertex(1)->point(),
                          face->vertex(2)->point()) != CGAL::LEFT_TURN)
      return false;
  } while (++face != first);
  return true;
}

// Lops every sharp corner at a vertex several blocks of the group share; returns the lops.
std::vector<Lop> lop_sharp_corners(Cdt& cdt, const BlockSet& blocks, const Group& group,
                                   const std::vector<RingHandles>& rings, const GroupSize& size) {
  std::vector<Lop> lops = corners_to_lop(blocks, group, rings);
  const std::vector<double> radius = lop_radii(cdt, lops, size);  // before any lop
  for (size_t l = 0; l < lops.size(); ++l) {
    Lop& lop = lops[l];
    lop.a = lop_point(cdt, lop.apex, lop.out, radius[l]);
    lop.b = lop_point(cdt, lop.apex, lop.back, radius[l]);
    if (!star_turns_left(cdt, lop.a) || !star_turns_left(cdt, lop.b))
      fail("block {}: zoning could not cut off its sharp corner at ({}, {}) (an internal error)",
           shown(group[lop.k]), lop.apex->point().x(), lop.apex->point().y());
    cdt.insert_constraint(lop.a, lop.b);
  }
  return lops;
}

// ---------------------------------------------------------------------------------------------
// Labelling the faces with their blocks.

// Enters `seed` and every face reachable from it without crossing a constrained edge;
// enter(face) marks the face and says whether it was new.
template <typename Enter>
void flood(FaceHandle seed, Enter enter) {
  if (!enter(seed)) return;
  std::vector<FaceHandle> stack{seed};
  while (!stack.empty()) {
    const FaceHandle face = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i)
      if (!face->is_constrained(i) && enter(face->neighbor(i))) stack.push_back(face->neighbor(i));
  }
}

// Gives the cell of `seed` the block k.
void flood_block(const Cdt& cdt, FaceHandle seed, int k, const Group& group) {
  flood(seed, [&](FaceHandle face) {
    const int block = face->info().block;
    if (block == k) return false;
    if (block >= 0)
      fail("blocks {} and {} overlap and cannot be zoned", shown(group[block]), shown(group[k]));
    if (cdt.is_infinite(face))
      fail("block {}: its rings do not enclose it (is a hole outside its outer boundary?)",
           shown(group[k]));
    face->info().block = k;
    return true;
  });
}

// Labels every face with its block in the group (-1 outside them all) and marks the lopped
// corners frozen: flood fills over unconstrained edges from the face left of each ring edge's
// first piece, from both sides of each lid, and from each lopped corner. Refinement splits
// constrained edges but never crosses them, so labelling again after it finds the same cells.
void label_blocks(Cdt& cdt, const BlockSet& blocks, const Group& group,
                  const std::vector<RingHandles>& rings, const std::vector<Lop>& lops) {
  for (auto face = cdt.all_faces_begin(); face != cdt.all_faces_end(); ++face)
    face->info() = FaceInfo{};
  for (size_t k = 0; k < group.size(); ++k) {
    const Block& block = blocks.blocks[group[k]];
    for (size_t r = 0; r < rings[k].size(); ++r) {
      const Ring& ring = ring_of(block, r);
      const size_t n = ring.points.size();
      for (size_t i = 0; i < n; ++i) {
        const Vec2 along = ring.points[(i + 1) % n] - ring.points[i];
        const Cdt::Edge edge = edge_leaving(cdt, rings[k][r][i], along, any_edge);
        if (edge.first != FaceHandle()) flood_block(cdt, edge.first, static_cast<int>(k), group);
      }
    }
  }
  for (const Lop& lop : lops) {
    const Vec2 lid = to_vec(lop.b->point()) - to_vec(lop.a->point());
    const Cdt::Edge edge = edge_leaving(cdt, lop.a, lid, any_edge);
    flood_block(cdt, edge.first, lop.k, group);
    flood_block(cdt, edge.first->neighbor(edge.second), lop.k, group);
    flood(edge_leaving(cdt, lop.apex, lop.out, any_edge).first, [](FaceHandle face) {
      if (face->info().frozen) return false;
      face->info().frozen = true;
      return true;
    });
  }
}

// Refinement works on the faces in its domain: those of the group's blocks, lopped corners
// aside.
bool refinable(const Cdt& cdt, FaceHandle face) {
  return !cdt.is_infinite(face) && face->info().block >= 0 && !face->info().frozen;
}

void mark_domain(Cdt& cdt) {
  for (auto face = cdt.all_faces_begin(); face != cdt.all_faces_end(); ++face)
    face->set_in_domain(refinable(cdt, face));
}

// Refines until no face is bad (true), or until the mesh would pass max_zones (false). The
// domain marks must be set.
//
// Two passes. The first is CGAL's: Ruppert's refinement with Shewchuk's cluster rule, which
// stops splitting near two constrained edges that meet at less than 60 degrees. That rule
// looks at the edges only, not at which side is the block, so it also spares skinny zones at a
// reflex corner whose edges make a narrow notch. The second pass insists on every badly shaped
// face except those whose smallest angle is at a sharp block corner. It usually adds nothing or
// a handful of vertices (at most 116 over some 12000 random blocks); should it ever run away,
// it stops insisting and CGAL's rule, which always terminates, finishes the mesh.
bool refine(Cdt& cdt, const GroupSize& size, int max_zones) {
  SizeShapeCriteria criteria(size);
  CGAL::Null_mesher_level null_level;
  CGAL::Null_mesh_visitor null_visitor;
  CGAL::Mesh_2::Clusters<Cdt> clusters(cdt);
  EdgesLevel edges(cdt, clusters, null_level);
  FacesLevel faces(cdt, criteria, edges);
  LevelsVisitor visitor(faces, edges, null_visitor);
  clusters.create_clusters();
  edges.scan_triangulation();
  faces.scan_triangulation();
  // Every step inserts one vertex (refinement never removes any), so a bound on the number of
  // triangles bounds the loop. The count is all triangles (O(1) to read), so it allows for
  // those outside the blocks at the start.
  const std::size_t max_faces = static_cast<std::size_t>(max_zones) + cdt.tds().number_of_faces();
  // Inserts points until done (true), max_vertices or the budget (false).
  auto run = [&](std::size_t max_vertices) {
    while (cdt.number_of_vertices() < max_vertices) {
      if (!faces.try_to_insert_one_point(visitor)) return true;
      if (cdt.tds().number_of_faces() > max_faces) return false;
    }
    return false;
  };
  const std::size_t unlimited = std::numeric_limits<std::size_t>::max();
  if (!run(unlimited)) return false;
  criteria.insist(true);
  faces.scan_triangulation();
  if (run(cdt.number_of_vertices() * 3 / 2 + 1000)) return true;
  if (cdt.tds().number_of_faces() > max_faces) return false;
  criteria.insist(false);
  faces.scan_triangulation();
  return run(unlimited);
}

// ---------------------------------------------------------------------------------------------
// Reading one block out of its group's CDT.

// One block's share of the mesh, its gridpoints numbered from 0; appended in block order once
// every group is meshed.
struct BlockZones {
  std::vector<Vec2> gp_position;
  std::vector<std::array<int, 3>> zone_gp;
  std::vector<BoundaryLoop> loops;
};

class GridpointNumbering {
 public:
  explicit GridpointNumbering(BlockZones& out) : out_(out) {}
  int operator()(VertexHandle v) {
    if (v->info().gp < 0) {
      v->info().gp = static_cast<int>(out_.gp_position.size());
      out_.gp_position.push_back(to_vec(v->point()));
    }
    return v->info().gp;
  }

 private:
  BlockZones& out_;
};

// The next vertex along the boundary of block k from v (block on the left): the other end of
// a constrained edge whose face on the left is in the block and whose face on the right is not
// (on a glued edge that one is in the neighbouring block). Usually one such edge leaves v;
// where rings touch there are more, and the one along the ring edge (direction `along`) is
// taken.
VertexHandle next_boundary_vertex(const Cdt& cdt, VertexHandle v, Vec2 along, int k) {
  const Cdt::Edge edge = edge_leaving(cdt, v, along, [k](FaceHandle face, int e) {
    return face->info().block == k && face->neighbor(e)->info().block != k;
  });
  if (edge.first == FaceHandle()) return VertexHandle();
  return edge.first->vertex(Cdt::cw(edge.second));
}

// Walks one ring of block k along the refined boundary, copying each ring edge's origin onto
// the segments it was split into.
BoundaryLoop walk_ring(const Cdt& cdt, const Ring& ring, const std::vector<VertexHandle>& handles,
                       int k, GridpointNumbering& number, int block) {
  BoundaryLoop loop;
  const size_t n = handles.size();
  const size_t max_steps = cdt.number_of_vertices();
  for (size_t i = 0; i < n; ++i) {
    const VertexHandle target = handles[(i + 1) % n];
    const Vec2 along = ring.points[(i + 1) % n] - ring.points[i];
    VertexHandle v = handles[i];
    for (size_t step = 0; v != target; ++step) {
      const VertexHandle w = next_boundary_vertex(cdt, v, along, k);
      if (w == VertexHandle() || step > max_steps)
        fail("block {}: lost the boundary after ({}, {}); the block outline is not simple",
             shown(block), v->point().x(), v->point().y());
      loop.gridpoints.push_back(number(v));
      loop.edges.push_back(ring.edges[i]);
      v = w;
    }
  }
  return loop;
}

// Spreads 16-bit x and y into a 32-bit Morton (Z-order) key, for a cache-friendly order.
std::uint32_t morton_key(Vec2 p, const Box& box) {
  auto cell = [](double t) {
    const double c = std::clamp(t, 0.0, 1.0) * 65535.0;
    std::uint32_t k = static_cast<std::uint32_t>(c);
    k = (k | (k << 8)) & 0x00FF00FFu;
    k = (k | (k << 4)) & 0x0F0F0F0Fu;
    k = (k | (k << 2)) & 0x33333333u;
    k = (k | (k << 1)) & 0x55555555u;
    return k;
  };
  const double wx = box.x1 > box.x0 ? box.x1 - box.x0 : 1.0;
  const double wy = box.y1 > box.y0 ? box.y1 - box.y0 : 1.0;
  return cell((p.x - box.x0) / wx) | (cell((p.y - box.y0) / wy) << 1);
}

template <typename Handle, typename Position>
void sort_by_morton(std::vector<Handle>& items, const Box& box, Position position) {
  std::vector<std::pair<std::uint32_t, int>> keys(items.size());
  for (size_t i = 0; i < items.size(); ++i)
    keys[i] = {morton_key(position(items[i]), box), static_cast<int>(i)};
  std::sort(keys.begin(), keys.end());
  std::vector<Handle> sorted;
  sorted.reserve(items.size());
  for (const auto& key : keys) sorted.push_back(items[key.second]);
  items = std::move(sorted);
}

// Block k of its group (`faces`: its faces, labelled k): boundary gridpoints first, in loop
// order; then the interior ones and the zones in Z-order.
BlockZones read_block(const Cdt& cdt, const Block& block, int k, int index,
                      const RingHandles& rings, const std::vector<FaceHandle>& faces) {
  // Vertices on a shared edge still hold the numbers of the block read before: start afresh.
  for (const FaceHandle face : faces)
    for (int i = 0; i < 3; ++i) face->vertex(i)->info().gp = -1;
  BlockZones out;
  GridpointNumbering number(out);
  for (size_t r = 0; r < rings.size(); ++r)
    out.loops.push_back(walk_ring(cdt, ring_of(block, r), rings[r], k, number, index));

  const Box box = bounding_box(block.outer.points);
  std::vector<VertexHandle> interior;
  for (const FaceHandle face : faces) {
    for (int i = 0; i < 3; ++i) {
      const VertexHandle v = face->vertex(i);
      if (v->info().gp == -1) {
        v->info().gp = -2;  // seen, not yet numbered
        interior.push_back(v);
      }
    }
  }
  sort_by_morton(interior, box, [](VertexHandle v) { return to_vec(v->point()); });
  for (const VertexHandle v : interior) {
    v->info().gp = -1;
    number(v);
  }
  std::vector<FaceHandle> ordered = faces;
  sort_by_morton(ordered, box, [](FaceHandle f) {
    const Vec2 a = to_vec(f->vertex(0)->point()), b = to_vec(f->vertex(1)->point()),
               c = to_vec(f->vertex(2)->point());
    return Vec2{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
  });
  for (const FaceHandle face : ordered)
    out.zone_gp.push_back({face->vertex(0)->info().gp, face->vertex(1)->info().gp,
                           face->vertex(2)->info().gp});  // CGAL faces are counter-clockwise
  return out;
}

// ---------------------------------------------------------------------------------------------
// One group.

// Names the group by its block with the sharpest corner (the first block if none is sharp),
// which is what usually makes the count explode.
[[noreturn]] void fail_budget(const BlockSet& blocks, const Group& group,
                              const std::vector<const SizeField*>& fields, int max_zones) {
  double sharpest = 360.0, edge = std::numeric_limits<double>::infinity();
  int named = group.front();
  for (size_t k = 0; k < group.size(); ++k) {
    const Block& block = blocks.blocks[group[k]];
    edge = std::min(edge, fields[k]->edge);
    for (size_t r = 0; r <= block.holes.size(); ++r) {
      const Ring& ring = ring_of(block, r);
      for (size_t i = 0; i < ring.points.size(); ++i) {
        const double angle = interior_angle(ring, i);
        if (angle < sharpest) {
          sharpest = angle;
          named = group[k];
        }
      }
    }
  }
  if (sharpest >= kShapeBoundAngle) named = group.front();
  const std::string what =
      group.size() == 1
          ? fmt::format("block {}: zoning it", shown(named))
          : fmt::format("block {} and the {} {} glued to it: zoning them together", shown(named),
                        group.size() - 1, group.size() == 2 ? "block" : "blocks");
  if (sharpest < kShapeBoundAngle)
    fail(
        "{} would make more than {} zones (zone edge {} m, sharpest corner {:.3g} deg, which "
        "needs ever smaller zones); make the edge larger or the block less slender",
        what, max_zones, edge, sharpest);
  fail("{} would make more than {} zones (zone edge {} m); make the edge larger", what, max_zones,
       edge);
}

// Inserts the rings of the group's blocks; returns their vertex handles, per block.
std::vector<RingHandles> insert_rings(Cdt& cdt, const BlockSet& blocks, const Group& group) {
  std::vector<RingHandles> rings(group.size());
  for (size_t k = 0; k < group.size(); ++k) {
    const Block& block = blocks.blocks[group[k]];
    try {
      for (size_t r = 0; r <= block.holes.size(); ++r)
        rings[k].push_back(insert_ring(cdt, ring_of(block, r), static_cast<int>(k)));
    } catch (const Cdt::Intersection_of_constraints_exception&) {
      if (group.size() == 1)
        fail("block {}: its boundary crosses itself and cannot be zoned", shown(group[k]));
      fail("block {}: its boundary crosses itself or a block glued to it and cannot be zoned",
           shown(group[k]));
    }
  }
  return rings;
}

// Meshes the blocks of one group in one CDT and reads each block out into zones[block].
void mesh_group(const BlockSet& blocks, const Group& group,
                const std::vector<const SizeField*>& size_of_block,
                const BlocksAtVertex& blocks_at, int max_zones, std::vector<BlockZones>& zones) {
  std::vector<const SizeField*> fields;
  for (int b : group) fields.push_back(size_of_block[b]);

  // A cheap lower bound first: even with equilateral zones of their `far` size the blocks may
  // need too many.
  double fewest = 0.0;
  for (size_t k = 0; k < group.size(); ++k) {
    const Block& block = blocks.blocks[group[k]];
    double area = ring_area(block.outer);
    for (const Ring& hole : block.holes) area += ring_area(hole);  // holes: negative
    fewest += area / (0.25 * std::sqrt(3.0) * fields[k]->far * fields[k]->far);
  }
  if (fewest > max_zones) fail_budget(blocks, group, fields, max_zones);

  Cdt cdt;
  const std::vector<RingHandles> rings = insert_rings(cdt, blocks, group);
  const GroupSize size(fields);
  std::vector<Lop> lops;
  if (group.size() > 1) {
    mark_vertices_on_other_rings(cdt);
    insert_neighbours(cdt, blocks, group, blocks_at);
    insert_frame(cdt);
    lops = lop_sharp_corners(cdt, blocks, group, rings, size);
  }
  label_blocks(cdt, blocks, group, rings, lops);
  mark_domain(cdt);
  if (!refine(cdt, size, max_zones)) fail_budget(blocks, group, fields, max_zones);

  label_blocks(cdt, blocks, group, rings, lops);
  std::vector<std::vector<FaceHandle>> faces(group.size());
  for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face) {
    // The mesher kept its own domain marks while refining; they must agree with the labels.
    if (refinable(cdt, face) != face->is_in_domain())
      fail("block {}: zoning lost track of the block's faces (an internal error)",
           shown(group.front()));
    if (face->info().block >= 0) faces[face->info().block].push_back(face);
  }
  for (size_t k = 0; k < group.size(); ++k)
    zones[group[k]] = read_block(cdt, blocks.blocks[group[k]], static_cast<int>(k),
                                 group[k], rings[k], faces[k]);
}

// Appends the blocks' shares in block order, renumbering their gridpoints.
Mesh assemble(std::vector<BlockZones>& zones) {
  const size_t count = zones.size();
  Mesh mesh;
  mesh.block_first_gp.reserve(count + 1);
  mesh.block_first_zone.reserve(count + 1);
  mesh.block_boundary.resize(count);
  mesh.block_first_gp.push_back(0);
  mesh.block_first_zone.push_back(0);
  for (size_t b = 0; b < count; ++b) {
    BlockZones& block = zones[b];
    const int offset = mesh.gp_count();
    mesh.gp_position.insert(mesh.gp_position.end(), block.gp_position.begin(),
                            block.gp_position.end());
    mesh.gp_block.insert(mesh.gp_block.end(), block.gp_position.size(), static_cast<int>(b));
    for (const auto& zone : block.zone_gp) {
      mesh.zone_gp.push_back({zone[0] + offset, zone[1] + offset, zone[2] + offset});
      mesh.zone_block.push_back(static_cast<int>(b));
    }
    for (BoundaryLoop& loop : block.loops)
      for (int& gp : loop.gridpoints) gp += offset;
    mesh.block_boundary[b] = std::move(block.loops);
    block = BlockZones{};  // release it as the mesh grows
    mesh.block_first_gp.push_back(mesh.gp_count());
    mesh.block_first_zone.push_back(mesh.zone_count());
  }
  return mesh;
}

}  // namespace

double SizeField::at(Vec2 point) const {
  return SizeEvaluator(*this).at(point);
}

double estimated_zone_count(const std::vector<Polygon>& blocks, const SizeField& size) {
  if (blocks.empty()) return 0.0;
  const SizeEvaluator at(size);
  const auto zone_area = [](double edge) { return std::sqrt(3.0) / 4.0 * edge * edge; };
  Polygon all;
  for (const Polygon& block : blocks) all.insert(all.end(), block.begin(), block.end());
  const Box box = bounding_box(all);
  constexpr int kSamples = 200;
  const double dx = (box.x1 - box.x0) / kSamples, dy = (box.y1 - box.y0) / kSamples;
  double count = 0.0;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const Vec2 p{box.x0 + (i + 0.5) * dx, box.y0 + (j + 0.5) * dy};
      for (const Polygon& block : blocks)
        if (contains(block, p)) {
          count += dx * dy / zone_area(at.at(p));
          break;
        }
    }
  for (const Polygon& block : blocks) {  // thin blocks, which the grid may miss
    const double area = std::fabs(signed_area(block)), length = perimeter(block);
    const double width = 2.0 * area / length, edge = at.at(block.front());
    if (width < edge) count += length / (2.0 * width);
  }
  return count;
}

Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block,
                 int max_zones_per_block) {
  const size_t count = blocks.blocks.size();
  if (size_of_block.size() != count)
    fail("zoning: {} size fields given for {} blocks", size_of_block.size(), count);
  for (size_t b = 0; b < count; ++b)
    if (size_of_block[b] != nullptr)
      check_block(blocks.blocks[b], *size_of_block[b], static_cast<int>(b));
  std::vector<BlockZones> zones(count);
  const std::vector<Group> groups = touching_groups(blocks, size_of_block);
  BlocksAtVertex blocks_at;
  if (std::any_of(groups.begin(), groups.end(), [](const Group& g) { return g.size() > 1; }))
    blocks_at = blocks_at_vertices(blocks);
  for (const Group& group : groups)
    mesh_group(blocks, group, size_of_block, blocks_at, max_zones_per_block, zones);
  return assemble(zones);
}

Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block) {
  return zone_blocks(blocks, size_of_block, kMaxZonesPerBlock);
}

}  // namespace edem
