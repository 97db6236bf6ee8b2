// The cycle, as passes over flat arrays inside one parallel region:
//   1. mixed zones: volumetric strain rate x area, to the node accumulators;
//   2. nodes: averaged volumetric strain rate;
//   3. zones: strain rate (averaged volumetric part in mixed zones), constitutive update, nodal
//      forces (mixed zones: area x mean stress change to the node accumulators instead);
//   4. nodes: averaged mean stress change;
//   5. mixed zones: nodal forces with the averaged mean stress change;
//   6. nodes: unbalanced force, damping, velocity and displacement.
// Passes 1, 2, 4 and 5 run only with set{ mixed = true }.
//
// Mixed discretisation (nodal mixed discretisation, as FLAC3D's for tetrahedra), with
// set{ mixed = true } only, in the Mohr-Coulomb zones. Each one's volumetric strain rate is
// replaced by the mean over its corners of the area-weighted nodal average over those zones,
// the difference added as an isotropic strain, a third on each axis, out of plane too
// (B-bar in plane strain). The forces see the same average of the mean stress change since the
// last insitu{}, so the stress does work on the strain that produced it and an initial state in
// equilibrium stays in equilibrium. With the zone's own mean stress in the forces instead (the
// first version), the plastic zones came out over-soft and went unstable with dilation.
// Measured:
//   near-incompressible elasticity (tests/verification/incompressible_hole.lua, nu = 0.499):
//     wall u 0.08 % off, ring-averaged stresses within 0.4 % of P0, against -3.1 % and up to
//     11 % with plain triangles (whose single zones are off by several P0: locking);
//   Salencon (the verification script with edge 0.03 a and set{ mixed = true }):
//   psi = 30: R0 +0.1 %, wall u +0.4 %, ring stresses <= 0.9 % of P0 (plain, edge 0.02 a: +0.3, +0.2);
//   psi = 0: R0 +29 %, wall u +72 %: the non-dilatant plastic zones find a soft
//     non-axisymmetric mode that keeps drifting, while plain triangles give +0.8 % and +1.5 %;
//     wall u against dilation: +29 % at psi = 1, +10 % at 5, +1.5 % at 15, +0.7 % at 25, so
//     the closer the plastic flow is to isochoric, the softer (in-plane-only averaging, which
//     keeps ezz = 0, is worse still: +234 % at psi = 0).
// So it stays off by default until the psi = 0 case is understood. Elastic zones stay plain
// triangles: rock is far from incompressible, and averaging next to boundaries costs accuracy.
#include "solver/cycle.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace edem {
namespace {

struct Partials {
  std::vector<double> zone_applied;  // per zone chunk
  std::vector<double> mixed_applied; // per zone chunk, the mixed zones' part
  std::vector<int> zone_inverted;
  std::vector<double> unbalanced, kinetic, num, den, speed;  // per node chunk
  std::vector<int> fastest;
  std::vector<char> finite;
};

void zone_volume_pass(Mechanics& m, int begin, int end) {
  const double* v = m.v.data();
  double* acc = m.acc_volume.data();
  for (int j = begin; j < end; ++j) {
    const int k = m.mixed[static_cast<size_t>(j)];
    const ZoneGeometry& g = m.geometry[static_cast<size_t>(m.active[static_cast<size_t>(k)])];
    double rate = 0.0;
    for (int i = 0; i < 3; ++i) {
      const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
      rate += g.b[i] * v[2 * n] + g.c[i] * v[2 * n + 1];
    }
    const double weighted = g.area * rate;
    const auto& dest = m.partition.dest[static_cast<size_t>(k)];
    acc[dest[0]] += weighted;
    acc[dest[1]] += weighted;
    acc[dest[2]] += weighted;
  }
}

// Area-weighted nodal average of what the zone passes left in acc_volume; clears them.
void node_average_pass(Mechanics& m, int begin, int end, double* out) {
  double* acc = m.acc_volume.data();
  const int* first = m.partition.gather_first.data();
  const int* gather = m.partition.gather.data();
  for (int n = begin; n < end; ++n) {
    double sum;
    if (first[n] == first[n + 1]) {
      sum = acc[n];
      acc[n] = 0.0;
    } else {
      sum = 0.0;
      for (int s = first[n]; s < first[n + 1]; ++s) {
        sum += acc[gather[s]];
        acc[gather[s]] = 0.0;
      }
    }
    out[n] = sum * m.inv_area[static_cast<size_t>(n)];
  }
}

// What a mixed zone's in-plane normal stresses are shifted by in its forces: its mean stress
// becomes the reference plus the average over its corners of the nodal mean stress change.
double mixed_shift(const Mechanics& m, size_t z, const double* node_pressure) {
  const auto& node = m.geometry[z].node;
  const double averaged = (node_pressure[node[0]] + node_pressure[node[1]] + node_pressure[node[2]]) * (1.0 / 3.0);
  return m.mean_stress_ref[z] + averaged - mean_stress(m.stress[z]);
}

// Nodal forces of one zone from the stress `s`, its in-plane normal stresses shifted by `shift`.
template <bool kMeasure>
double add_zone_forces(Mechanics& m, const ZoneGeometry& g, const std::array<int, 3>& dest,
                       const Stress& s, double shift) {
  double* acc = m.acc_force.data();
  const double a = g.area, sxx = s.xx + shift, syy = s.yy + shift;
  double applied = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double fx = -a * (sxx * g.b[i] + s.xy * g.c[i]);
    const double fy = -a * (s.xy * g.b[i] + syy * g.c[i]);
    const size_t d = static_cast<size_t>(dest[static_cast<size_t>(i)]);
    acc[2 * d] += fx;
    acc[2 * d + 1] += fy;
    if constexpr (kMeasure) applied += std::sqrt(fx * fx + fy * fy);
  }
  return applied;
}

