// Zoning with CGAL's constrained Delaunay refinement (Ruppert's algorithm, Shewchuk's clusters).
//
// Each block is meshed on its own: its rings go in as constraints of a CDT, the faces inside
// the outer ring and outside the holes are marked by nesting level, and CGAL's mesher levels
// (assembled here rather than through Delaunay_mesher_2, see DomainGabriel and refine()) insert
// points one at a time until every face meets the size field and the shape bound. A zone
// budget stops runaway meshes. The refined CDT is then read out block-contiguously: boundary
// gridpoints in loop order first, then interior gridpoints and zones in Z-order.
#include "geom/zoning.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>  // the mesher levels, assembled below
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <queue>
#include <utility>

#include "core/error.hpp"

namespace edem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
struct VertexInfo {
  int gp = -1;         // gridpoint index, -1 until numbered
  bool sharp = false;  // a block corner sharper than the shape bound (kShapeBoundAngle)
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
// Face info: nesting level while marking the domain.
using FaceInfoBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
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

// ---------------------------------------------------------------------------------------------
// Refinement criteria, modelled on CGAL::Delaunay_mesh_size_criteria_2 but with a size field:
// a face is imperatively bad when its longest edge exceeds the size at its centroid, and bad
// when its smallest angle is below asin(sqrt(B)). Imperatively bad faces are split even next to
// small input angles, where CGAL's cluster rule spares merely bad ones (that is what keeps
// refinement from running forever at sharp corners).
//
// With `insist` set (the second pass, see refine()), a badly shaped face is imperatively bad
// too, unless its smallest angle sits at a sharp block corner: no mesh can do better there.

class SizeShapeCriteria : public CGAL::Delaunay_mesh_criteria_2<Cdt> {
 public:
  using Base = CGAL::Delaunay_mesh_criteria_2<Cdt>;
  using Face_handle = Cdt::Face_handle;

  SizeShapeCriteria(const SizeEvaluator& size, double shape_bound = kShapeBound)
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
    Is_bad(double shape_bound, const SizeEvaluator* size, bool insist)
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
      q.insist = insist_ && !face->vertex(shortest)->info().sharp;
      return q.insist ? CGAL::Mesh_2::IMPERATIVELY_BAD : CGAL::Mesh_2::BAD;
    }

   private:
    double bound_;
    const SizeEvaluator* size_;
    bool insist_;
  };

  Is_bad is_bad_object() const { return Is_bad(bound(), size_, insist_); }

 private:
  const SizeEvaluator* size_;
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
// One block.

void check_size_field(const SizeField& field, int block) {
  if (!(std::isfinite(field.edge) && field.edge > 0.0))
    fail("block {}: zone edge must be a positive length, got {}", block, field.edge);
  if (!(std::isfinite(field.far) && field.far >= field.edge))
    fail("block {}: zone far size {} must be at least the edge {}", block, field.far, field.edge);
  if (!(std::isfinite(field.growth) && field.growth >= 0.0))
    fail("block {}: zone growth must be zero or positive, got {}", block, field.growth);
}

