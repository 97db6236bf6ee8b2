// The cycle (run_cycles): its stages run in this order every cycle, inside one parallel region,
// each over flat arrays split among the threads:
//   1. zones: strain rate, constitutive update, nodal forces to the accumulators (zone_force_pass);
//      contacts: forces from the joint law, pushed to the gridpoint and its edge's ends
//      (contact_pass);
//   2. on one thread, the excavation's release takes its step off the loads (step_release) and
//      the bolts move their own nodes (bolt_cycle);
//   3. nodes: forces gathered, damping, velocity and displacement (node_motion).
// A barrier ends stages 2 and 3. The last cycle of a batch also measures (Measure); the energy
// sums run every cycle. Sums are taken per chunk and added in chunk order: the same bits for any
// thread count.
//
// Mixed discretisation (set{ mixed = true }), FLAC's for its quadrilaterals made of triangles:
// zones are grouped in pairs that share an edge (a left-over zone joins a neighbouring pair;
// solver/zone_groups.cpp), each member's volumetric strain rate is replaced by the group's
// area-weighted mean, the difference added as an isotropic strain, a third on each axis, the
// out-of-plane one included (B-bar in plane strain), and each member's forces see the group's
// mean stress change since the last insitu{} in place of its own, so the stress does work on
// exactly the strain that produced it and an initial state in equilibrium stays in equilibrium.
// One volumetric constraint per pair instead of per zone: about one per node, as Q1P0. It lifts
// the plain triangles' volumetric lock (prandtl_footing.lua, incompressible_hole.lua in
// tests/verification), and is not the default because non-associated perfect plasticity
// (psi < phi) admits shear bands: the less locked the zones, the more freely they form, and the
// wall of Salencon's hole (salencon.lua) moves further from the closed form than with plain
// triangles, which stay nearer to it.
#include "solver/cycle.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "bolt/bolt_coupling.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/zone_law.hpp"
#include "contact/contact_force.hpp"
#include "contact/detect.hpp"
#include "solver/excavation.hpp"
#include "solver/load_balance.hpp"