bool inverted(const Mechanics& m, const ZoneGeometry& g) {
  double x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
    x[i] = m.position[2 * n] + m.u[2 * n];
    y[i] = m.position[2 * n + 1] + m.u[2 * n + 1];
  }
  return (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]) <= 0.0;
}

// Strain rate, constitutive update and nodal forces. A mixed zone's forces wait for the
// averaged mean stress (mixed_force_pass); it leaves area x its mean stress change instead.
template <bool kMeasure>
void zone_force_pass(Mechanics& m, int begin, int end, Partials& partials) {
  const double* v = m.v.data();
  const double* nv = m.node_volume.data();
  const bool mixed_on = !m.mixed.empty();
  const double dt = m.step;
  double applied = 0.0;
  int inverted_zone = -1;
  for (int k = begin; k < end; ++k) {
    const int z = m.active[static_cast<size_t>(k)];
    const ZoneGeometry& g = m.geometry[static_cast<size_t>(z)];
    const size_t n0 = static_cast<size_t>(g.node[0]), n1 = static_cast<size_t>(g.node[1]),
                 n2 = static_cast<size_t>(g.node[2]);
    const double vx0 = v[2 * n0], vy0 = v[2 * n0 + 1], vx1 = v[2 * n1], vy1 = v[2 * n1 + 1],
                 vx2 = v[2 * n2], vy2 = v[2 * n2 + 1];
    const double exx = g.b[0] * vx0 + g.b[1] * vx1 + g.b[2] * vx2;
    const double eyy = g.c[0] * vy0 + g.c[1] * vy1 + g.c[2] * vy2;
    const double gxy = g.c[0] * vx0 + g.c[1] * vx1 + g.c[2] * vx2 + g.b[0] * vy0 +
                       g.b[1] * vy1 + g.b[2] * vy2;
    const size_t zi = static_cast<size_t>(z);
    const MaterialParams& p = m.params[static_cast<size_t>(m.zone_material[zi])];
    Stress& s = m.stress[zi];
    const auto& dest = m.partition.dest[static_cast<size_t>(k)];
    if (p.model == MaterialModel::elastic || !mixed_on) {
      if (p.model == MaterialModel::elastic) {
        elastic_update(p, s, exx * dt, eyy * dt, gxy * dt);
      } else {
        const std::uint8_t now = mohr_coulomb_update(p, s, exx * dt, eyy * dt, gxy * dt, 0.0);
        m.zone_state[zi] = static_cast<std::uint8_t>((m.zone_state[zi] & (kShearPast | kTensionPast)) |
                                                     now | (now << 2));
      }
      const double f = add_zone_forces<kMeasure>(m, g, dest, s, 0.0);
      if constexpr (kMeasure) applied += f;
    } else {
      // The averaged volumetric rate replaces the zone's own as an isotropic strain, a third on
      // each axis, the out-of-plane one included (B-bar in plane strain).
      const double mixed = (nv[n0] + nv[n1] + nv[n2]) * (1.0 / 3.0);
      const double shift = (mixed - (exx + eyy)) * (1.0 / 3.0);
      const std::uint8_t now =
          mohr_coulomb_update(p, s, (exx + shift) * dt, (eyy + shift) * dt, gxy * dt, shift * dt);
      m.zone_state[zi] = static_cast<std::uint8_t>((m.zone_state[zi] & (kShearPast | kTensionPast)) |
                                                   now | (now << 2));
      const double weighted = g.area * (mean_stress(s) - m.mean_stress_ref[zi]);
      double* acc = m.acc_volume.data();
      acc[dest[0]] += weighted;
      acc[dest[1]] += weighted;
      acc[dest[2]] += weighted;
    }
    if constexpr (kMeasure) {
      if (inverted_zone < 0 && inverted(m, g)) inverted_zone = z;
      if ((k + 1) % kChunk == 0 || k + 1 == end) {
        partials.zone_applied[static_cast<size_t>(k / kChunk)] = applied;
        partials.zone_inverted[static_cast<size_t>(k / kChunk)] = inverted_zone;
        applied = 0.0;
        inverted_zone = -1;
      }
    }
  }
}