void check_ring(const Ring& ring, int block, const char* what) {
  const size_t n = ring.points.size();
  if (n < 3) fail("block {}: its {} has {} vertices, at least 3 are needed", block, what, n);
  if (ring.edges.size() != n)
    fail("block {}: its {} has {} vertices but {} edge origins", block, what, n, ring.edges.size());
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = ring.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      fail("block {}: its {} has a non-finite vertex", block, what);
    if (p == ring.points[(i + 1) % n])
      fail("block {}: its {} repeats vertex ({}, {})", block, what, p.x, p.y);
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

// Inserts the ring's vertices and edges; returns the vertex handle of each ring point.
std::vector<VertexHandle> insert_ring(Cdt& cdt, const Ring& ring) {
  std::vector<VertexHandle> handles;
  handles.reserve(ring.points.size());
  for (size_t i = 0; i < ring.points.size(); ++i) {
    const Vec2 p = ring.points[i];
    handles.push_back(cdt.insert(Point(p.x, p.y)));
    if (interior_angle(ring, i) < kShapeBoundAngle) handles.back()->info().sharp = true;
  }
  for (size_t i = 0; i < handles.size(); ++i)
    cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
  return handles;
}

// In the domain: faces at odd nesting level (crossing constraints from the infinite face),
// i.e. inside the outer ring and outside every hole.
void mark_domain(Cdt& cdt) {
  for (auto face = cdt.all_faces_begin(); face != cdt.all_faces_end(); ++face) face->info() = -1;
  std::queue<FaceHandle> level_seeds, queue;
  level_seeds.push(cdt.infinite_face());
  int level = 0;
  while (!level_seeds.empty()) {
    std::queue<FaceHandle> next_seeds;
    while (!level_seeds.empty()) {
      const FaceHandle seed = level_seeds.front();
      level_seeds.pop();
      if (seed->info() != -1) continue;
      seed->info() = level;
      queue.push(seed);
      while (!queue.empty()) {
        const FaceHandle face = queue.front();
        queue.pop();
        for (int i = 0; i < 3; ++i) {
          const FaceHandle neighbor = face->neighbor(i);
          if (neighbor->info() != -1) continue;
          if (face->is_constrained(i)) {
            next_seeds.push(neighbor);
          } else {
            neighbor->info() = level;
            queue.push(neighbor);
          }
        }
      }
    }
    level_seeds = std::move(next_seeds);
    ++level;
  }
  for (auto face = cdt.all_faces_begin(); face != cdt.all_faces_end(); ++face)
    face->set_in_domain(!cdt.is_infinite(face) && face->info() % 2 == 1);
}

bool in_domain(const Cdt& cdt, FaceHandle face) {
  return !cdt.is_infinite(face) && face->is_in_domain();
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
bool refine(Cdt& cdt, const SizeEvaluator& size, int max_zones) {
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
  // those outside the block at the start.
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

class GridpointNumbering {
 public:
  GridpointNumbering(Mesh& mesh, int block) : mesh_(mesh), block_(block) {}
  int operator()(VertexHandle v) {
    if (v->info().gp < 0) {
      v->info().gp = mesh_.gp_count();
      mesh_.gp_position.push_back(to_vec(v->point()));
      mesh_.gp_block.push_back(block_);
    }
    return v->info().gp;
  }

 private:
  Mesh& mesh_;
  int block_;
};

// The next vertex along the domain boundary from v towards `target` (domain on the left).
// Usually one boundary edge leaves v; where rings touch there are more, and the one along
// the ring edge (direction `along`) is taken.
VertexHandle next_boundary_vertex(const Cdt& cdt, VertexHandle v, Vec2 along) {
  VertexHandle best;
  double best_deviation = std::numeric_limits<double>::infinity();
  auto face = cdt.incident_faces(v);
  const auto first = face;
  do {
    if (in_domain(cdt, face)) {
      const int i = face->index(v);
      const int e = Cdt::cw(i);  // edge v -> vertex(ccw(i)), face on its left
      if (face->is_constrained(e) && !in_domain(cdt, face->neighbor(e))) {
        const VertexHandle w = face->vertex(Cdt::ccw(i));
        const Vec2 step = to_vec(w->point()) - to_vec(v->point());
        const double deviation = dot(step, along) > 0.0 ? std::abs(cross(along, step)) / norm(step)
                                                        : std::numeric_limits<double>::max();
        if (deviation < best_deviation) {
          best_deviation = deviation;
          best = w;
        }
      }
    }
  } while (++face != first);
  return best;
}

// Walks one ring along the refined boundary, copying each ring edge's origin onto the
// segments it was split into.
BoundaryLoop walk_ring(const Cdt& cdt, const Ring& ring, const std::vector<VertexHandle>& handles,
                       GridpointNumbering& number, int block) {
  BoundaryLoop loop;
  const size_t n = handles.size();
  const size_t max_steps = cdt.number_of_vertices();
  for (size_t i = 0; i < n; ++i) {
    const VertexHandle target = handles[(i + 1) % n];
    const Vec2 along = ring.points[(i + 1) % n] - ring.points[i];
    VertexHandle v = handles[i];
    for (size_t step = 0; v != target; ++step) {
      const VertexHandle w = next_boundary_vertex(cdt, v, along);
      if (w == VertexHandle() || step > max_steps)
        fail("block {}: lost the boundary after ({}, {}); the block outline is not simple", block,
             v->point().x(), v->point().y());
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

[[noreturn]] void fail_budget(const Block& block, const SizeField& field, int index,
                              int max_zones) {
  double sharpest = 360.0;
  auto visit = [&](const Ring& ring) {
    for (size_t i = 0; i < ring.points.size(); ++i)
      sharpest = std::min(sharpest, interior_angle(ring, i));
  };
  visit(block.outer);
  for (const Ring& hole : block.holes) visit(hole);
  if (sharpest < kShapeBoundAngle)
    fail(
        "block {}: zoning it would make more than {} zones (zone edge {} m, sharpest corner "
        "{:.3g} deg, which needs ever smaller zones); make the edge larger or the block less "
        "slender",
        index, max_zones, field.edge, sharpest);
  fail("block {}: zoning it would make more than {} zones (zone edge {} m); make the edge larger",
       index, max_zones, field.edge);
}

void mesh_block(const Block& block, const SizeField& field, int index, int max_zones, Mesh& mesh) {
  check_size_field(field, index);
  check_ring(block.outer, index, "outer boundary");
  for (const Ring& hole : block.holes) check_ring(hole, index, "hole");
  // The boundary walk relies on the block lying left of every ring.
  if (!(ring_area(block.outer) > 0.0))
    fail("block {}: its outer boundary must be counter-clockwise", index);
  for (const Ring& hole : block.holes)
    if (!(ring_area(hole) < 0.0)) fail("block {}: its holes must be clockwise", index);

  // A cheap lower bound first: even with equilateral zones of the `far` size the block may
  // need too many.
  double area = ring_area(block.outer);
  for (const Ring& hole : block.holes) area += ring_area(hole);  // holes: negative
  const double fewest = area / (0.25 * std::sqrt(3.0) * field.far * field.far);
  if (fewest > max_zones) fail_budget(block, field, index, max_zones);

  Cdt cdt;
  std::vector<std::vector<VertexHandle>> rings;
  try {
    rings.push_back(insert_ring(cdt, block.outer));
    for (const Ring& hole : block.holes) rings.push_back(insert_ring(cdt, hole));
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    fail("block {}: its boundary crosses itself and cannot be zoned", index);
  }
  mark_domain(cdt);
  const SizeEvaluator size(field);
  if (!refine(cdt, size, max_zones)) fail_budget(block, field, index, max_zones);

  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info().gp = -1;
  GridpointNumbering number(mesh, index);

  // Boundary gridpoints first, in loop order; then the interior ones in Z-order.
  auto& loops = mesh.block_boundary[index];
  loops.push_back(walk_ring(cdt, block.outer, rings[0], number, index));
  for (size_t h = 0; h < block.holes.size(); ++h)
    loops.push_back(walk_ring(cdt, block.holes[h], rings[h + 1], number, index));

  const Box box = bounding_box(block.outer.points);
  std::vector<VertexHandle> interior;
  std::vector<FaceHandle> faces;
  for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face) {
    if (!face->is_in_domain()) continue;
    faces.push_back(face);
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
  sort_by_morton(faces, box, [](FaceHandle f) {
    const Vec2 a = to_vec(f->vertex(0)->point()), b = to_vec(f->vertex(1)->point()),
               c = to_vec(f->vertex(2)->point());
    return Vec2{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
  });
  for (const FaceHandle face : faces) {
    mesh.zone_gp.push_back({face->vertex(0)->info().gp, face->vertex(1)->info().gp,
                            face->vertex(2)->info().gp});  // CGAL faces are counter-clockwise
    mesh.zone_block.push_back(index);
  }
}

}  // namespace

double SizeField::at(Vec2 point) const {
  return SizeEvaluator(*this).at(point);
}

Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block,
                 int max_zones_per_block) {
  const size_t count = blocks.blocks.size();
  if (size_of_block.size() != count)
    fail("zoning: {} size fields given for {} blocks", size_of_block.size(), count);
  Mesh mesh;
  mesh.block_first_gp.reserve(count + 1);
  mesh.block_first_zone.reserve(count + 1);
  mesh.block_boundary.resize(count);
  mesh.block_first_gp.push_back(0);
  mesh.block_first_zone.push_back(0);
  for (size_t b = 0; b < count; ++b) {
    if (size_of_block[b] != nullptr)
      mesh_block(blocks.blocks[b], *size_of_block[b], static_cast<int>(b), max_zones_per_block,
                 mesh);
    mesh.block_first_gp.push_back(mesh.gp_count());
    mesh.block_first_zone.push_back(mesh.zone_count());
  }
  return mesh;
}

Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block) {
  return zone_blocks(blocks, size_of_block, kMaxZonesPerBlock);
}

}  // namespace edem