namespace edem {
namespace {

// Work on a chunk of nodes summed every step [J/m]: the contacts' and the bolts' forces, the
// supports of moving held gridpoints, and the damping's (the force's work less the kinetic
// energy it gave). Weight and boundary loads are constant over a batch: their work is taken from
// the batch's displacement (external_work).
struct NodeWork {
  double contacts = 0.0, bolts = 0.0, supports = 0.0, damping = 0.0;
  NodeWork& operator+=(const NodeWork& o) {
    contacts += o.contacts, bolts += o.bolts, supports += o.supports, damping += o.damping;
    return *this;
  }
};

// Sums per chunk of zones (kChunk of them), contacts or nodes (kSplitChunk), added in chunk order
// so that the totals are the same bits for any thread count and any split. The energy sums run
// over every cycle of a batch, the others over its last (measuring) cycle.
struct Partials {
  std::vector<double> zone_applied;  // per zone chunk
  std::vector<int> zone_inverted;
  std::vector<double> plastic;       // per zone chunk [J/m]
  std::vector<double> contact_applied;  // per contact chunk
  std::vector<int> contact_overlapping;   // per contact chunk: its first contact past the limit
  std::vector<double> contact_depth;      // and how deep its gridpoint is in the block [m]
  std::vector<ContactLoss> contact_loss;  // per contact chunk [J/m]
  std::vector<double> unbalanced, kinetic, num, den, speed;  // per node chunk
  std::vector<int> fastest;
  std::vector<char> finite;
  std::vector<NodeWork> work;  // per node chunk [J/m]
};

// Constitutive update of mesh zone z over one step; `iso` is the isotropic strain rate the
// mixed discretisation adds, on all three axes (kIso false: none, and no flops spent on it;
// with them the plain cycle was 10 % slower). Any other law through its kernel
// (constitutive/zone_law.hpp). Returns the zone's plastic work of the step [J/m]: summed in a
// register by the caller, not in memory, so that yielding zones do not wait on one another.
template <bool kIso>
[[gnu::always_inline]] inline double update_zone(Mechanics& m, size_t z, const ZoneStrain& r, double iso, double dt) {
  const MaterialParams& p = m.params[static_cast<size_t>(m.zone_material[z])];
  Stress& s = m.stress[z];
  const double dxx = (kIso ? r.xx + iso : r.xx) * dt, dyy = (kIso ? r.yy + iso : r.yy) * dt;
  const double dzz = kIso ? iso * dt : 0.0;
  if (p.model == MaterialModel::elastic) {  // the registry's law 0, inlined
    if constexpr (kIso)
      elastic_update(p, s, dxx, dyy, r.xy * dt, dzz);
    else
      elastic_update(p, s, dxx, dyy, r.xy * dt);
    return 0.0;
  }
  double work = 0.0;  // [J/m^3]
  const std::uint8_t now = zone_law(p.model).update(p, s, dxx, dyy, r.xy * dt, dzz, m.zone_history[z], &work);
  m.zone_state[z] = static_cast<std::uint8_t>((m.zone_state[z] & (kShearPast | kTensionPast)) | now | (now << 2));
  m.zone_plastic_work[z] += work;
  return m.geometry[z].area * work;
}

// The forces a zone's stress `s` puts on its three corners, its in-plane normal stresses shifted
// by `shift`: the cycle's and measure_state's.
struct CornerForces {
  double fx[3], fy[3];
};
[[gnu::always_inline]] inline CornerForces corner_forces(const ZoneGeometry& g, const Stress& s, double shift) {
  const double a = g.area, sxx = s.xx + shift, syy = s.yy + shift;
  CornerForces f;
  for (int i = 0; i < 3; ++i) {
    f.fx[i] = -a * (sxx * g.b[i] + s.xy * g.c[i]);
    f.fy[i] = -a * (s.xy * g.b[i] + syy * g.c[i]);
  }
  return f;
}

// Nodal forces of one zone from the stress `s`, its in-plane normal stresses shifted by `shift`.
// Inlined into the zone pass: called out of line it costs the hot loop a tenth of its time.
template <bool kMeasure>
[[gnu::always_inline]] inline double add_zone_forces(Mechanics& m, const ZoneGeometry& g, const std::array<int, 3>& dest,
                       const Stress& s, double shift) {
  double* acc = m.acc_force.data();
  const CornerForces f = corner_forces(g, s, shift);
  double applied = 0.0;
  for (int i = 0; i < 3; ++i) {
    const size_t d = static_cast<size_t>(dest[static_cast<size_t>(i)]);
    acc[2 * d] += f.fx[i];
    acc[2 * d + 1] += f.fy[i];
    if constexpr (kMeasure) applied += std::sqrt(f.fx[i] * f.fx[i] + f.fy[i] * f.fy[i]);
  }
  return applied;
}

// What a contact adds to the applied force the ratio is measured against: its force on both sides.
inline double contact_applied(const Contact& c) { return 2.0 * std::sqrt(c.fx * c.fx + c.fy * c.fy); }

bool inverted(const Mechanics& m, const ZoneGeometry& g) {
  double x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
    x[i] = m.origin[2 * n] + m.u[2 * n];
    y[i] = m.origin[2 * n + 1] + m.u[2 * n + 1];
  }
  return (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]) <= 0.0;
}

// Area-weighted mean over a group (active positions) of each member's mean stress change since
// the last insitu{}: what the forces of every member see in place of its own.
double group_mean_stress_change(const Mechanics& m, const int* members, int count) {
  double area = 0.0, sum = 0.0;
  for (int i = 0; i < count; ++i) {
    const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(members[i])]);
    const double a = m.geometry[z].area;
    area += a;
    sum += a * (mean_stress(m.stress[z]) - m.mean_stress_ref[z]);
  }
  return sum / area;
}

// What a group member's in-plane normal stresses are shifted by in its forces: its own mean
// stress change replaced by the group's.
double member_shift(const Mechanics& m, size_t z, double group_change) {
  return group_change - (mean_stress(m.stress[z]) - m.mean_stress_ref[z]);
}