// Forces of the mixed zones: the mean stress change the force sees is the same average of the
// zones around as the volumetric strain rate the constitutive law saw, so the stress does work
// on exactly the strain that produced it (with own-zone mean stress here, the plastic zones
// gained energy from nowhere: over-soft and, with dilation, unstable).
template <bool kMeasure>
void mixed_force_pass(Mechanics& m, int begin, int end, Partials& partials) {
  const double* np = m.node_pressure.data();
  for (int j = begin; j < end; ++j) {
    const int k = m.mixed[static_cast<size_t>(j)];
    const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(k)]);
    const ZoneGeometry& g = m.geometry[z];
    const Stress& s = m.stress[z];
    const double shift = mixed_shift(m, z, np);
    const double f = add_zone_forces<kMeasure>(m, g, m.partition.dest[static_cast<size_t>(k)], s, shift);
    // Zone ranges are whole chunks, so each chunk's sum is one thread's, in zone order.
    if constexpr (kMeasure) partials.mixed_applied[static_cast<size_t>(k / kChunk)] += f;
  }
}

// Velocity update coefficients of one cycle.
struct Motion {
  double dt = 1.0;
  bool local = false;   // local damping
  double alpha = 0.0;   // its coefficient
  double keep = 1.0;    // viscous: v' = keep v + push F / m
  double push = 1.0;
};

template <bool kMeasure>
void node_motion_pass(Mechanics& m, int begin, int end, const Motion& motion, bool record_start,
                      Partials& partials) {
  double* acc = m.acc_force.data();
  const int* first = m.partition.gather_first.data();
  const int* gather = m.partition.gather.data();
  double unbalanced = 0.0, kinetic = 0.0, num = 0.0, den = 0.0, speed = -1.0;
  int fastest = -1;
  bool finite = true;
  for (int n = begin; n < end; ++n) {
    const size_t nn = static_cast<size_t>(n);
    double f[2];
    if (first[n] == first[n + 1]) {
      f[0] = acc[2 * nn];
      f[1] = acc[2 * nn + 1];
      acc[2 * nn] = 0.0;
      acc[2 * nn + 1] = 0.0;
    } else {
      f[0] = f[1] = 0.0;
      for (int s = first[n]; s < first[n + 1]; ++s) {
        const size_t d = static_cast<size_t>(gather[s]);
        f[0] += acc[2 * d];
        f[1] += acc[2 * d + 1];
        acc[2 * d] = 0.0;
        acc[2 * d + 1] = 0.0;
      }
    }
    const double mass = m.mass[nn];
    if (mass > 0.0) {
      const double inv_mass = 1.0 / mass;
      for (int c = 0; c < 2; ++c) {
        const size_t dof = 2 * nn + static_cast<size_t>(c);
        const double force = f[c] + m.weight[dof] + m.load[dof];
        m.force[dof] = force;
        const bool held = (m.fix[nn] >> c) & 1;
        if (!held) {
          if (record_start) m.adaptive.r_start[dof] = force;
          double& vel = m.v[dof];
          if (motion.local) {
            const double damped = force - motion.alpha * std::fabs(force) * (vel > 0.0 ? 1.0 : vel < 0.0 ? -1.0 : 0.0);
            vel += motion.dt * damped * inv_mass;
          } else {
            vel = motion.keep * vel + motion.push * force * inv_mass;
          }
          if constexpr (kMeasure) {
            unbalanced += std::fabs(force);
            const double du = m.u[dof] - m.adaptive.u_start[dof];  // where `force` was found
            num += du * (m.adaptive.r_start[dof] - force);
            den += mass * du * du;
          }
        }
        m.u[dof] += motion.dt * m.v[dof];
      }
    } else {
      // No stiffness to move against: held components still follow their velocity.
      for (int c = 0; c < 2; ++c) {
        const size_t dof = 2 * nn + static_cast<size_t>(c);
        m.force[dof] = f[c] + m.weight[dof] + m.load[dof];
        if ((m.fix[nn] >> c) & 1) m.u[dof] += motion.dt * m.v[dof];
      }
    }
    if (mass > 0.0) {
      if constexpr (kMeasure) {
        const double v2 = m.v[2 * nn] * m.v[2 * nn] + m.v[2 * nn + 1] * m.v[2 * nn + 1];
        kinetic += 0.5 * mass * v2;
        if (!(std::isfinite(v2) && std::isfinite(f[0]) && std::isfinite(f[1]))) finite = false;
        if (v2 > speed) {
          speed = v2;
          fastest = n;
        }
      }
    }
    if constexpr (kMeasure) {
      if ((n + 1) % kChunk == 0 || n + 1 == end) {
        const size_t chunk = static_cast<size_t>(n / kChunk);
        partials.unbalanced[chunk] = unbalanced;
        partials.kinetic[chunk] = kinetic;
        partials.num[chunk] = num;
        partials.den[chunk] = den;
        partials.speed[chunk] = speed;
        partials.fastest[chunk] = fastest;
        partials.finite[chunk] = finite;
        unbalanced = kinetic = num = den = 0.0;
        speed = -1.0;
        fastest = -1;
        finite = true;
      }
    }
  }
}

