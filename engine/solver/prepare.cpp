// Nodes, zone geometry, masses, time step, loads and the thread partition.
#include "solver/prepare.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "bolt/bolt_coupling.hpp"
#include "constitutive/zone_law.hpp"
#include "contact/detect.hpp"
#include "core/error.hpp"
#include "core/union_find.hpp"
#include "crack/judge.hpp"
#include "solver/load_balance.hpp"
#include "solver/loads.hpp"
#include "solver/zone_groups.hpp"

namespace edem {
namespace {

// Mesh gridpoint -> node: gridpoints at the two ends of the same glued segment (edge_glued, per
// flat loop edge), seen from the blocks on either side, become one node.
std::vector<int> merge_glued(const Mesh& mesh, const std::vector<char>& edge_glued, int& node_count) {
  const int n = mesh.gp_count();
  std::vector<int> parent(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) parent[static_cast<size_t>(i)] = i;
  using Key = std::pair<std::pair<double, double>, std::pair<double, double>>;
  std::map<Key, std::pair<int, int>> first_side;  // segment -> its gridpoints (a, b)
  size_t flat = 0;
  for (const auto& loops : mesh.block_boundary) {
    for (const BoundaryLoop& loop : loops) {
      const size_t count = loop.gridpoints.size();
      for (size_t i = 0; i < count; ++i, ++flat) {
        if (!edge_glued[flat]) continue;
        const int a = loop.gridpoints[i], b = loop.gridpoints[(i + 1) % count];
        Vec2 pa = mesh.gp_position[static_cast<size_t>(a)];
        Vec2 pb = mesh.gp_position[static_cast<size_t>(b)];
        const bool swap = std::make_pair(pb.x, pb.y) < std::make_pair(pa.x, pa.y);
        const Key key = swap ? Key{{pb.x, pb.y}, {pa.x, pa.y}} : Key{{pa.x, pa.y}, {pb.x, pb.y}};
        const std::pair<int, int> ends = swap ? std::make_pair(b, a) : std::make_pair(a, b);
        const auto [it, inserted] = first_side.emplace(key, ends);
        if (inserted) continue;
        parent[static_cast<size_t>(find_root(parent, ends.first))] = find_root(parent, it->second.first);
        parent[static_cast<size_t>(find_root(parent, ends.second))] = find_root(parent, it->second.second);
      }
    }
  }
  std::vector<int> node_of_root(static_cast<size_t>(n), -1), gp_node(static_cast<size_t>(n));
  node_count = 0;
  for (int i = 0; i < n; ++i) {
    int& node = node_of_root[static_cast<size_t>(find_root(parent, i))];
    if (node < 0) node = node_count++;
    gp_node[static_cast<size_t>(i)] = node;
  }
  return gp_node;
}

// The outer boundary segments of the mesh (block{} outlines), with their nodes.
std::vector<BoundarySegment> outer_boundary(const Mesh& mesh, const std::vector<int>& gp_node) {
  std::vector<BoundarySegment> boundary;
  for (const auto& loops : mesh.block_boundary)
    for (const BoundaryLoop& loop : loops)
      for (size_t i = 0; i < loop.gridpoints.size(); ++i)
        if (loop.edges[i].kind == EdgeKind::boundary)
          boundary.push_back({gp_node[static_cast<size_t>(loop.gridpoints[i])],
                              gp_node[static_cast<size_t>(loop.gridpoints[(i + 1) % loop.gridpoints.size()])],
                              false, {}, {}});
  return boundary;
}

ZoneGeometry zone_geometry(const Mechanics& m, const Mesh& mesh, int zone) {
  ZoneGeometry g;
  Vec2 p[3];
  for (int i = 0; i < 3; ++i) {
    const int gp = mesh.zone_gp[static_cast<size_t>(zone)][static_cast<size_t>(i)];
    g.node[static_cast<size_t>(i)] = m.gp_node[static_cast<size_t>(gp)];
    p[i] = mesh.gp_position[static_cast<size_t>(gp)];
  }
  const double twice_area = cross(p[1] - p[0], p[2] - p[0]);
  g.area = 0.5 * twice_area;
  for (int i = 0; i < 3; ++i) {
    const Vec2 pj = p[(i + 1) % 3], pk = p[(i + 2) % 3];
    g.b[i] = (pj.y - pk.y) / twice_area;
    g.c[i] = (pk.x - pj.x) / twice_area;
  }
  return g;
}

// Gershgorin row sums of one zone's stiffness matrix A B^T D B, added to the nodes: free rows
// over free columns only, since held components do not take part in the vibration.
void add_row_sums(const ZoneGeometry& g, const MaterialParams& p,
                  const std::vector<std::uint8_t>& fix, std::vector<double>& rows) {
  auto free = [&](int corner, int axis) {
    return !((fix[static_cast<size_t>(g.node[static_cast<size_t>(corner)])] >> axis) & 1);
  };
  for (int i = 0; i < 3; ++i) {
    double row_x = 0.0, row_y = 0.0;
    for (int j = 0; j < 3; ++j) {
      const double xx = p.e1 * g.b[i] * g.b[j] + p.shear * g.c[i] * g.c[j];
      const double xy = p.e2 * g.b[i] * g.c[j] + p.shear * g.c[i] * g.b[j];
      const double yx = p.e2 * g.c[i] * g.b[j] + p.shear * g.b[i] * g.c[j];
      const double yy = p.e1 * g.c[i] * g.c[j] + p.shear * g.b[i] * g.b[j];
      if (free(j, 0)) row_x += std::fabs(xx), row_y += std::fabs(yx);
      if (free(j, 1)) row_x += std::fabs(xy), row_y += std::fabs(yy);
    }
    const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
    if (free(i, 0)) rows[2 * n] += g.area * row_x;
    if (free(i, 1)) rows[2 * n + 1] += g.area * row_y;
  }
}

std::vector<int> chunked_split(int items, int parts) {
  const int chunks = (items + kChunk - 1) / kChunk;
  std::vector<int> begin(static_cast<size_t>(parts) + 1);
  for (int t = 0; t <= parts; ++t)
    begin[static_cast<size_t>(t)] = std::min(items, static_cast<int>(static_cast<long>(chunks) * t / parts) * kChunk);
  return begin;
}

Partition make_partition(const Mechanics& m, int threads) {
  Partition part;
  part.threads = threads;
  const int zones = static_cast<int>(m.active.size());
  part.zone_begin = chunked_split(zones, threads);
  part.contact_cut = even_cuts(threads);
  part.node_cut = even_cuts(threads);
  // The order zones are done in: active order, except that the other members of a mixed
  // group follow its first member, whose thread does the whole group. Contributions to a node
  // are summed in this order whatever the thread count.
  std::vector<int> order, range_of(static_cast<size_t>(zones));
  order.reserve(static_cast<size_t>(zones));
  for (int t = 0; t < threads; ++t)
    for (int k = part.zone_begin[static_cast<size_t>(t)]; k < part.zone_begin[static_cast<size_t>(t) + 1]; ++k) {
      const std::array<int, 2> others = m.mates.empty() ? std::array<int, 2>{-1, -1} : m.mates[static_cast<size_t>(k)];
      if (others[0] >= 0 && (others[0] < k || (others[1] >= 0 && others[1] < k))) continue;
      for (const int member : {k, others[0], others[1]}) {
        if (member < 0) continue;
        order.push_back(member);
        range_of[static_cast<size_t>(member)] = t;
      }
    }
  // Corners of each node, in that order.
  std::vector<int> first(static_cast<size_t>(m.node_count) + 1, 0);
  for (int k = 0; k < zones; ++k)
    for (int node : m.geometry[static_cast<size_t>(m.active[static_cast<size_t>(k)])].node)
      ++first[static_cast<size_t>(node) + 1];
  for (size_t n = 0; n < static_cast<size_t>(m.node_count); ++n) first[n + 1] += first[n];
  std::vector<int> corners(static_cast<size_t>(first.back()));
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (const int k : order) {
    const auto& node = m.geometry[static_cast<size_t>(m.active[static_cast<size_t>(k)])].node;
    for (int i = 0; i < 3; ++i)
      corners[static_cast<size_t>(fill[static_cast<size_t>(node[static_cast<size_t>(i)])]++)] = 3 * k + i;
  }
  part.dest.resize(static_cast<size_t>(zones));
  part.gather_first.assign(static_cast<size_t>(m.node_count) + 1, 0);
  int slot = m.node_count;
  for (int n = 0; n < m.node_count; ++n) {
    const int begin = first[static_cast<size_t>(n)], end = first[static_cast<size_t>(n) + 1];
    bool shared = false;
    for (int c = begin; c < end; ++c)
      shared |= range_of[static_cast<size_t>(corners[static_cast<size_t>(c)] / 3)] !=
                range_of[static_cast<size_t>(corners[static_cast<size_t>(begin)] / 3)];
    for (int c = begin; c < end; ++c) {
      const int corner = corners[static_cast<size_t>(c)];
      int& dest = part.dest[static_cast<size_t>(corner / 3)][static_cast<size_t>(corner % 3)];
      if (!shared) {
        dest = n;
      } else {
        dest = slot++;
        part.gather.push_back(dest);
      }
    }
    part.gather_first[static_cast<size_t>(n) + 1] = static_cast<int>(part.gather.size());
  }
  part.accumulators = slot;
  return part;
}

}  // namespace

void update_masses(Mechanics& m) {
  const size_t nodes = static_cast<size_t>(m.node_count);
  const bool contacts = m.contacts.rows.size() == nodes;
  const bool bolts = m.bolt_hosts.rows.size() == nodes;
  m.stiffness.assign(nodes, 0.0);
  double critical = INFINITY;
  for (size_t n = 0; n < nodes; ++n) {
    m.stiffness[n] = m.zone_rows[n] + (contacts ? m.contacts.rows[n] : 0.0) + (bolts ? m.bolt_hosts.rows[n] : 0.0);
    if (m.stiffness[n] > 0.0 && m.real_mass[n] > 0.0)
      critical = std::min(critical, 2.0 * std::sqrt(m.real_mass[n] / m.stiffness[n]));
  }
  const double fraction = m.settings.step_fraction;
  const double amplification = m.settings.damping == Damping::local ? 1.0 + m.settings.local_damping : 1.0;
  critical = std::min(critical, bolt_masses(m, m.settings.mode == SolverMode::dynamic, amplification, fraction));
  m.critical_step = std::isfinite(critical) ? critical : 0.0;
  if (m.settings.mode == SolverMode::dynamic) {
    m.mass = m.real_mass;
    m.step = m.settings.step > 0.0 ? m.settings.step : fraction * m.critical_step;
  } else {
    // Density scaling: with a step of 1, masses that make every node's own bound equal.
    // Local damping can add up to alpha |F| to a force (when F opposes the velocity), which
    // acts like a stiffness (1 + alpha) times larger: the masses grow with it.
    m.step = 1.0;
    m.mass.resize(nodes);
    for (size_t n = 0; n < nodes; ++n)
      m.mass[n] = amplification * m.stiffness[n] / (4.0 * fraction * fraction);
  }
  m.info.step = m.step;
}

void reset_for_mesh(Mechanics& m, const Mesh& mesh) {
  const size_t zones = static_cast<size_t>(mesh.zone_count());
  m.zone_material.assign(zones, -1);
  m.stress.assign(zones, Stress{});
  m.mean_stress_ref.assign(zones, 0.0);
  m.zone_state.assign(zones, 0);
  m.zone_history.assign(zones, 0.0);
  m.zone_plastic_work.assign(zones, 0.0);
  m.zone_excavated.assign(zones, 0);
  SectionLayout layout = find_sections(mesh);
  m.sections = std::move(layout.sections);
  m.edge_section = std::move(layout.edge_section);
  m.edge_glued = std::move(layout.edge_glued);
  m.cracks.clear();
  m.fresh_cracks = false;
  m.fits = SectionFits{};
  m.gp_node = merge_glued(mesh, m.edge_glued, m.node_count);
  const size_t dofs = 2 * static_cast<size_t>(m.node_count);
  m.position.assign(dofs, 0.0);
  m.node_block.assign(static_cast<size_t>(m.node_count), -1);
  for (size_t gp = 0; gp < m.gp_node.size(); ++gp) {
    const size_t n = static_cast<size_t>(m.gp_node[gp]);
    m.position[2 * n] = mesh.gp_position[gp].x;
    m.position[2 * n + 1] = mesh.gp_position[gp].y;
    if (m.node_block[n] < 0) m.node_block[n] = mesh.gp_block[gp];
  }
  m.u.assign(dofs, 0.0);
  m.origin = m.position;
  m.v.assign(dofs, 0.0);
  m.force.assign(dofs, 0.0);
  m.load.assign(dofs, 0.0);
  m.fix.assign(static_cast<size_t>(m.node_count), 0);
  m.boundary = outer_boundary(mesh, m.gp_node);
  m.faces = contact_boundary(mesh, m.edge_glued, m.gp_node, m.position);
  m.contacts = ContactSet{};
  m.geometry.resize(zones);
  for (size_t z = 0; z < zones; ++z) m.geometry[z] = zone_geometry(m, mesh, static_cast<int>(z));
  m.insitu.clear();
  m.bolts = BoltSet{m.bolts.laws, {}, {}, {0}, {0}};  // bolts are laid in zones: they go with them
  m.bolt_hosts = BoltHosts{};
  m.dirty = true;
}

void reconnect(Mechanics& m, const Mesh& mesh) {
  int count = 0;
  const std::vector<int> fresh = merge_glued(mesh, m.edge_glued, count);
  // Ties are only ever released, so each new node lies within one old node: the first part of
  // an old node (in gridpoint order) keeps its number, the others are numbered after the old.
  const size_t old_count = static_cast<size_t>(m.node_count);
  std::vector<int> number(static_cast<size_t>(count), -1), source;
  std::vector<char> kept(old_count, 0);
  std::vector<int> gp_node(m.gp_node.size());
  for (size_t gp = 0; gp < gp_node.size(); ++gp) {
    int& id = number[static_cast<size_t>(fresh[gp])];
    if (id < 0) {
      const int old = m.gp_node[gp];
      if (!kept[static_cast<size_t>(old)]) {
        kept[static_cast<size_t>(old)] = 1;
        id = old;
      } else {
        id = static_cast<int>(old_count + source.size());
        source.push_back(old);
      }
    }
    gp_node[gp] = id;
  }
  if (source.empty()) return;
  // A new node starts where its old node was, moving with it, and takes over the old node's
  // contacts on the faces it touches that the old node no longer does (find_contacts).
  for (size_t i = 0; i < source.size(); ++i) {
    m.contacts.split_from.push_back(static_cast<int>(old_count + i));
    m.contacts.split_from.push_back(source[i]);
  }
  for (const int old : source) {
    const size_t o = static_cast<size_t>(old);
    for (std::vector<double>* v : {&m.position, &m.u, &m.v, &m.origin, &m.force, &m.load}) {
      v->push_back((*v)[2 * o]);
      v->push_back((*v)[2 * o + 1]);
    }
    m.fix.push_back(m.fix[o]);
    m.node_block.push_back(m.node_block[o]);
  }
  for (size_t gp = 0; gp < gp_node.size(); ++gp)
    if (gp_node[gp] >= static_cast<int>(old_count)) m.node_block[static_cast<size_t>(gp_node[gp])] = mesh.gp_block[gp];
  m.gp_node = std::move(gp_node);
  m.node_count = static_cast<int>(old_count + source.size());
  // Outer boundary segments keep their loads, now on the nodes of their own side.
  std::vector<BoundarySegment> boundary = outer_boundary(mesh, m.gp_node);
  for (size_t i = 0; i < boundary.size(); ++i) {
    boundary[i].loaded = m.boundary[i].loaded;
    boundary[i].at_a = m.boundary[i].at_a;
    boundary[i].at_b = m.boundary[i].at_b;
  }
  m.boundary = std::move(boundary);
  lump_boundary_loads(m);
  m.faces = contact_boundary(mesh, m.edge_glued, m.gp_node, m.position);
  for (int z = 0; z < mesh.zone_count(); ++z) m.geometry[static_cast<size_t>(z)] = zone_geometry(m, mesh, z);
  m.contacts.detected = false;
  m.keep_fits = true;
  m.dirty = true;
}

void split_among_threads(Mechanics& m) {
  Partition part = make_partition(m, thread_count(m));
  // Split among as many threads as before, the contacts and nodes keep the cuts the threads'
  // times moved them to (load_balance.hpp).
  if (part.threads == m.partition.threads) {
    part.contact_cut = std::move(m.partition.contact_cut);
    part.node_cut = std::move(m.partition.node_cut);
  }
  m.partition = std::move(part);
  m.acc_force.assign(2 * static_cast<size_t>(m.partition.accumulators), 0.0);
}

void prepare(Mechanics& m, const Mesh& mesh) {
  if (!m.dirty) {
    // Only the thread count may have changed (set_threads, a restored checkpoint): the split
    // follows it, nothing else does, so the bits stay those of any thread count.
    if (m.partition.threads != thread_count(m)) split_among_threads(m);
    return;
  }
  if (mesh.zone_count() == 0) fail("the model has no zones: zone{{...}} the blocks first");

  m.active.clear();
  for (int z = 0; z < mesh.zone_count(); ++z) {
    const int material = m.zone_material[static_cast<size_t>(z)];
    if (material < 0) {
      const Vec2 c = mesh.zone_centroid(z);
      fail("zone {} at ({:.6g}, {:.6g}) has no material: assign{{ material = ... }} first", z + 1,
           c.x, c.y);
    }
    const bool void_zone = zone_law(m.params[static_cast<size_t>(material)].model).is_void;
    if (void_zone || m.zone_excavated[static_cast<size_t>(z)] > 0) continue;
    m.active.push_back(z);
  }

  m.block_live.assign(mesh.block_boundary.size(), 0);
  for (const int z : m.active) m.block_live[static_cast<size_t>(mesh.zone_block[static_cast<size_t>(z)])] = 1;
  if (!m.keep_fits) fit_sections(m, mesh);  // before the joint materials: cracks take `after`
  m.keep_fits = false;
  assign_joint_materials(m);
  m.contacts.detected = false;  // materials or zones may have changed
  tie_bolts(m);

  const size_t nodes = static_cast<size_t>(m.node_count);
  std::vector<double> rows(2 * nodes, 0.0);
  m.real_mass.assign(nodes, 0.0);
  m.weight.assign(2 * nodes, 0.0);
  for (const int z : m.active) {
    const ZoneGeometry& g = m.geometry[static_cast<size_t>(z)];
    const MaterialParams& p = m.params[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])];
    add_row_sums(g, p, m.fix, rows);
    for (const int node : g.node) {
      const size_t n = static_cast<size_t>(node);
      m.real_mass[n] += p.density * g.area / 3.0;
      m.weight[2 * n] += p.density * g.area / 3.0 * m.gravity.x;
      m.weight[2 * n + 1] += p.density * g.area / 3.0 * m.gravity.y;
    }
  }
  m.zone_rows.assign(nodes, 0.0);
  for (size_t n = 0; n < nodes; ++n) m.zone_rows[n] = std::max(rows[2 * n], rows[2 * n + 1]);
  if (m.settings.mode == SolverMode::dynamic) {
    for (const int z : m.active) {
      const auto& p = m.params[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])];
      if (!(p.density > 0.0))
        fail("dynamic mode needs a density > 0 in every material; material '{}' has {}",
             m.materials[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])].name,
             p.density);
    }
  }
  update_masses(m);

  m.applied_magnitude = 0.0;
  for (size_t n = 0; n < nodes; ++n)
    m.applied_magnitude += std::hypot(m.weight[2 * n], m.weight[2 * n + 1]) +
                           std::hypot(m.load[2 * n], m.load[2 * n + 1]);

  m.mates.clear();
  if (m.settings.mixed) m.mates = group_zones(m.geometry, m.active, m.position);
  split_among_threads(m);  // once the active zones are known
  m.info.step = m.step;
  m.dirty = false;
  m.restart_damping = true;
}

}  // namespace edem