// Strain rate, constitutive update and nodal forces of every zone; a group of the mixed
// discretisation is done whole by the thread of its first member, so that no other thread
// needs its members' rates or stresses. `begin` starts a chunk.
template <bool kMeasure, bool kGrouped>
void zone_force_pass(Mechanics& m, int begin, int end, Partials& partials) {
  const double* v = m.v.data();
  const double dt = m.step;
  for (int first = begin; first < end; first += kChunk) {
    const int last = std::min(end, first + kChunk);
    double applied = 0.0;
    double plastic = 0.0;
    int inverted_zone = -1;
    for (int k = first; k < last; ++k) {
      const std::array<int, 2> others = kGrouped ? m.mates[static_cast<size_t>(k)] : std::array<int, 2>{-1, -1};
      if (others[0] < 0) {
        const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(k)]);
        const ZoneGeometry& g = m.geometry[z];
        const auto& dest = m.partition.dest[static_cast<size_t>(k)];
        const Stress& s = m.stress[z];
        plastic += update_zone<false>(m, z, zone_strain(v, g), 0.0, dt);
        const double f = add_zone_forces<kMeasure>(m, g, dest, s, 0.0);
        if constexpr (kMeasure) {
          applied += f;
          if (inverted_zone < 0 && inverted(m, g)) inverted_zone = static_cast<int>(z);
        }
      } else if (others[0] > k && (others[1] < 0 || others[1] > k)) {
        const int members[3] = {k, others[0], others[1]};
        const int count = others[1] < 0 ? 2 : 3;
        ZoneStrain rate[3];
        double area = 0.0, volume = 0.0;
        for (int i = 0; i < count; ++i) {
          const ZoneGeometry& g = m.geometry[static_cast<size_t>(m.active[static_cast<size_t>(members[i])])];
          rate[i] = zone_strain(v, g);
          area += g.area;
          volume += g.area * (rate[i].xx + rate[i].yy);
        }
        // The group's volumetric strain rate replaces each member's own as an isotropic strain,
        // a third on each axis, the out-of-plane one included (B-bar in plane strain).
        const double mean_rate = volume / area;
        for (int i = 0; i < count; ++i) {
          const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(members[i])]);
          plastic += update_zone<true>(m, z, rate[i], (mean_rate - (rate[i].xx + rate[i].yy)) * (1.0 / 3.0), dt);
        }
        const double group_change = group_mean_stress_change(m, members, count);
        for (int i = 0; i < count; ++i) {
          const size_t z = static_cast<size_t>(m.active[static_cast<size_t>(members[i])]);
          const ZoneGeometry& g = m.geometry[z];
          const double f = add_zone_forces<kMeasure>(m, g, m.partition.dest[static_cast<size_t>(members[i])], m.stress[z],
                                                     member_shift(m, z, group_change));
          if constexpr (kMeasure) {
            applied += f;
            if (inverted_zone < 0 && inverted(m, g)) inverted_zone = static_cast<int>(z);
          }
        }
      }
    }
    const size_t chunk = static_cast<size_t>(first / kChunk);
    partials.plastic[chunk] += plastic;
    if constexpr (kMeasure) {
      partials.zone_applied[chunk] = applied;
      partials.zone_inverted[chunk] = inverted_zone;
    }
  }
}

// Books one contact's step into its own balance (ContactBook, energy{ by_contact = true }): its
// stored energy's change from `before`, what it dissipated (`lost` less `lost_before`), and the work
// of its force on its nodes over the step the nodes last moved (velocities v), half at last cycle's
// force and half at this one's: over a run, the balance's F(n) . (u(n+1) - u(n-1)) / 2.
void book_contact(const Mechanics& m, const Contact& c, const JointParams& p, double before,
                  const ContactLoss& lost_before, const ContactLoss& lost, const double* push, ContactBook& book) {
  const ContactEdge& e = m.faces.edges[static_cast<size_t>(c.edge)];
  double work = half_step_work(book, m.v.data(), m.step);  // last cycle's force
  for (int k = 0; k < 2 * kContactRoles; ++k) book.push[k] = push[k];
  book.nodes[0] = c.node, book.nodes[1] = e.a, book.nodes[2] = e.b;
  book.nodes[3] = c.far_a, book.nodes[4] = c.far_b;
  work += half_step_work(book, m.v.data(), m.step);  // this one's
  book.made += stored_in(c, p) - before + (lost.slip - lost_before.slip) + (lost.bond - lost_before.bond) -
               (lost.given - lost_before.given) + work;
}