Motion motion_of(const Mechanics& m) {
  Motion motion;
  motion.dt = m.step;
  motion.push = m.step;
  const Damping damping = m.settings.damping;
  if (damping == Damping::local) {
    motion.local = true;
    motion.alpha = m.settings.local_damping;
  } else if (damping == Damping::adaptive) {
    const double c = m.adaptive.c * m.step;
    motion.keep = (2.0 - c) / (2.0 + c);
    motion.push = 2.0 * m.step / (2.0 + c);
  }
  return motion;
}

}  // namespace

Measure run_cycles(Mechanics& m, int count) {
  const Partition& part = m.partition;
  const int ranges = part.threads;
  const size_t zone_chunks = (m.active.size() + kChunk - 1) / kChunk;
  const size_t node_chunks = (static_cast<size_t>(m.node_count) + kChunk - 1) / kChunk;
  Partials partials;
  partials.zone_applied.assign(zone_chunks, 0.0);
  partials.mixed_applied.assign(zone_chunks, 0.0);
  partials.zone_inverted.assign(zone_chunks, -1);
  for (auto* sums : {&partials.unbalanced, &partials.kinetic, &partials.num, &partials.den})
    sums->assign(node_chunks, 0.0);
  partials.speed.assign(node_chunks, -1.0);
  partials.fastest.assign(node_chunks, -1);
  partials.finite.assign(node_chunks, 1);
  if (m.adaptive.u_start.size() != m.u.size()) {
    m.adaptive.u_start = m.u;
    m.adaptive.r_start.assign(m.u.size(), 0.0);
    m.adaptive.have_r_start = false;
  }
  const Motion motion = motion_of(m);
  const bool record = !m.adaptive.have_r_start;
  const bool any_mixed = !m.mixed.empty();

#pragma omp parallel num_threads(ranges)
  {
    // Each thread takes the ranges t, t + team, ...; with a full team that is range t.
    const int team = omp_get_num_threads(), me = omp_get_thread_num();
    for (int cycle = 0; cycle < count; ++cycle) {
      const bool measure = cycle == count - 1;
      if (any_mixed) {
        for (int r = me; r < ranges; r += team)
          zone_volume_pass(m, part.mixed_begin[static_cast<size_t>(r)], part.mixed_begin[static_cast<size_t>(r) + 1]);
#pragma omp barrier
        for (int r = me; r < ranges; r += team)
          node_average_pass(m, part.node_begin[static_cast<size_t>(r)], part.node_begin[static_cast<size_t>(r) + 1],
                            m.node_volume.data());
#pragma omp barrier
      }
      for (int r = me; r < ranges; r += team) {
        const int b = part.zone_begin[static_cast<size_t>(r)], e = part.zone_begin[static_cast<size_t>(r) + 1];
        if (measure)
          zone_force_pass<true>(m, b, e, partials);
        else
          zone_force_pass<false>(m, b, e, partials);
      }
#pragma omp barrier
      if (any_mixed) {
        for (int r = me; r < ranges; r += team)
          node_average_pass(m, part.node_begin[static_cast<size_t>(r)], part.node_begin[static_cast<size_t>(r) + 1],
                            m.node_pressure.data());
#pragma omp barrier
        for (int r = me; r < ranges; r += team) {
          const int b = part.mixed_begin[static_cast<size_t>(r)], e = part.mixed_begin[static_cast<size_t>(r) + 1];
          if (measure)
            mixed_force_pass<true>(m, b, e, partials);
          else
            mixed_force_pass<false>(m, b, e, partials);
        }
#pragma omp barrier
      }
      for (int r = me; r < ranges; r += team) {
        const int b = part.node_begin[static_cast<size_t>(r)], e = part.node_begin[static_cast<size_t>(r) + 1];
        const bool rec = record && cycle == 0;
        if (measure)
          node_motion_pass<true>(m, b, e, motion, rec, partials);
        else
          node_motion_pass<false>(m, b, e, motion, rec, partials);
      }
#pragma omp barrier
    }
  }
  m.adaptive.have_r_start = true;

  Measure out;
  out.applied = m.applied_magnitude;
  for (size_t c = 0; c < zone_chunks; ++c) {
    out.applied += partials.zone_applied[c] + partials.mixed_applied[c];
    if (out.inverted_zone < 0) out.inverted_zone = partials.zone_inverted[c];
  }
  double speed = -1.0;
  for (size_t c = 0; c < node_chunks; ++c) {
    out.unbalanced += partials.unbalanced[c];
    out.kinetic += partials.kinetic[c];
    out.rayleigh_num += partials.num[c];
    out.rayleigh_den += partials.den[c];
    out.finite = out.finite && partials.finite[c];
    if (partials.speed[c] > speed) {
      speed = partials.speed[c];
      out.fastest_node = partials.fastest[c];
    }
  }
  if (!std::isfinite(out.unbalanced) || !std::isfinite(out.kinetic)) out.finite = false;
  return out;
}

}  // namespace edem

