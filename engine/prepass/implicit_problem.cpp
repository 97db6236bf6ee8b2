#include "prepass/implicit_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/zone_law.hpp"

namespace edem {
namespace {

// The displacement since the step's start, per node component.
std::vector<double> increment(const std::vector<double>& u, const std::vector<double>& u0) {
  std::vector<double> du(u.size());
  for (size_t i = 0; i < u.size(); ++i) du[i] = u[i] - u0[i];
  return du;
}

// The stress after a strain increment from `start`, and the state bits of that increment;
// `history` is the zone's law state at the start, which the prepass holds fixed (a softening law
// is perfectly plastic at its current strength within a prepass).
Stress stress_after(const MaterialParams& p, double history, const Stress& start, const ZoneStrain& e,
                    std::uint8_t* state) {
  Stress s = start;
  const ZoneLaw& law = zone_law(p.model);
  if (!law.update) {
    elastic_update(p, s, e.xx, e.yy, e.xy);
    if (state) *state = 0;
  } else {
    const std::uint8_t now = law.update(p, s, e.xx, e.yy, e.xy, 0.0, history, nullptr);
    if (state) *state = now;
  }
  return s;
}

using Matrix3 = std::array<std::array<double, 3>, 3>;

// d stress / d strain of the increment e from `start`: exact for elastic zones, central
// differences of the law's update for the others (a return mapping: piecewise smooth; the step
// is small against the strain that would cross a corner of the surface).
Matrix3 material_tangent(const MaterialParams& p, double history, const Stress& start, const ZoneStrain& e) {
  Matrix3 d{};
  if (!zone_law(p.model).update) {
    d[0] = {p.e1, p.e2, 0.0};
    d[1] = {p.e2, p.e1, 0.0};
    d[2] = {0.0, 0.0, p.shear};
    return d;
  }
  const double stress_scale = std::max({std::abs(start.xx), std::abs(start.yy), std::abs(start.xy),
                                        std::abs(start.zz), p.cohesion, 1.0});
  const double h = 1e-6 * (stress_scale / p.e1 + std::max({std::abs(e.xx), std::abs(e.yy), std::abs(e.xy)}));
  for (int k = 0; k < 3; ++k) {
    ZoneStrain plus = e, minus = e;
    double* pk = k == 0 ? &plus.xx : k == 1 ? &plus.yy : &plus.xy;
    double* mk = k == 0 ? &minus.xx : k == 1 ? &minus.yy : &minus.xy;
    *pk += h;
    *mk -= h;
    const Stress sp = stress_after(p, history, start, plus, nullptr),
                 sm = stress_after(p, history, start, minus, nullptr);
    d[0][static_cast<size_t>(k)] = (sp.xx - sm.xx) / (2.0 * h);
    d[1][static_cast<size_t>(k)] = (sp.yy - sm.yy) / (2.0 * h);
    d[2][static_cast<size_t>(k)] = (sp.xy - sm.xy) / (2.0 * h);
  }
  return d;
}

}  // namespace

ImplicitProblem make_problem(const Mechanics& m, const std::vector<int>& zones, const std::vector<Stress>& stress,
                             const std::vector<double>& u, const std::vector<int>& tie) {
  ImplicitProblem p;
  p.zones = zones;
  const size_t nodes = static_cast<size_t>(m.node_count), components = 2 * nodes;
  auto root = [&](size_t n) { return tie.empty() ? n : static_cast<size_t>(tie[n]); };
  std::vector<char> used(nodes, 0);
  std::vector<std::uint8_t> held(nodes, 0);
  for (int z : zones)
    for (int n : m.geometry[static_cast<size_t>(z)].node) used[root(static_cast<size_t>(n))] = 1;
  for (size_t n = 0; n < nodes; ++n) held[root(n)] |= m.fix[n];
  std::vector<int> unknown_of(components, -1);
  for (size_t n = 0; n < nodes; ++n) {
    if (!used[n]) continue;
    for (size_t axis = 0; axis < 2; ++axis)
      if (!(held[n] & (1u << axis))) unknown_of[2 * n + axis] = p.unknowns++;
  }
  p.free_of.assign(components, -1);
  for (size_t n = 0; n < nodes; ++n)
    for (size_t axis = 0; axis < 2; ++axis) p.free_of[2 * n + axis] = unknown_of[2 * root(n) + axis];
  p.applied.assign(components, 0.0);
  for (size_t i = 0; i < components; ++i)
    if (p.free_of[i] >= 0) p.applied[i] = m.weight[i] + m.load[i];
  p.stress0.reserve(zones.size());
  for (int z : zones) p.stress0.push_back(stress[static_cast<size_t>(z)]);
  p.stress = p.stress0;
  p.state.assign(zones.size(), 0);
  p.u0 = u;
  p.base = u;
  return p;
}

void add_interfaces(const Mechanics& m, ImplicitProblem& p, const std::vector<InterfacePair>& pairs,
                    const std::vector<InterfaceState>& state) {
  std::vector<char> used(static_cast<size_t>(m.node_count), 0);
  for (int z : p.zones)
    for (int n : m.geometry[static_cast<size_t>(z)].node) used[static_cast<size_t>(n)] = 1;
  for (size_t i = 0; i < pairs.size(); ++i) {
    if (!used[static_cast<size_t>(pairs[i].a)] || !used[static_cast<size_t>(pairs[i].b)]) continue;
    p.pairs.push_back(pairs[i]);
    p.pair_index.push_back(static_cast<int>(i));
    p.pair_state0.push_back(state[i]);
  }
  p.pair_state = p.pair_state0;
}

void commit_trial(ImplicitProblem& p, const std::vector<double>& u) {
  p.u0 = u;
  p.stress0 = p.stress;
  p.pair_state0 = p.pair_state;
}

void gather_unknowns(const ImplicitProblem& p, const std::vector<double>& u, double* unknowns) {
  for (size_t i = p.free_of.size(); i-- > 0;)  // backwards: the first component wins
    if (p.free_of[i] >= 0) unknowns[p.free_of[i]] = u[i] - p.base[i];
}

void scatter_unknowns(const ImplicitProblem& p, const double* unknowns, std::vector<double>& u) {
  for (size_t i = 0; i < p.free_of.size(); ++i)
    if (p.free_of[i] >= 0) u[i] = p.base[i] + unknowns[p.free_of[i]];
}

void sum_to_unknowns(const ImplicitProblem& p, const std::vector<double>& force, double* out) {
  std::fill(out, out + p.unknowns, 0.0);
  for (size_t i = 0; i < p.free_of.size(); ++i)
    if (p.free_of[i] >= 0) out[p.free_of[i]] += force[i];
}

void evaluate(const Mechanics& m, ImplicitProblem& p, const std::vector<double>& u, std::vector<double>& force) {
  force = p.applied;
  const std::vector<double> du = increment(u, p.u0);
  for (size_t k = 0; k < p.zones.size(); ++k) {
    const size_t z = static_cast<size_t>(p.zones[k]);
    const ZoneGeometry& g = m.geometry[z];
    const MaterialParams& params = m.params[static_cast<size_t>(m.zone_material[z])];
    const Stress s = stress_after(params, m.zone_history[z], p.stress0[k], zone_strain(du.data(), g), &p.state[k]);
    p.stress[k] = s;
    for (int i = 0; i < 3; ++i) {
      const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
      force[2 * n] -= g.area * (s.xx * g.b[i] + s.xy * g.c[i]);
      force[2 * n + 1] -= g.area * (s.xy * g.b[i] + s.yy * g.c[i]);
    }
  }
  for (size_t k = 0; k < p.pairs.size(); ++k) {
    const InterfacePair& pair = p.pairs[k];
    const size_t a = static_cast<size_t>(pair.a), b = static_cast<size_t>(pair.b);
    const Vec2 d = opening(pair, u);
    const InterfaceState& now = p.pair_state[k] =
        interface_trial(m.joint_params[static_cast<size_t>(pair.material)], pair, p.pair_state0[k], d);
    const Vec2 f = pair.length * (now.sn * pair.n + now.ss * along(pair.n));
    force[2 * a] += f.x;
    force[2 * a + 1] += f.y;
    force[2 * b] -= f.x;
    force[2 * b + 1] -= f.y;
  }
}

void tangent(const Mechanics& m, const ImplicitProblem& p, const std::vector<double>& u,
             std::vector<Eigen::Triplet<double, int>>& out) {
  out.clear();
  out.reserve(p.zones.size() * 36);
  const std::vector<double> du = increment(u, p.u0);
  for (size_t k = 0; k < p.zones.size(); ++k) {
    const size_t z = static_cast<size_t>(p.zones[k]);
    const ZoneGeometry& g = m.geometry[z];
    const MaterialParams& params = m.params[static_cast<size_t>(m.zone_material[z])];
    const Matrix3 d = material_tangent(params, m.zone_history[z], p.stress0[k], zone_strain(du.data(), g));
    // B: strain (xx, yy, xy) per corner displacement (x, y).
    double bm[3][6] = {};
    for (int i = 0; i < 3; ++i) {
      bm[0][2 * i] = g.b[i];
      bm[1][2 * i + 1] = g.c[i];
      bm[2][2 * i] = g.c[i];
      bm[2][2 * i + 1] = g.b[i];
    }
    double db[3][6];  // D B
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 6; ++c)
        db[r][c] = d[static_cast<size_t>(r)][0] * bm[0][c] + d[static_cast<size_t>(r)][1] * bm[1][c] +
                   d[static_cast<size_t>(r)][2] * bm[2][c];
    int dof[6];
    for (int i = 0; i < 3; ++i) {
      const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
      dof[2 * i] = p.free_of[2 * n];
      dof[2 * i + 1] = p.free_of[2 * n + 1];
    }
    for (int r = 0; r < 6; ++r) {
      if (dof[r] < 0) continue;
      for (int c = 0; c < 6; ++c) {
        if (dof[c] < 0) continue;
        const double k_rc = g.area * (bm[0][r] * db[0][c] + bm[1][r] * db[1][c] + bm[2][r] * db[2][c]);
        out.emplace_back(dof[r], dof[c], -k_rc);  // force = -A B^T stress
      }
    }
  }
  // Joint pairs: force on a = length x traction(u_b - u_a), on b its opposite.
  for (size_t k = 0; k < p.pairs.size(); ++k) {
    const InterfacePair& pair = p.pairs[k];
    const JointParams& params = m.joint_params[static_cast<size_t>(pair.material)];
    const Vec2 d = opening(pair, u);
    const auto t = interface_tangent(params, pair, interface_trial(params, pair, p.pair_state0[k], d));
    const int node[2] = {pair.a, pair.b};
    for (int i = 0; i < 2; ++i)      // force on node[i]
      for (int j = 0; j < 2; ++j) {  // by displacement of node[j]
        const double sign = (i == 0 ? 1.0 : -1.0) * (j == 1 ? 1.0 : -1.0);
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c) {
            const int row = p.free_of[2 * static_cast<size_t>(node[i]) + static_cast<size_t>(r)];
            const int col = p.free_of[2 * static_cast<size_t>(node[j]) + static_cast<size_t>(c)];
            if (row >= 0 && col >= 0) out.emplace_back(row, col, sign * pair.length * t[static_cast<size_t>(2 * r + c)]);
          }
      }
  }
}

}  // namespace edem