// Forces of contacts [begin, end), `begin` starting a chunk; the nodes gather them in their own
// pass.
template <bool kMeasure>
void contact_pass(Mechanics& m, int begin, int end, Partials& partials) {
  Contact* list = m.contacts.list.data();
  double* push = m.contacts.push.data();
  const ContactEdge* edges = m.faces.edges.data();
  const JointParams* params = m.joint_params.data();
  const double limit = overlap_limit(m);
  const bool booking = m.energy.by_contact && m.contacts.books.size() == m.contacts.list.size();
  for (int first = begin; first < end; first += kSplitChunk) {
    const int last = std::min(end, first + kSplitChunk);
    double applied = 0.0;
    int overlapping = -1;
    double depth = 0.0;
    ContactLoss lost;
    for (int i = first; i < last; ++i) {
      Contact& c = list[i];
      const JointParams& p = params[c.material];
      const ContactLoss lost_before = lost;
      const double before = booking ? stored_in(c, p) : 0.0;
      NodePush extra;
      const double overlap = contact_force(c, edges, p, m.origin.data(), m.u.data(), m.v.data(), m.step, lost, &extra);
      double* pushed = push + 2 * kContactRoles * static_cast<size_t>(i);
      contact_push(c, extra, pushed);
      if (booking) [[unlikely]]
        book_contact(m, c, p, before, lost_before, lost, pushed, m.contacts.books[static_cast<size_t>(i)]);
      if constexpr (kMeasure) {
        applied += contact_applied(c);
        // Past the limit behind the edge's line, and in the block as far (not beside it).
        if (overlapping < 0 && overlap > limit) {
          const double in_block = depth_in_block(c, edges, m.origin.data(), m.u.data());
          if (in_block > limit) overlapping = i, depth = in_block;
        }
      }
    }
    const size_t chunk = static_cast<size_t>(first / kSplitChunk);
    partials.contact_loss[chunk].slip += lost.slip;
    partials.contact_loss[chunk].bond += lost.bond;
    partials.contact_loss[chunk].given += lost.given;
    if constexpr (kMeasure) {
      partials.contact_applied[chunk] = applied;
      partials.contact_overlapping[chunk] = overlapping;
      partials.contact_depth[chunk] = depth;
    }
  }
}

