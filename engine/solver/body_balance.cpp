#include "solver/body_balance.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "bolt/bolt_coupling.hpp"
#include "core/union_find.hpp"
#include "solver/cycle.hpp"
#include "state/mechanics.hpp"

namespace edem {

namespace {

// Each node's body (its root node) and each root's share of the forces on it unbalanced.
struct Bodies {
  std::vector<int> parent;
  std::vector<double> share;  // per root node
};

Bodies find_bodies(const Mechanics& m) {
  const size_t nodes = static_cast<size_t>(m.node_count);
  std::vector<int> parent(nodes);
  std::iota(parent.begin(), parent.end(), 0);
  for (const int z : m.active) {
    const auto& node = m.geometry[static_cast<size_t>(z)].node;
    const int root = find_root(parent, node[0]);
    for (size_t i = 1; i < 3; ++i) parent[static_cast<size_t>(find_root(parent, node[i]))] = root;
  }
  std::vector<double> f = standing_forces(m);
  // The bolts as their last cycle left them, on the nodes they were tied to then (nodes a crack
  // split off since have none until the bolts are tied again).
  if (!m.bolt_hosts.gather.empty())
    for (size_t n = 0; n + 1 < std::min(nodes + 1, m.bolt_hosts.gather_first.size()); ++n)
      add_bolt_forces(m, n, &f[2 * n]);
  std::vector<Vec2> net(nodes, Vec2{});
  std::vector<double> holding(nodes, 0.0);
  std::vector<char> moving(nodes, 0);  // bodies with a free component (not all held)
  for (size_t n = 0; n < nodes; ++n) {
    if (!(m.mass[n] > 0.0)) continue;
    const size_t root = static_cast<size_t>(find_root(parent, static_cast<int>(n)));
    for (size_t c = 0; c < 2; ++c) {
      const size_t dof = 2 * n + c;
      if ((m.fix[n] >> c) & 1) continue;
      (c == 0 ? net[root].x : net[root].y) += f[dof] + m.weight[dof] + m.load[dof];
      moving[root] = 1;
    }
    holding[root] += std::hypot(m.weight[2 * n], m.weight[2 * n + 1]) +
                     std::hypot(m.load[2 * n], m.load[2 * n + 1]);
  }
  // After a crack split nodes the contacts still name the faces before it until they are found
  // again (a solve stopped then): their indices are checked, not trusted.
  const auto in_range = [&](int node) { return node >= 0 && static_cast<size_t>(node) < nodes; };
  for (const Contact& c : m.contacts.list) {
    if (c.edge < 0 || static_cast<size_t>(c.edge) >= m.faces.edges.size()) continue;
    const double force = std::hypot(c.fx, c.fy);
    const int edge_node = m.faces.edges[static_cast<size_t>(c.edge)].a;
    for (const int node : {c.node, edge_node})
      if (in_range(node)) holding[static_cast<size_t>(find_root(parent, node))] += force;
  }
  std::vector<double> share(nodes, 0.0);
  for (size_t n = 0; n < nodes; ++n) {
    const bool root = static_cast<size_t>(find_root(parent, static_cast<int>(n))) == n;
    if (root && moving[n] && holding[n] > 0.0) share[n] = norm(net[n]) / holding[n];
  }
  return {std::move(parent), std::move(share)};
}

}  // namespace

BodyBalance worst_body_balance(const Mechanics& m) {
  const Bodies bodies = find_bodies(m);
  BodyBalance worst;
  for (size_t n = 0; n < bodies.share.size(); ++n) {
    if (bodies.share[n] > worst.share) {
      worst.share = bodies.share[n];
      worst.block = m.node_block[n];
      worst.at = {m.origin[2 * n] + m.u[2 * n], m.origin[2 * n + 1] + m.u[2 * n + 1]};
    }
  }
  return worst;
}

std::vector<double> body_share_by_node(const Mechanics& m) {
  Bodies bodies = find_bodies(m);
  std::vector<double> by_node(bodies.share.size(), 0.0);
  for (size_t n = 0; n < by_node.size(); ++n)
    by_node[n] = bodies.share[static_cast<size_t>(find_root(bodies.parent, static_cast<int>(n)))];
  return by_node;
}

}  // namespace edem
