// Cycling commands: batches of cycles between measurements, the watchdog, the adaptive
// damping, callbacks and histories.
#include "solver/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "contact/detect.hpp"
#include "contact/joint_law.hpp"
#include "crack/judge.hpp"
#include "bolt/bolt_coupling.hpp"
#include "solver/body_balance.hpp"
#include "solver/cycle.hpp"
#include "solver/energy.hpp"
#include "solver/excavation.hpp"
#include "solver/thread_watch.hpp"
#include "solver/prepare.hpp"

namespace edem {
namespace {

// The ratio and the watchdog look at the state every this many cycles (and at the end of
// every batch cut short by a callback or history).
constexpr int kMeasureInterval = 10;
// A solve with a stall limit counts a ratio as progress when it is below this share of the lowest
// one before it.
constexpr double kProgress = 0.9;
// Kinetic energy growing faster than this per cycle for kGrowthChecks checks in a row is an
// instability (a stable run from rest grows as t^2, far slower).
constexpr double kGrowthPerCycle = 1.585;  // 100x over 10 cycles
constexpr int kGrowthChecks = 3;
constexpr int kGrowthSpan = 10;  // cycles, at least, per check

// Clears Mechanics::cycling_now however cycling ends.
struct CyclingFlag {
  explicit CyclingFlag(bool& flag) : flag_(flag) { flag_ = true; }
  ~CyclingFlag() { flag_ = false; }
  CyclingFlag(const CyclingFlag&) = delete;
  CyclingFlag& operator=(const CyclingFlag&) = delete;
  bool& flag_;
};

Vec2 node_position(const Mechanics& m, int node) {
  return {m.position[2 * static_cast<size_t>(node)], m.position[2 * static_cast<size_t>(node) + 1]};
}

std::string likely_cause(const Mechanics& m) {
  if (m.settings.mode == SolverMode::dynamic && m.settings.step > 0.0 &&
      m.settings.step >= m.critical_step)
    return fmt::format(
        "likely cause: the forced time step {:.6g} s is above the critical step {:.6g} s of the "
        "stiffest gridpoint; leave set{{ step }} out to get the automatic step",
        m.settings.step, m.critical_step);
  return "likely cause: the time step is too large for the stiffest part of the model, or a "
         "material with an unphysical stiffness; check the materials and set{ step }";
}

// What the overlap watchdog found, measured: the contact, its stress and stiffness, its
// gridpoint's shortest edge and what made it, its speed; and the cause those point to.
std::string overlap_cause(const Mechanics& m, const Measure& measure) {
  const Contact& c = m.contacts.list[static_cast<size_t>(measure.overlapping)];
  const size_t n = static_cast<size_t>(c.node);
  const Vec2 p{m.origin[2 * n] + m.u[2 * n], m.origin[2 * n + 1] + m.u[2 * n + 1]};
  const JointParams& jp = m.joint_params[static_cast<size_t>(c.material)];
  // The closure its joint law gives at the contact's stress (the law's inverse: a nonlinear law
  // closes more than sigma_n / kn_max), and the overlap that is beyond its prestress.
  const double limit = overlap_limit(m), closes = c.sn > 0.0 ? closure_at(jp, c.sn) : 0.0;
  const double needs = closes - (c.closure0 + c.dilation);
  // The gridpoint's shortest touchable edge, and what made it.
  const ContactBoundary& cb = m.faces;
  const auto k = std::lower_bound(cb.nodes.begin(), cb.nodes.end(), c.node) - cb.nodes.begin();
  double shortest = INFINITY, half_edges = 0.0;
  std::string made_by;
  for (int i = cb.edge_first[static_cast<size_t>(k)]; i < cb.edge_first[static_cast<size_t>(k) + 1]; ++i) {
    const ContactEdge& e = cb.edges[static_cast<size_t>(cb.node_edges[static_cast<size_t>(i)])];
    const double length = std::hypot(m.position[2 * static_cast<size_t>(e.b)] - m.position[2 * static_cast<size_t>(e.a)],
                                     m.position[2 * static_cast<size_t>(e.b) + 1] - m.position[2 * static_cast<size_t>(e.a) + 1]);
    if (length < shortest) shortest = length, made_by = describe(e);
    half_edges += 0.5 * length;
  }
  const double carrying = carrying_length(c, last_overlap(c));
  const double moved = m.step * std::hypot(m.v[2 * n], m.v[2 * n + 1]);
  std::string cause;
  if (m.settings.mode == SolverMode::dynamic && m.settings.step > 0.0 && m.settings.step >= m.critical_step)
    cause = fmt::format("the forced time step {:.6g} s is {:.3g} times the critical step {:.6g} s of the "
                        "stiffest gridpoint: leave set{{ step }} out to get the automatic step",
                        m.settings.step, m.settings.step / m.critical_step, m.critical_step);
  else if (!(c.wedge > 0.0) && carrying < 0.01 * half_edges)
    // Its stress is that of its depth; what holds the gridpoint back is that stress times a length
    // next to nothing (a tip's length grows with its depth: not it).
    cause = fmt::format("the contact's force acts over {:.3g} m of the {:.3g} m its gridpoint's half-edges "
                        "give: they run into the face edge on instead of lying over it (a block landing on an "
                        "edge, or turned past a corner), so however great its stress it holds the gridpoint back "
                        "with next to no force",
                        carrying, half_edges);
  else if (needs > 0.5 * limit)
    cause = fmt::format("joint material '{}' is too soft for this stress: its law closes {:.3g} m at it, {:.3g} m "
                        "beyond its prestress, more than half the limit; give a larger set{{ overlap }}, or a "
                        "stiffer joint",
                        m.joint_materials[static_cast<size_t>(c.material)].name, closes, needs) +
            // The stress is the force over the length: a corner pressed in point first raises it.
            (carrying < 0.1 * half_edges
                 ? fmt::format(" (its force acts over {:.3g} m of the {:.3g} m its gridpoint's half-edges give: a "
                               "corner pressed in point first, which raises the stress)",
                               carrying, half_edges)
                 : std::string());
  else if (moved > 0.1 * limit)
    cause = fmt::format("driven in faster than the contact pushes back: the gridpoint moves {:.3g} m a step "
                        "(a boundary velocity or a time step too large)", moved);
  else if (shortest < 0.2 * cb.median_edge)
    cause = fmt::format("a sliver: the gridpoint's shortest edge, {:.3g} m, is under a fifth of the median "
                        "edge ({:.3g} m), and a tip that short is driven into the face", shortest, cb.median_edge);
  else
    cause = fmt::format("the contact carries only what its stress gives ({:.3g} m of overlap) yet is {:.3g} m in: "
                        "it was made late, or the gridpoint went past a corner it was not in contact with",
                        needs, measure.overlap);
  return fmt::format(
      "overlap too great: the gridpoint at ({:.6g}, {:.6g}) of block {} is {:.3g} m inside block {}, more than "
      "the limit of {:.3g} m (set{{ overlap }}); its contact carries {:.4g} Pa over {:.3g} m, {:.3g} of it over "
      "the edge, with joint material '{}' (kn up to {:.4g} Pa/m; its law closes {:.3g} m at that stress; prestress "
      "{:.3g} m); the gridpoint's shortest edge is {:.3g} m, {}; measured cause: {}",
      p.x, p.y, c.block + 1, measure.overlap, c.other + 1, limit, c.sn, carrying,
      c.share, m.joint_materials[static_cast<size_t>(c.material)].name, jp.kn_max, closes, c.closure0 + c.dilation,
      shortest, made_by, cause);
}

// Stops the run with a message if the measured state is unstable.
void watch(Mechanics& m, const Mesh& mesh, const Measure& measure, int batch) {
  const long cycle = m.info.cycle;
  auto where = [&](int node) {
    if (node < 0) return std::string();
    const Vec2 p = node_position(m, node);
    return fmt::format(" near ({:.6g}, {:.6g}) in block {}", p.x, p.y,
                       m.node_block[static_cast<size_t>(node)] + 1);
  };
  // Growth is judged over spans of at least kGrowthSpan cycles: a run measured every cycle
  // (a callback every cycle) grows from rest by ((n + 1) / n)^2 per cycle, fast for a few.
  m.growth_span += batch;
  double per_cycle = 0.0;
  if (m.growth_span >= kGrowthSpan) {
    per_cycle = m.last_kinetic > 0.0 ? std::pow(measure.kinetic / m.last_kinetic, 1.0 / m.growth_span) : 0.0;
    m.growth_checks = per_cycle > kGrowthPerCycle ? m.growth_checks + 1 : 0;
    m.last_kinetic = measure.kinetic;
    m.growth_span = 0;
  } else if (m.last_kinetic > 0.0) {
    per_cycle = std::pow(measure.kinetic / m.last_kinetic, 1.0 / m.growth_span);
  }
  if (measure.overlapping >= 0) fail("cycle {}: {}", cycle, overlap_cause(m, measure));
  std::string inverted;
  if (measure.inverted_zone >= 0) {
    const Vec2 c = mesh.zone_centroid(measure.inverted_zone);
    inverted = fmt::format("zone {} at ({:.6g}, {:.6g}) in block {} turned inside out (its "
                           "deformed area is not positive)",
                           measure.inverted_zone + 1, c.x, c.y,
                           mesh.zone_block[static_cast<size_t>(measure.inverted_zone)] + 1);
  }
  if (!measure.finite)
    fail("cycle {}: the run went unstable: forces or velocities are no longer finite{}; {}", cycle,
         where(measure.fastest_node), likely_cause(m));
  // Fast growth of the kinetic energy is the signature of a step above the stability limit;
  // an inverted zone while it grows is the same instability seen sooner.
  if (m.growth_checks >= kGrowthChecks || (m.growth_checks >= 1 && !inverted.empty()))
    fail("cycle {}: the run went unstable: kinetic energy grows without bound ({:.3g}x per "
         "cycle), fastest{}{}; {}",
         cycle, per_cycle, where(measure.fastest_node), inverted.empty() ? "" : "; " + inverted,
         likely_cause(m));
  if (!inverted.empty())
    fail("cycle {}: {}; likely cause: displacements larger than the zones, from an unsupported "
         "or too soft region or a load the material cannot carry; check boundary conditions "
         "and materials",
         cycle, inverted);
}

void adapt_damping(Mechanics& m, const Measure& measure) {
  if (!(measure.rayleigh_den > 0.0 && measure.rayleigh_num > 0.0)) return;
  const double omega2 = measure.rayleigh_num / measure.rayleigh_den;
  if (!std::isfinite(omega2)) return;
  m.adaptive.c = std::min(2.0 * std::sqrt(omega2), 2.0 / m.step);
}

// Some section is still intact.
bool any_intact(const Mechanics& m) {
  return static_cast<long>(m.cracks.size()) < static_cast<long>(m.sections.size());
}

// Judges the sections; those that broke release their ties: the nodes are reconnected.
int broken_and_reconnected(Mechanics& m, const Mesh& mesh) {
  const int broke = judge_sections(m);
  if (broke > 0) reconnect(m, mesh);
  return broke;
}

// Sections are judged every n cycles (judge{ at = "cycles" }) while any is intact.
bool judging(const Mechanics& m) { return m.judge.at == JudgeAt::cycles && any_intact(m); }

// With judge{ at = "equilibrium" }, at a state the solve has brought to its ratio: every intact
// section judged on it. True if the state stands (nothing broke, or judging is not on equilibrium).
bool stands_judged(Mechanics& m, const Mesh& mesh, SolveResult& result) {
  if (m.judge.at != JudgeAt::equilibrium || !any_intact(m)) return true;
  ++result.judgments;
  const int broke = broken_and_reconnected(m, mesh);
  result.broke += broke;
  return broke == 0;
}

// Lets the bodies more out of balance than `balance` move undamped (Mechanics::undamped), the
// rest damped as set. True if any is.
bool free_unbalanced_bodies(Mechanics& m, double balance) {
  const std::vector<double> share = body_share_by_node(m);
  m.undamped.assign(share.size(), 0);
  bool any = false;
  for (size_t n = 0; n < share.size(); ++n)
    if (share[n] > balance) m.undamped[n] = 1, any = true;
  if (!any) m.undamped.clear();
  return any;
}

// The bodies a solve let move undamped are damped again when it ends, however it ends.
struct UndampedCleared {
  explicit UndampedCleared(Mechanics& mechanics) : m(mechanics) { m.undamped.clear(); }
  ~UndampedCleared() { m.undamped.clear(); }
  UndampedCleared(const UndampedCleared&) = delete;
  UndampedCleared& operator=(const UndampedCleared&) = delete;
  Mechanics& m;
};

// A solve's state, not a cycle()'s (run with no ratio to reach).
void note_worst_body(const Mechanics& m, SolveResult& result) {
  const BodyBalance worst = worst_body_balance(m);
  result.body_share = worst.share;
  result.body_block = worst.block;
  result.body_at = worst.at;
}

long next_due(const Mechanics& m, long cycle) {
  long due = cycle + kMeasureInterval - cycle % kMeasureInterval;
  for (const Callback& c : m.callbacks) due = std::min(due, (cycle / c.every + 1) * c.every);
  for (const History& h : m.histories)
    if (h.ended.empty()) due = std::min(due, (cycle / h.every + 1) * h.every);
  if (judging(m)) due = std::min(due, (cycle / m.judge.every + 1) * m.judge.every);
  return due;
}

// Judgment first, so that histories and callbacks of this cycle see its cracks. Returns whether
// sections broke; `commands_pending` is set when callbacks ran (what they changed is booked as
// commands' once the model is prepared again).
bool run_due(Mechanics& m, const Mesh& mesh, long cycle, bool& commands_pending) {
  const bool broke = judging(m) && cycle % m.judge.every == 0 && broken_and_reconnected(m, mesh) > 0;
  for (History& h : m.histories)
    if (cycle % h.every == 0 && h.ended.empty()) {
      const double value = h.sample();
      h.cycles.push_back(cycle);
      h.values.push_back(value);
    }
  // Callbacks may add or cancel callbacks: walk the handles present now.
  std::vector<std::pair<int, long>> due;
  for (const Callback& c : m.callbacks)
    if (cycle % c.every == 0) due.push_back({c.handle, c.every});
  if (!due.empty() && !commands_pending) {
    m.energy.last = stored_energy(m);
    m.energy.last_current = true;
    commands_pending = true;
  }
  for (const auto& [handle, every] : due) {
    const auto it = std::find_if(m.callbacks.begin(), m.callbacks.end(),
                                 [&](const Callback& c) { return c.handle == handle; });
    if (it == m.callbacks.end()) continue;
    const auto fn = it->fn;  // a copy: the callback may cancel itself
    fn(cycle);
  }
  return broke;
}

void start_adaptive(Mechanics& m) {
  m.adaptive.u_start = m.u;
  m.adaptive.r_start.assign(m.u.size(), 0.0);
  m.adaptive.have_r_start = false;
  m.adaptive.c = 0.0;
  start_bolt_damping(m);
  m.last_kinetic = 0.0;
  m.growth_span = 0;
  m.growth_checks = 0;
  m.restart_damping = false;
}

// A restored checkpoint holds no Lua functions: those it had must be given again first.
void check_functions_given(const Mechanics& m) {
  for (const History& h : m.histories)
    if (!h.sample)
      fail("history '{}' was restored without its function: give history{{ name = \"{}\", fn = ... }} again "
           "after restore", h.name, h.name);
  if (m.judge_criterion_missing)
    fail("the restored judge{{}} had a criterion function: give judge{{ criterion = ... }} again after "
         "restore (or judge{{}} for the built-in criteria)");
}

// Masses and the time step again (contacts or bolts changed): in static mode the scaled masses
// change the kinetic energy, which goes with the damping's (the fictitious dynamics of static mode).
void update_masses_booked(Mechanics& m) {
  const bool scaled = m.settings.mode == SolverMode::static_;
  const double before = scaled ? kinetic_energy(m) : 0.0;
  update_masses(m);
  if (scaled) m.energy.damping += before - kinetic_energy(m);
}

// Whatever way cycling ends, the energy balance's last state is the state then (what callbacks
// changed since they ran booked as commands').
struct EnergyAtExit {
  EnergyAtExit(Mechanics& m, const bool& commands_pending) : m_(m), pending_(commands_pending) {}
  ~EnergyAtExit() {
    if (!m_.energy.started) return;
    if (pending_) {
      book_commands(m_);
    } else {
      m_.energy.last = stored_energy(m_);
      m_.energy.last_current = true;
    }
  }
  EnergyAtExit(const EnergyAtExit&) = delete;
  EnergyAtExit& operator=(const EnergyAtExit&) = delete;
  Mechanics& m_;
  const bool& pending_;
};

// Shrinks the team while its threads are not all running, grows it back when they are.
void follow_thread_watch(Mechanics& m, const Measure& batch, long cycles) {
  const TeamChange change = watch_team(m.thread_watch, batch.team, batch.wall, batch.waited, cycles, wanted_threads(m));
  if (change.changed) split_among_threads(m);
  if (!change.notice.empty() && m.notice) m.notice(change.notice);
}

// The damping a solve that settles (run_solver's `settle`) found set, given back at its end (a
// solve that does not settle leaves whatever a callback set).
struct DampingKept {
  Mechanics& m;
  Damping set;
  bool settles;
  DampingKept(Mechanics& mechanics, bool settling)
      : m(mechanics), set(mechanics.settings.damping), settles(settling) {}
  DampingKept(const DampingKept&) = delete;
  DampingKept& operator=(const DampingKept&) = delete;
  ~DampingKept() {
    if (!settles || m.settings.damping == set) return;
    m.settings.damping = set;
    m.dirty = true;  // masses scale with the damping (update_masses)
  }
};

}  // namespace

SolveResult run_solver(Mechanics& m, const Mesh& mesh, long max_cycles, double target_ratio, long stall,
                       double settle, double balance) {
  if (m.cycling_now) fail("cannot cycle from inside a callback or history while cycling");
  check_functions_given(m);
  prepare(m, mesh);  // a changed model; else the thread count may have changed
  if (m.restart_damping) start_adaptive(m);
  // The energy balance starts with the first cycle; after that, what commands changed is theirs.
  if (!m.energy.started)
    start_energy(m);
  else
    book_commands(m);
  bool commands_pending = false;
  EnergyAtExit energy_at_exit(m, commands_pending);
  if (refresh_contacts(m, 0.0)) update_masses_booked(m);
  // Past its critical step a bolt's segments chatter between their yield forces: bounded, so the
  // watchdog would not see it grow, and the answer would be garbage. Refused up front.
  if (m.settings.mode == SolverMode::dynamic && m.settings.step > 0.0 && m.settings.step >= m.bolt_hosts.critical_step)
    fail("the forced time step {:.6g} s is above the critical step {:.6g} s of the bolts' stiffest node: their "
         "segments would ring between their yield forces; leave set{{ step }} out to get the automatic step, or "
         "give the bolts longer segments",
         m.settings.step, m.bolt_hosts.critical_step);
  CyclingFlag flag(m.cycling_now);
  const bool reporting = m.progress && m.progress_every > 0.0;
  const auto started = std::chrono::steady_clock::now();
  auto reported = started;
  SolveResult result;
  // Local damping brings rock that can slide to an equilibrium safely, and on soft joints slowly:
  // there a ratio of 1e-5 leaves millimetres unsettled. With `settle` the state it reaches is
  // taken on under adaptive damping, which can settle the last decades far sooner, and only that
  // state counts.
  const DampingKept kept{m, settle > 0.0};
  double goal = target_ratio;  // the ratio the solve aims at now
  bool settling = false;
  // At `goal`: true if the solve is done; else it goes on to settle, or (sections broke) to the
  // next state under the set damping.
  const auto at_goal = [&] {
    if (settle > 0.0 && !settling) {
      settling = true;
      goal = settle;
      if (m.settings.damping != Damping::adaptive) {
        m.settings.damping = Damping::adaptive;
        m.dirty = true;  // prepared again: masses scale with the damping, and it starts afresh
      }
      return false;
    }
    if (stands_judged(m, mesh, result)) return true;
    if (settling) {
      settling = false;
      goal = target_ratio;
      m.dirty = m.dirty || m.settings.damping != kept.set;
      m.settings.damping = kept.set;
    }
    return false;
  };
  // With `balance`, a state at the ratio counts only once no body is further out of balance: the
  // ratio, a sum over the whole model, can hide a few blocks with no equilibrium. Those move
  // undamped until they are back within it: the damping is the method's, and holds such a block
  // creeping, as far as the cycles run, where it would slide or fall (a path the release and the
  // damping would then decide). Looked at again every measuring cycle while any moves so.
  const UndampedCleared undamped_cleared{m};
  bool freed = false;
  const auto balanced = [&] {
    if (balance <= 0.0) return true;
    freed = free_unbalanced_bodies(m, balance);
    return !freed;
  };
  if (target_ratio > 0.0 && m.release.dof.empty()) {
    const Measure now = measure_state(m);
    m.info.ratio = now.applied > 0.0 ? now.unbalanced / now.applied : 0.0;
    while (m.info.ratio <= goal && balanced()) {
      if (at_goal()) {
        result.ratio = m.info.ratio;
        result.converged = true;
        note_worst_body(m, result);
        return result;
      }
      if (!settling) break;  // sections broke: cycles must find the next state
    }
  }
  // Progress towards an equilibrium: the lowest ratio since the load came off or sections last
  // broke, and when it was reached. Rock that keeps sliding or creeping holds the ratio level (or
  // lets it rise) however long it runs: a solve with `stall` stops there instead of at max_cycles.
  double lowest = INFINITY;
  long lowest_at = 0;
  while (result.cycles < max_cycles) {
    if (m.stop != nullptr && m.stop->load(std::memory_order_relaxed) != 0) {
      result.interrupted = true;
      break;
    }
    if (m.dirty) {  // a callback or a judgment changed the model
      const double kinetic = kinetic_energy(m);
      prepare(m, mesh);
      if (!commands_pending) m.energy.damping += kinetic - kinetic_energy(m);  // masses split at a crack
    }
    if (commands_pending) {
      book_commands(m);
      commands_pending = false;
    }
    if (m.restart_damping) start_adaptive(m);
    const long cycle = m.info.cycle;
    // An excavation's loads come off a step every cycle while its release runs (run_cycles takes
    // the steps); the last step gives the boundary its own loads back, exactly, before its cycle.
    const long release_left = release_cycles_left(m);
    const bool releasing = release_left > 0;
    long batch = std::min(max_cycles - result.cycles, next_due(m, cycle) - cycle);
    if (release_left > 1) batch = std::min(batch, release_left - 1);
    if (release_left == 1) {
      end_release(m);
      batch = 1;
    }
    // What the run's course depends on is decided on measuring cycles only (contacts found again,
    // bolts rehosted, the damping adapted), never where a callback or an output frame cut a batch
    // short: watching a run does not change it.
    const bool measuring = cycle % kMeasureInterval == 0;
    // Contacts are found again where things have moved far enough (allowing for their speed
    // until the next measuring cycle), and everywhere at once when the list is no longer current.
    if ((measuring || !m.contacts.detected) && refresh_contacts(m, kMeasureInterval)) update_masses_booked(m);
    // Bolt nodes that slid out of their zone take the one they are in now.
    if (measuring && !m.bolts.nodes.x.empty() && rehost_bolts(m)) {
      tie_bolts(m);
      update_masses_booked(m);
    }
    m.energy.last_current = false;
    const Measure measure = run_cycles(m, static_cast<int>(batch));
    follow_thread_watch(m, measure, batch);
    result.cycles += batch;
    m.cycles_run += batch;
    m.info.cycle += batch;
    m.info.time += static_cast<double>(batch) * m.step;
    m.info.kinetic = measure.kinetic;
    m.info.ratio = measure.applied > 0.0 ? measure.unbalanced / measure.applied : 0.0;
    watch(m, mesh, measure, static_cast<int>(batch));
    if (m.settings.damping == Damping::adaptive && m.info.cycle % kMeasureInterval == 0) adapt_damping(m, measure);
    // A model that has just cracked is not in equilibrium, whatever the ratio said before.
    const bool cracked = run_due(m, mesh, m.info.cycle, commands_pending);
    // Nor is one whose excavation loads are still coming off.
    const int broke_before = result.broke;
    const bool was_settling = settling;
    const bool at_ratio = target_ratio > 0.0 && m.info.ratio <= goal && !cracked && !releasing;
    if (at_ratio && balanced() && at_goal()) {
      result.converged = true;
      break;
    }
    if (!at_ratio && freed && m.info.cycle % kMeasureInterval == 0) freed = free_unbalanced_bodies(m, balance);
    if (releasing || cracked || result.broke != broke_before || settling != was_settling) {
      lowest = INFINITY;
      lowest_at = result.cycles;
    } else if (m.info.cycle % kMeasureInterval == 0 && m.info.ratio < kProgress * lowest) {
      lowest = m.info.ratio;
      lowest_at = result.cycles;
    }
    if (stall > 0 && m.info.cycle % kMeasureInterval == 0 && result.cycles - lowest_at >= stall) {
      result.stalled = true;
      break;
    }
    if (reporting) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - reported).count() >= m.progress_every) {
        reported = now;
        long slipping = 0, open = 0;
        for (const Contact& c : m.contacts.list) {
          slipping += c.state == ContactState::slip;
          open += c.state == ContactState::open;
        }
        m.progress({.cycle = m.info.cycle,
                    .run_cycles = result.cycles,
                    .max_cycles = max_cycles,
                    .ratio = m.info.ratio,
                    .target = target_ratio,
                    .cracks = static_cast<long>(m.cracks.size()),
                    .stage = m.stage,
                    .seconds = std::chrono::duration<double>(now - started).count(),
                    .slipping = slipping,
                    .open = open,
                    .releasing = release_cycles_left(m)});
      }
    }
  }
  result.ratio = m.info.ratio;
  result.unjudged = !result.converged && m.judge.at == JudgeAt::equilibrium && any_intact(m);
  if (target_ratio > 0.0) note_worst_body(m, result);
  return result;
}

}  // namespace edem