// Unbalanced force, damping and integration of nodes [begin, end), `begin` starting a chunk. The
// work of a force over the step is F . (v_old + v_new) / 2 dt, the distance the scheme moves the
// node by between the midpoints of the last step and this one; damping takes the difference of
// the force's impulse and the momentum it gave, at that speed. kDamped: the damping takes energy
// out; kCoupled: contacts or bolts act on the nodes (their forces' work is summed apart); kFreed:
// some bodies move undamped (Mechanics::undamped, solve{ balance }).
template <bool kMeasure, bool kDamped, bool kCoupled, bool kFreed>
void node_motion_pass(Mechanics& m, int begin, int end, const Motion& motion, bool record_start,
                      Partials& partials) {
  double* acc = m.acc_force.data();
  const int* first_slot = m.partition.gather_first.data();
  const int* gather = m.partition.gather.data();
  const bool with_contacts = !m.contacts.list.empty();
  const int* contact_first = m.contacts.gather_first.data();
  const int* contact_gather = m.contacts.gather.data();
  const double* push = m.contacts.push.data();
  const bool with_bolts = !m.bolt_hosts.gather.empty();
  const double half_dt = 0.5 * motion.dt;
  const char* undamped = m.undamped.data();
  for (int first = begin; first < end; first += kSplitChunk) {
    const int last = std::min(end, first + kSplitChunk);
    double unbalanced = 0.0, kinetic = 0.0, num = 0.0, den = 0.0, speed = -1.0;
    int fastest = -1;
    bool finite = true;
    NodeWork work;
    for (int n = first; n < last; ++n) {
      const size_t nn = static_cast<size_t>(n);
      double f[2];
      if (first_slot[n] == first_slot[n + 1]) {
        f[0] = acc[2 * nn];
        f[1] = acc[2 * nn + 1];
        acc[2 * nn] = 0.0;
        acc[2 * nn + 1] = 0.0;
      } else {
        f[0] = f[1] = 0.0;
        for (int s = first_slot[n]; s < first_slot[n + 1]; ++s) {
          const size_t d = static_cast<size_t>(gather[s]);
          f[0] += acc[2 * d];
          f[1] += acc[2 * d + 1];
          acc[2 * d] = 0.0;
          acc[2 * d + 1] = 0.0;
        }
      }
      // The contacts' and the bolts' shares, for the work each does.
      double fc[2] = {0.0, 0.0}, fb[2] = {0.0, 0.0};
      if constexpr (kCoupled) {
        const double own[2] = {f[0], f[1]};
        if (with_contacts) {
          for (int s = contact_first[n]; s < contact_first[n + 1]; ++s) {
            const double* p = push + 2 * static_cast<size_t>(contact_gather[s]);
            f[0] += p[0];
            f[1] += p[1];
          }
        }
        fc[0] = f[0] - own[0], fc[1] = f[1] - own[1];
        if (with_bolts) add_bolt_forces(m, nn, f);
        fb[0] = f[0] - own[0] - fc[0], fb[1] = f[1] - own[1] - fc[1];
      }
      const double mass = m.mass[nn];
      if (mass > 0.0) {
        const double inv_mass = 1.0 / mass;
        bool free = false;
        if constexpr (kFreed) free = undamped[n] != 0;
        for (int c = 0; c < 2; ++c) {
          const size_t dof = 2 * nn + static_cast<size_t>(c);
          const double force = f[c] + m.weight[dof] + m.load[dof];
          m.force[dof] = force;
          const bool held = (m.fix[nn] >> c) & 1;
          double& vel = m.v[dof];
          if (!held) {
            if (record_start) m.adaptive.r_start[dof] = force;
            const double before = vel;
            double impulse_lost;  // the force's impulse less the momentum it gave [N s/m]
            if (free) {
              vel += motion.dt * force * inv_mass;
              impulse_lost = 0.0;
            } else if (motion.local) {
              const double damped = force - motion.alpha * std::fabs(force) * (vel > 0.0 ? 1.0 : vel < 0.0 ? -1.0 : 0.0);
              vel += motion.dt * damped * inv_mass;
              impulse_lost = (force - damped) * motion.dt;
            } else {
              vel = motion.keep * vel + motion.push * force * inv_mass;
              impulse_lost = force * motion.dt - mass * (vel - before);
            }
            if constexpr (kDamped) work.damping += impulse_lost * (before + vel) * 0.5;
            if constexpr (kCoupled) {
              const double step = (before + vel) * half_dt;
              work.contacts += fc[c] * step;
              work.bolts += fb[c] * step;
            }
            if constexpr (kMeasure) {
              unbalanced += std::fabs(force);
              const double du = m.u[dof] - m.adaptive.u_start[dof];  // where `force` was found
              num += du * (m.adaptive.r_start[dof] - force);
              den += mass * du * du;
            }
          } else if (vel != 0.0) {  // moved as told: its support does the work the forces do not
            const double step = motion.dt * vel;
            work.supports -= force * step;
            work.contacts += fc[c] * step;
            work.bolts += fb[c] * step;
          }
          m.u[dof] += motion.dt * vel;
        }
      } else {
        // No stiffness to move against: held components still follow their velocity.
        for (int c = 0; c < 2; ++c) {
          const size_t dof = 2 * nn + static_cast<size_t>(c);
          const double force = f[c] + m.weight[dof] + m.load[dof];
          m.force[dof] = force;
          if (!((m.fix[nn] >> c) & 1)) continue;
          const double step = motion.dt * m.v[dof];
          m.u[dof] += step;
          work.supports -= force * step;
          work.contacts += fc[c] * step;
          work.bolts += fb[c] * step;
        }
      }
      if constexpr (kMeasure) {
        if (mass > 0.0) {
          const double v2 = m.v[2 * nn] * m.v[2 * nn] + m.v[2 * nn + 1] * m.v[2 * nn + 1];
          kinetic += 0.5 * mass * v2;
          if (!(std::isfinite(v2) && std::isfinite(f[0]) && std::isfinite(f[1]))) finite = false;
          if (v2 > speed) {
            speed = v2;
            fastest = n;
          }
        }
      }
    }
    const size_t chunk = static_cast<size_t>(first / kSplitChunk);
    partials.work[chunk] += work;
    if constexpr (kMeasure) {
      partials.unbalanced[chunk] = unbalanced;
      partials.kinetic[chunk] = kinetic;
      partials.num[chunk] = num;
      partials.den[chunk] = den;
      partials.speed[chunk] = speed;
      partials.fastest[chunk] = fastest;
      partials.finite[chunk] = finite;
    }
  }
}