namespace edem {

Measure measure_state(const Mechanics& m) {
  Measure out;
  std::vector<double> f(m.u.size(), 0.0);
  out.applied = m.applied_magnitude;
  // The mixed zones' forces see the averaged mean stress change, as in the cycle.
  std::vector<double> shift(m.active.size(), 0.0), node_pressure(static_cast<size_t>(m.node_count), 0.0);
  for (const int k : m.mixed) {
    const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(k)]);
    const ZoneGeometry& g = m.geometry[z];
    for (const int n : g.node)
      node_pressure[static_cast<size_t>(n)] += g.area * (mean_stress(m.stress[z]) - m.mean_stress_ref[z]);
  }
  for (size_t n = 0; n < node_pressure.size(); ++n) node_pressure[n] *= m.inv_area[n];
  for (const int k : m.mixed) {
    const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(k)]);
    shift[static_cast<size_t>(k)] = mixed_shift(m, z, node_pressure.data());
  }
  for (size_t k = 0; k < m.active.size(); ++k) {
    const int z = m.active[k];
    const ZoneGeometry& g = m.geometry[static_cast<size_t>(z)];
    const Stress& s = m.stress[static_cast<size_t>(z)];
    const double sxx = s.xx + shift[k], syy = s.yy + shift[k];
    for (int i = 0; i < 3; ++i) {
      const double fx = -g.area * (sxx * g.b[i] + s.xy * g.c[i]);
      const double fy = -g.area * (s.xy * g.b[i] + syy * g.c[i]);
      const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
      f[2 * n] += fx;
      f[2 * n + 1] += fy;
      out.applied += std::sqrt(fx * fx + fy * fy);
    }
  }
  for (size_t n = 0; n < static_cast<size_t>(m.node_count); ++n) {
    if (!(m.mass[n] > 0.0)) continue;
    for (size_t c = 0; c < 2; ++c)
      if (!((m.fix[n] >> c) & 1)) out.unbalanced += std::fabs(f[2 * n + c] + m.weight[2 * n + c] + m.load[2 * n + c]);
    out.kinetic += 0.5 * m.mass[n] * (m.v[2 * n] * m.v[2 * n] + m.v[2 * n + 1] * m.v[2 * n + 1]);
  }
  out.finite = std::isfinite(out.unbalanced) && std::isfinite(out.kinetic);
  return out;
}

}  // namespace edem