// One node pass, its kind chosen once a pass.
void node_motion(Mechanics& m, int begin, int end, const Motion& motion, bool record_start, bool measure,
                 bool coupled, Partials& partials) {
  const bool freed = motion.damped && m.undamped.size() == static_cast<size_t>(m.node_count);
  const auto run = [&]<bool kMeasure, bool kDamped>() {
    if (coupled) {
      if (kDamped && freed)
        node_motion_pass<kMeasure, kDamped, true, true>(m, begin, end, motion, record_start, partials);
      else
        node_motion_pass<kMeasure, kDamped, true, false>(m, begin, end, motion, record_start, partials);
    } else {
      if (kDamped && freed)
        node_motion_pass<kMeasure, kDamped, false, true>(m, begin, end, motion, record_start, partials);
      else
        node_motion_pass<kMeasure, kDamped, false, false>(m, begin, end, motion, record_start, partials);
    }
  };
  if (measure)
    motion.damped ? run.template operator()<true, true>() : run.template operator()<true, false>();
  else
    motion.damped ? run.template operator()<false, true>() : run.template operator()<false, false>();
}

// Where a node was midway through the last step, u - v dt / 2 [m]: the node pass's work over a
// step, F . (v_old + v_new) dt / 2, is F times the change of this.
double midstep(const Mechanics& m, size_t dof) { return m.u[dof] - 0.5 * m.step * m.v[dof]; }

// The work of the weight and of the boundary's own loads (the loads less a release's share, which
// release_work counts) over a batch, from the nodes' midstep positions at its start, `start`:
// both are constant while it runs.
void external_work(Mechanics& m, const std::vector<double>& start) {
  double gravity = 0.0, boundary = 0.0;
  for (size_t dof = 0; dof < m.u.size(); ++dof) {
    const double du = midstep(m, dof) - start[dof];
    gravity += m.weight[dof] * du;
    boundary += m.load[dof] * du;
  }
  const ReleaseLoad& r = m.release;
  for (size_t i = 0; i < r.dof.size(); ++i) {
    const size_t dof = static_cast<size_t>(r.dof[i]);
    boundary -= r.factor * r.force[i] * (midstep(m, dof) - start[dof]);
  }
  m.energy.gravity += gravity;
  m.energy.boundary += boundary;
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
  motion.damped = motion.local || motion.keep != 1.0;
  return motion;
}

}  // namespace

Measure run_cycles(Mechanics& m, int count) {
  const Partition& part = m.partition;
  const int ranges = part.threads;
  const size_t zone_chunks = (m.active.size() + kChunk - 1) / kChunk;
  const size_t node_chunks = (static_cast<size_t>(m.node_count) + kSplitChunk - 1) / kSplitChunk;
  Partials partials;
  partials.zone_applied.assign(zone_chunks, 0.0);
  partials.zone_inverted.assign(zone_chunks, -1);
  partials.plastic.assign(zone_chunks, 0.0);
  partials.work.assign(node_chunks, NodeWork{});
  for (auto* sums : {&partials.unbalanced, &partials.kinetic, &partials.num, &partials.den})
    sums->assign(node_chunks, 0.0);
  partials.speed.assign(node_chunks, -1.0);
  partials.fastest.assign(node_chunks, -1);
  partials.finite.assign(node_chunks, 1);
  const int contact_count = static_cast<int>(m.contacts.list.size());
  m.contacts.push.resize(2 * kContactRoles * static_cast<size_t>(contact_count));
  const size_t contact_chunks = (static_cast<size_t>(contact_count) + kSplitChunk - 1) / kSplitChunk;
  partials.contact_applied.assign(contact_chunks, 0.0);
  partials.contact_overlapping.assign(contact_chunks, -1);
  partials.contact_depth.assign(contact_chunks, 0.0);
  partials.contact_loss.assign(contact_chunks, ContactLoss{});
  const std::vector<int> contact_begin = split_at(part.contact_cut, contact_count);
  const std::vector<int> node_begin = split_at(part.node_cut, m.node_count);
  if (m.adaptive.u_start.size() != m.u.size()) {
    m.adaptive.u_start = m.u;
    m.adaptive.r_start.assign(m.u.size(), 0.0);
    m.adaptive.have_r_start = false;
  }
  const Motion motion = motion_of(m);
  m.u_batch_start.resize(m.u.size());
  for (size_t dof = 0; dof < m.u.size(); ++dof) m.u_batch_start[dof] = midstep(m, dof);
  const bool record = !m.adaptive.have_r_start;
  const bool grouped = !m.mates.empty();
  const bool coupled = !m.contacts.list.empty() || !m.bolt_hosts.gather.empty();
  Measure bolt_measure;

  // Each thread's waits at the barriers, and when it finished (the rest of its wait is the join).
  std::vector<double> waited(static_cast<size_t>(ranges), 0.0), finished(static_cast<size_t>(ranges), 0.0);
  // Each thread's seconds of work before the first barrier and before the second.
  std::vector<double> forces_busy(static_cast<size_t>(ranges), 0.0), motion_busy(static_cast<size_t>(ranges), 0.0);
  int team_size = 1;
  const double region_start = omp_get_wtime();
#pragma omp parallel num_threads(ranges)
  {
    // Each thread takes the ranges t, t + team, ...; with a full team that is range t.
    const int team = omp_get_num_threads(), me = omp_get_thread_num();
    if (me == 0) team_size = team;
    double wait = 0.0, forces = 0.0, moves = 0.0;
    double phase_start = omp_get_wtime();
    // Waits for the team; adds the work since the last barrier to `busy`.
    const auto barrier = [&wait, &phase_start](double& busy) {
      const double arrived = omp_get_wtime();
      busy += arrived - phase_start;
#pragma omp barrier
      phase_start = omp_get_wtime();
      wait += phase_start - arrived;
    };
    for (int cycle = 0; cycle < count; ++cycle) {
      const bool measure = cycle == count - 1;
      for (int r = me; r < ranges; r += team) {
        const int b = part.zone_begin[static_cast<size_t>(r)], e = part.zone_begin[static_cast<size_t>(r) + 1];
        if (measure)
          grouped ? zone_force_pass<true, true>(m, b, e, partials) : zone_force_pass<true, false>(m, b, e, partials);
        else
          grouped ? zone_force_pass<false, true>(m, b, e, partials) : zone_force_pass<false, false>(m, b, e, partials);
        const int cb = contact_begin[static_cast<size_t>(r)], ce = contact_begin[static_cast<size_t>(r) + 1];
        if (cb < ce) measure ? contact_pass<true>(m, cb, ce, partials) : contact_pass<false>(m, cb, ce, partials);
      }
      // An excavation's loads come off a step every cycle; only the node pass below reads them.
      if (me == 0) step_release(m);
      // The bolts read the nodes' displacements, as the zones do, and move only their own nodes.
      if (me == 0) bolt_cycle(m, motion, record && cycle == 0, measure, bolt_measure);
      barrier(forces);
      for (int r = me; r < ranges; r += team) {
        const int b = node_begin[static_cast<size_t>(r)], e = node_begin[static_cast<size_t>(r) + 1];
        node_motion(m, b, e, motion, record && cycle == 0, measure, coupled, partials);
      }
      barrier(moves);
    }
    waited[static_cast<size_t>(me)] = wait;
    forces_busy[static_cast<size_t>(me)] = forces;
    motion_busy[static_cast<size_t>(me)] = moves;
    finished[static_cast<size_t>(me)] = omp_get_wtime();
  }
  const double region_end = omp_get_wtime();
  if (team_size == ranges) {  // thread t ran range t: its times are the range's
    rebalance(m.partition.contact_cut, forces_busy);
    rebalance(m.partition.node_cut, motion_busy);
  }
  m.adaptive.have_r_start = true;
  release_work(m);

  EnergyLedger& energy = m.energy;
  for (const double plastic : partials.plastic) energy.plastic += plastic;
  for (const ContactLoss& lost : partials.contact_loss) {
    energy.slip += lost.slip;
    energy.bond += lost.bond;
    energy.prestress += lost.given;
  }
  for (const NodeWork& work : partials.work) {
    energy.by_contacts += work.contacts;
    energy.by_bolts += work.bolts;
    energy.boundary += work.supports;
    energy.damping += work.damping;
  }
  external_work(m, m.u_batch_start);

  Measure out;
  out.applied = m.applied_magnitude;
  for (size_t c = 0; c < zone_chunks; ++c) {
    out.applied += partials.zone_applied[c];
    if (out.inverted_zone < 0) out.inverted_zone = partials.zone_inverted[c];
  }
  for (size_t c = 0; c < contact_chunks; ++c) {
    out.applied += partials.contact_applied[c];
    if (out.overlapping < 0 && partials.contact_overlapping[c] >= 0) {
      out.overlapping = partials.contact_overlapping[c];
      out.overlap = partials.contact_depth[c];
    }
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
  out.unbalanced += bolt_measure.unbalanced;
  out.applied += bolt_measure.applied;
  out.kinetic += bolt_measure.kinetic;
  out.rayleigh_num += bolt_measure.rayleigh_num;
  out.rayleigh_den += bolt_measure.rayleigh_den;
  out.finite = out.finite && bolt_measure.finite;
  if (!std::isfinite(out.unbalanced) || !std::isfinite(out.kinetic)) out.finite = false;
  out.team = team_size;
  out.wall = region_end - region_start;
  for (int t = 0; t < team_size; ++t)
    out.waited += waited[static_cast<size_t>(t)] + (region_end - finished[static_cast<size_t>(t)]);
  return out;
}

std::vector<double> standing_forces(const Mechanics& m, double* applied) {
  std::vector<double> f(m.u.size(), 0.0);
  double unused = 0.0;
  double& sum = applied != nullptr ? *applied : unused;
  // The grouped zones' forces see their group's mean stress change, as in the cycle.
  std::vector<double> shift(m.active.size(), 0.0);
  for (size_t k = 0; k < m.mates.size(); ++k) {
    const auto& others = m.mates[k];
    if (others[0] < 0) continue;
    const int members[3] = {static_cast<int>(k), others[0], others[1]};
    const size_t z = static_cast<size_t>(m.active[k]);
    shift[k] = member_shift(m, z, group_mean_stress_change(m, members, others[1] < 0 ? 2 : 3));
  }
  for (size_t k = 0; k < m.active.size(); ++k) {
    const size_t z = static_cast<size_t>(m.active[k]);
    const ZoneGeometry& g = m.geometry[z];
    const CornerForces zf = corner_forces(g, m.stress[z], shift[k]);
    for (size_t i = 0; i < 3; ++i) {
      const size_t n = static_cast<size_t>(g.node[i]);
      f[2 * n] += zf.fx[i];
      f[2 * n + 1] += zf.fy[i];
      sum += std::sqrt(zf.fx[i] * zf.fx[i] + zf.fy[i] * zf.fy[i]);
    }
  }
  // Contact forces at the current positions, without a step.
  for (const Contact& c : m.contacts.list) {
    Contact now = c;
    const ContactEdge& e = m.faces.edges[static_cast<size_t>(c.edge)];
    ContactLoss ignored;
    NodePush extra;
    contact_force(now, m.faces.edges.data(), m.joint_params[static_cast<size_t>(c.material)], m.origin.data(),
                  m.u.data(), m.v.data(), 0.0, ignored, &extra);
    double p[2 * kContactRoles];
    contact_push(now, extra, p);
    const int nodes[kContactRoles] = {c.node, e.a, e.b, c.far_a, c.far_b};
    for (int k = 0; k < kContactRoles; ++k) {
      if (nodes[k] < 0) continue;
      const size_t node = static_cast<size_t>(nodes[k]);
      f[2 * node] += p[2 * k];
      f[2 * node + 1] += p[2 * k + 1];
    }
    sum += contact_applied(now);
  }
  return f;
}

Measure measure_state(const Mechanics& m) {
  Measure out;
  out.applied = m.applied_magnitude;
  std::vector<double> f = standing_forces(m, &out.applied);
  // The bolts as their last cycle left them.
  if (!m.bolt_hosts.gather.empty())
    for (size_t n = 0; n < static_cast<size_t>(m.node_count); ++n) add_bolt_forces(m, n, &f[2 * n]);
  measure_bolts(m, out);
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
