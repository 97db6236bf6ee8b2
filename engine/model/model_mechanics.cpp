// The Model's mechanical commands: materials, loads, cycling with the watchdog, callbacks,
// histories and the read-only views.
#include "state/mechanics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>

#include "bolt/bolt_coupling.hpp"
#include "constitutive/zone_law.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "core/union_find.hpp"
#include "io/temp_file.hpp"
#include "model/model.hpp"
#include "model/zone_in_rock.hpp"
#include "solver/loads.hpp"
#include "solver/prepare.hpp"
#include "solver/run.hpp"
#include "state/insitu.hpp"

namespace edem {
namespace {

bool has_x(const std::string& axes) { return axes.find('x') != std::string::npos; }
bool has_y(const std::string& axes) { return axes.find('y') != std::string::npos; }

void check_axes(const std::string& axes, const char* key) {
  if (!(axes.empty() || axes == "x" || axes == "y" || axes == "xy"))
    fail("{} must be \"x\", \"y\" or \"xy\", got \"{}\"", key, axes);
}

}  // namespace

Model::~Model() = default;
Model::Model(Model&&) noexcept = default;
Model& Model::operator=(Model&&) noexcept = default;

std::string zone_state_name(std::uint8_t state) {
  std::string name;
  auto add = [&](const char* part) {
    if (!name.empty()) name += ' ';
    name += part;
  };
  if (state & kShearNow)
    add("shear");
  else if (state & kShearPast)
    add("shear-past");
  if (state & kTensionNow)
    add("tension");
  else if (state & kTensionPast)
    add("tension-past");
  return name.empty() ? "elastic" : name;
}

// ---- inputs -----------------------------------------------------------------------------------

void Model::add_material(const MaterialDef& def) {
  const MaterialParams params = material_params(def);
  const MaterialDef kept = with_strength_defaults(def);
  Mechanics& m = *mechanics_;
  for (size_t i = 0; i < m.materials.size(); ++i) {
    if (m.materials[i].name != def.name) continue;
    if (zone_law(m.params[i].model).is_void != zone_law(params.model).is_void) {
      for (const int used : m.zone_material)
        if (used == static_cast<int>(i))
          fail("material '{}' is assigned to zones; it cannot change to or from model \"null\" "
               "(assign the zones another material instead)", def.name);
    }
    m.materials[i] = kept;
    m.params[i] = params;
    m.dirty = true;
    return;
  }
  m.materials.push_back(kept);
  m.params.push_back(params);
}

std::vector<std::string> Model::material_names() const {
  std::vector<std::string> names;
  for (const auto& material : mechanics_->materials) names.push_back(material.name);
  return names;
}

std::vector<int> Model::zones_in(const RegionRef& ref) const {
  std::vector<int> zones;
  if (ref.empty()) {
    for (int z = 0; z < mesh_.zone_count(); ++z) zones.push_back(z);
  } else if (!ref.name.empty()) {
    const int region = region_index(ref.name);
    for (int z = 0; z < mesh_.zone_count(); ++z) {
      const auto& regions = blocks_.blocks[static_cast<size_t>(mesh_.zone_block[static_cast<size_t>(z)])].regions;
      if (std::find(regions.begin(), regions.end(), region) != regions.end()) zones.push_back(z);
    }
  } else {
    const Polygon polygon = resolve(ref);
    for (int z = 0; z < mesh_.zone_count(); ++z)
      if (contains(polygon, mesh_.zone_centroid(z))) zones.push_back(z);
  }
  return zones;
}

void Model::assign(const AssignDef& def) {
  Mechanics& m = *mechanics_;
  const int material = index_of_name(m.materials, def.material, "material", "material{...}");
  if (mesh_.zone_count() == 0) fail("there are no zones to assign to: zone{{...}} the blocks first");
  const std::vector<int> zones = zones_in(def.region);
  if (zones.empty()) fail("no zone lies in the region");
  const bool null = zone_law(m.params[static_cast<size_t>(material)].model).is_void;
  for (const int z : zones) {
    m.zone_material[static_cast<size_t>(z)] = material;
    if (null) {
      m.stress[static_cast<size_t>(z)] = Stress{};
      m.mean_stress_ref[static_cast<size_t>(z)] = 0.0;
      m.zone_state[static_cast<size_t>(z)] = 0;
      m.zone_history[static_cast<size_t>(z)] = 0.0;
      m.zone_plastic_work[static_cast<size_t>(z)] = 0.0;
    }
  }
  m.dirty = true;
  if (!cycling_started() && !m.replaying)
    m.replay.push_back([def](Model& model) { model.assign(def); });
}

void Model::set_gravity(Vec2 g) {
  if (!std::isfinite(g.x) || !std::isfinite(g.y))
    fail("gravity must be finite, got ({}, {})", g.x, g.y);
  mechanics_->gravity = g;
  mechanics_->gravity_set = true;
  mechanics_->dirty = true;
}

void Model::insitu(const InsituDef& def) {
  check_insitu(def);
  Mechanics& m = *mechanics_;
  if (mesh_.zone_count() == 0) fail("there are no zones to initialise: zone{{...}} the blocks first");
  Polygon region;
  if (!def.region.empty()) region = resolve(def.region);
  const double g = m.gravity_set ? norm(m.gravity) : 9.81;
  for (int z = 0; z < mesh_.zone_count(); ++z) {
    const Vec2 centroid = mesh_.zone_centroid(z);
    if (!region.empty() && !contains(region, centroid)) continue;
    const int material = m.zone_material[static_cast<size_t>(z)];
    if (material >= 0 && zone_law(m.params[static_cast<size_t>(material)].model).is_void) continue;
    const Stress s = insitu_stress(def, centroid, g);
    m.stress[static_cast<size_t>(z)] = s;
    m.mean_stress_ref[static_cast<size_t>(z)] = mean_stress(s);
  }
  m.insitu.push_back(def);
  m.insitu_regions.push_back(region);
  m.contacts.from_insitu = true;  // contacts take the in-situ tractions when next found
  m.dirty = true;
  if (!cycling_started() && !m.replaying)
    m.replay.push_back([def](Model& model) { model.insitu(def); });
}

void Model::boundary(const BoundaryDef& def) {
  Mechanics& m = *mechanics_;
  if (def.side.empty() == def.polygon.empty()) fail("give either side or polygon");
  check_axes(def.fix, "fix");
  check_axes(def.free, "free");
  for (double vel : {def.xvel, def.yvel})
    if (!std::isnan(vel) && !std::isfinite(vel)) fail("velocity must be finite, got {}", vel);
  if (def.stress && def.stress_insitu) fail("give stress as three numbers or \"insitu\", not both");
  if (def.stress)
    for (double s : *def.stress)
      if (!std::isfinite(s)) fail("stress must be finite, got {}", s);
  if (mesh_.zone_count() == 0) fail("there are no gridpoints: zone{{...}} the blocks first");
  const std::vector<int> nodes = select_boundary_nodes(m, def);
  if (nodes.empty()) fail("no outer boundary gridpoint lies on side \"{}\"", def.side);

  // Tractions first: they can fail (no in-situ field), and nothing is changed before.
  std::vector<char> chosen(static_cast<size_t>(m.node_count), 0);
  for (int n : nodes) chosen[static_cast<size_t>(n)] = 1;
  std::vector<std::pair<size_t, std::pair<Stress, Stress>>> loads;
  if (def.stress || def.stress_insitu) {
    for (size_t i = 0; i < m.boundary.size(); ++i) {
      const BoundarySegment& s = m.boundary[i];
      if (!chosen[static_cast<size_t>(s.a)] || !chosen[static_cast<size_t>(s.b)]) continue;
      Stress at_a, at_b;
      if (def.stress_insitu) {
        auto point = [&](int n) {
          return Vec2{m.position[2 * static_cast<size_t>(n)], m.position[2 * static_cast<size_t>(n) + 1]};
        };
        at_a = insitu_stress_at(m, point(s.a));
        at_b = insitu_stress_at(m, point(s.b));
      } else {
        at_a = at_b = Stress{(*def.stress)[0], (*def.stress)[1], (*def.stress)[2], 0.0};
      }
      loads.push_back({i, {at_a, at_b}});
    }
    if (loads.empty()) fail("the selection holds no boundary segment to load (it needs two neighbouring gridpoints)");
  }

  for (const auto& [i, stresses] : loads) {
    m.boundary[i].loaded = true;
    m.boundary[i].at_a = stresses.first;
    m.boundary[i].at_b = stresses.second;
  }
  for (int n : nodes) {
    const size_t nn = static_cast<size_t>(n);
    std::uint8_t& fix = m.fix[nn];
    if (has_x(def.free)) fix &= static_cast<std::uint8_t>(~1u), m.v[2 * nn] = 0.0;
    if (has_y(def.free)) fix &= static_cast<std::uint8_t>(~2u), m.v[2 * nn + 1] = 0.0;
    if (has_x(def.fix)) fix |= 1, m.v[2 * nn] = 0.0;
    if (has_y(def.fix)) fix |= 2, m.v[2 * nn + 1] = 0.0;
    if (!std::isnan(def.xvel)) fix |= 1, m.v[2 * nn] = def.xvel;
    if (!std::isnan(def.yvel)) fix |= 2, m.v[2 * nn + 1] = def.yvel;
  }
  lump_boundary_loads(m);
  m.dirty = true;
  if (!cycling_started() && !m.replaying)
    m.replay.push_back([def](Model& model) { model.boundary(def); });
}

void Model::set_solver(const SolverSettings& settings) {
  if (!(settings.local_damping >= 0.0 && settings.local_damping < 1.0))
    fail("local damping must be in [0, 1), got {}", settings.local_damping);
  if (!(settings.step >= 0.0) || !std::isfinite(settings.step))
    fail("step must be >= 0 (0: automatic), got {}", settings.step);
  if (!(settings.step_fraction > 0.0 && settings.step_fraction <= 1.0))
    fail("fraction must be in (0, 1], got {}", settings.step_fraction);
  if (!(settings.overlap >= 0.0) || !std::isfinite(settings.overlap))
    fail("overlap must be >= 0 (0: automatic), got {}", settings.overlap);
  mechanics_->settings = settings;
  mechanics_->dirty = true;
}

const SolverSettings& Model::solver_settings() const { return mechanics_->settings; }

void Model::set_progress(std::function<void(const RunProgress&)> report, double every_seconds) {
  if (!(every_seconds >= 0.0)) fail("the progress interval must be >= 0 s, got {}", every_seconds);
  mechanics_->progress = std::move(report);
  mechanics_->progress_every = every_seconds;
}

void Model::set_stop(const std::atomic<int>* flag) { mechanics_->stop = flag; }

void Model::set_prepass_progress(std::function<void(const PrepassProgress&)> report) {
  mechanics_->prepass_progress = std::move(report);
}

void Model::set_notice(std::function<void(const std::string&)> say) { mechanics_->notice = std::move(say); }

void Model::set_threads(int threads) {
  if (threads < 0) fail("threads must be >= 1, got {}", threads);
  mechanics_->threads = threads;
  mechanics_->thread_watch = ThreadWatch{};
}

void Model::reset(const ResetWhat& what) {
  Mechanics& m = *mechanics_;
  if (what.displacement) {
    reset_bolt_displacements(m);
    for (size_t dof = 0; dof < m.u.size(); ++dof) m.origin[dof] += m.u[dof];  // nodes stay put
    std::fill(m.u.begin(), m.u.end(), 0.0);
  }
  if (what.velocity)
    for (size_t n = 0; n < static_cast<size_t>(m.node_count); ++n) {
      if (!(m.fix[n] & 1)) m.v[2 * n] = 0.0;
      if (!(m.fix[n] & 2)) m.v[2 * n + 1] = 0.0;
    }
  if (what.state) {
    std::fill(m.zone_state.begin(), m.zone_state.end(), 0);
    std::fill(m.zone_plastic_work.begin(), m.zone_plastic_work.end(), 0.0);
  }
  if (what.joint)
    for (Contact& c : m.contacts.list) c.us = c.slip = 0.0;
  m.dirty = true;  // restarts the adaptive damping from here
}

// ---- cycling --------------------------------------------------------------------------------

bool Model::cycling_started() const { return mechanics_->cycles_run > 0; }
bool Model::cycling_now() const { return mechanics_->cycling_now; }
SolverInfo Model::solver_info() const {
  SolverInfo info = mechanics_->info;
  info.contacts = mechanics_->contacts.detected ? static_cast<int>(mechanics_->contacts.list.size()) : 0;
  info.late_contacts = mechanics_->contacts.late;
  info.damping_rate = mechanics_->settings.damping == Damping::adaptive ? mechanics_->adaptive.c : 0.0;
  info.contact_searches = mechanics_->contacts.searched;
  info.threads = mechanics_->partition.threads > 0 ? thread_count(*mechanics_) : asked_threads(*mechanics_);
  return info;
}

EnergyReport Model::energy() const { return energy_report(*mechanics_); }

void Model::reset_energy() {
  if (mechanics_->cycling_now) fail("energy{{ reset = true }} cannot be given while cycling (from a callback)");
  start_energy(*mechanics_);
}

void Model::book_energy_by_contact(bool on) {
  if (mechanics_->cycling_now) fail("energy{{ by_contact = ... }} cannot be given while cycling (from a callback)");
  book_by_contact(*mechanics_, on);
}

std::string Model::unheld() const {
  const Mechanics& m = *mechanics_;
  if (!m.gravity_set || (m.gravity.x == 0.0 && m.gravity.y == 0.0)) return {};
  if (std::any_of(m.fix.begin(), m.fix.end(), [](std::uint8_t f) { return f != 0; })) return {};
  return "gravity acts and no gridpoint is held: the model falls as a whole (hold its base, e.g. "
         "boundary{ side = \"bottom\", fix = \"y\" })";
}

SolveResult Model::run(long max_cycles, double target_ratio, long stall, double settle, double balance) {
  return run_solver(*mechanics_, mesh_, max_cycles, target_ratio, stall, settle, balance);
}

SolveResult Model::cycle(long count) {
  if (count < 1) fail("the number of cycles must be >= 1, got {}", count);
  return run(count, 0.0);
}

SolveResult Model::solve(const SolveDef& def) {
  if (!(def.ratio > 0.0 && def.ratio < 1.0)) fail("ratio must be in (0, 1), got {}", def.ratio);
  if (def.max_cycles < 1) fail("max_cycles must be >= 1, got {}", def.max_cycles);
  if (def.stall < 0) fail("stall must be >= 0, got {}", def.stall);
  if (!(def.settle >= 0.0 && def.settle < def.ratio))
    fail("settle must be 0 or below ratio ({}), got {}", def.ratio, def.settle);
  if (!(def.balance >= 0.0 && def.balance < 1.0)) fail("balance must be in [0, 1), got {}", def.balance);
  return run(def.max_cycles, def.ratio, def.stall, def.settle, def.balance);
}

int Model::add_callback(long every, std::function<void(long)> fn) {
  if (every < 1) fail("every must be >= 1, got {}", every);
  Mechanics& m = *mechanics_;
  m.callbacks.push_back({m.next_handle, every, std::move(fn)});
  return m.next_handle++;
}

void Model::cancel_callback(int handle) {
  auto& callbacks = mechanics_->callbacks;
  const auto it = std::find_if(callbacks.begin(), callbacks.end(),
                               [&](const Callback& c) { return c.handle == handle; });
  if (it == callbacks.end()) fail("no callback with handle {} (cancelled already?)", handle);
  callbacks.erase(it);
}

// ---- histories --------------------------------------------------------------------------------

int Model::add_history(HistoryDef def) {
  if (def.name.empty()) fail("a history needs a name");
  if (def.every < 1) fail("every must be >= 1, got {}", def.every);
  if (!def.sample && def.quantity.empty()) fail("history '{}' has nothing to sample", def.name);
  auto& histories = mechanics_->histories;
  for (size_t i = 0; i < histories.size(); ++i) {
    History& h = histories[i];
    if (h.name != def.name) continue;
    // A restored history whose function the script gives again goes on where it stopped.
    if (h.sample || !h.quantity.empty() || !def.quantity.empty())
      fail("a history named '{}' exists already", def.name);
    if (def.every != h.every)
      fail("history '{}' was recorded every {} cycles before it was saved; give every = {} to go on with it",
           def.name, h.every, h.every);
    h.sample = std::move(def.sample);
    h.unit = def.unit;
    return static_cast<int>(i + 1);
  }
  History h;
  h.name = def.name;
  h.every = def.every;
  h.sample = std::move(def.sample);
  h.unit = def.unit;
  h.quantity = def.quantity;
  h.at = def.at;
  if (!h.quantity.empty()) follow(h);
  if (h.node >= 0 && zone_at(*h.at) < 0) {
    const Mechanics& m = *mechanics_;
    const Vec2 node{m.position[2 * static_cast<size_t>(h.node)], m.position[2 * static_cast<size_t>(h.node) + 1]};
    if (norm(node - *h.at) > tolerance())
      notices_.push_back({true, fmt::format("at = ({:.4g}, {:.4g}) lies outside the model's zones: history '{}' "
                                            "follows the gridpoint nearest to it, {:.3g} m away at ({:.4g}, {:.4g})",
                                            h.at->x, h.at->y, h.name, norm(node - *h.at), node.x, node.y)});
  }
  histories.push_back(std::move(h));
  return static_cast<int>(histories.size());
}

const std::vector<std::string>& Model::history_point_quantities() {
  static const std::vector<std::string> names{"ux",       "uy",        "vx",       "vy",
                                              "sxx",      "syy",       "sxy",      "szz",
                                              "s1",       "s3",        "joint_sn", "joint_tau",
                                              "joint_un", "joint_us",  "joint_slip"};
  return names;
}

const std::vector<std::string>& Model::history_model_quantities() {
  static const std::vector<std::string> names{
      "ratio",           "time",           "kinetic",          "cycle",           "contacts",
      "slipping",        "open",           "max_slip",         "cracks",          "shear_cracks",
      "tension_cracks",  "stage",          "energy.kinetic",   "energy.strain",   "energy.contact",
      "energy.bolt",     "energy.gravity", "energy.boundary",  "energy.release",  "energy.prestress",
      "energy.commands", "energy.excavated", "energy.plastic", "energy.slip",     "energy.bond",
      "energy.damping",  "energy.bolt_plastic", "energy.error"};
  return names;
}

std::string Model::history_unit(std::string_view quantity) {
  if (quantity == "ratio" || quantity == "cycle" || quantity == "contacts" ||
      quantity == "slipping" || quantity == "open" || quantity.ends_with("cracks") || quantity == "stage")
    return "-";
  if (quantity == "time") return "s";
  if (quantity == "kinetic" || quantity.starts_with("energy.")) return "J/m";
  if (quantity == "ux" || quantity == "uy" || quantity == "max_slip" || quantity == "joint_un" ||
      quantity == "joint_us" || quantity == "joint_slip")
    return "m";
  if (quantity == "vx" || quantity == "vy") return "m/s";
  return "Pa";
}

namespace {

// Counts of the contacts as last found, or the largest slip among them.
double contact_statistic(const Mechanics& m, std::string_view quantity) {
  const std::vector<Contact>& list = m.contacts.list;
  if (quantity == "contacts") return static_cast<double>(list.size());
  double value = 0.0;
  for (const Contact& c : list) {
    if (quantity == "slipping") value += c.state == ContactState::slip;
    else if (quantity == "open") value += c.state == ContactState::open;
    else value = std::max(value, c.slip);
  }
  return value;
}

// A joint quantity of the first contact of `node` (contacts are sorted by node), 0 if none.
double joint_quantity(const Mechanics& m, int node, std::string_view quantity) {
  const std::vector<Contact>& list = m.contacts.list;
  const auto c = std::lower_bound(list.begin(), list.end(), node,
                                  [](const Contact& x, int n) { return x.node < n; });
  if (c == list.end() || c->node != node) return 0.0;
  const bool open = c->state == ContactState::open;
  if (quantity == "joint_sn") return open ? 0.0 : -c->sn;  // compression negative
  const double length = c->length * c->share;
  if (quantity == "joint_tau") return length > 0.0 ? c->fs / length : 0.0;
  if (quantity == "joint_un") return c->dilation - c->closure;
  if (quantity == "joint_us") return c->us;
  return c->slip;
}

// One term of the energy balance by its name (energy.hpp, EnergyReport).
double energy_term(const Mechanics& m, std::string_view term) {
  const EnergyReport r = energy_report(m);
  if (term == "kinetic") return r.stored.kinetic;
  if (term == "strain") return r.stored.strain;
  if (term == "contact") return r.stored.contact();
  if (term == "bolt") return r.stored.bolt;
  if (term == "gravity") return r.gravity;
  if (term == "boundary") return r.boundary;
  if (term == "release") return r.release;
  if (term == "prestress") return r.prestress;
  if (term == "commands") return r.commands;
  if (term == "excavated") return r.excavated;
  if (term == "plastic") return r.plastic;
  if (term == "slip") return r.slip;
  if (term == "bond") return r.bond;
  if (term == "damping") return r.damping;
  if (term == "bolt_plastic") return r.bolt_plastic;
  return r.error;
}

// The sampler of a quantity of the whole model.
std::function<double()> global_sampler(const Mechanics* m, std::string_view quantity) {
  if (quantity == "ratio") return [m] { return m->info.ratio; };
  if (quantity == "time") return [m] { return m->info.time; };
  if (quantity == "kinetic") return [m] { return m->info.kinetic; };
  if (quantity == "cycle") return [m] { return static_cast<double>(m->info.cycle); };
  if (quantity == "stage") return [m] { return static_cast<double>(m->stage); };
  if (quantity.starts_with("energy.")) return [m, q = std::string(quantity.substr(7))] { return energy_term(*m, q); };
  if (quantity.ends_with("cracks")) {
    const CrackMode mode = quantity == "shear_cracks"     ? CrackMode::shear
                           : quantity == "tension_cracks" ? CrackMode::tension
                                                          : CrackMode::none;
    return [m, mode] {
      if (mode == CrackMode::none) return static_cast<double>(m->cracks.size());
      return static_cast<double>(std::count_if(m->cracks.begin(), m->cracks.end(),
                                               [mode](const CrackView& c) { return c.mode == mode; }));
    };
  }
  return [m, q = std::string(quantity)] { return contact_statistic(*m, q); };
}

// The sampler of a point quantity on what it follows: a node for ux, uy, vx, vy and joint_*, a
// zone for the stresses.
std::function<double()> point_sampler(const Mechanics* m, const std::string& q, int node, int zone) {
  if (q.starts_with("joint_")) return [m, node, q] { return joint_quantity(*m, node, q); };
  if (q[0] == 'u' || q[0] == 'v') {
    const size_t dof = 2 * static_cast<size_t>(node) + (q[1] == 'y' ? 1 : 0);
    if (q[0] == 'u') return [m, dof] { return m->u[dof]; };
    return [m, dof] { return m->v[dof]; };
  }
  const size_t z = static_cast<size_t>(zone);
  if (q == "sxx") return [m, z] { return m->stress[z].xx; };
  if (q == "syy") return [m, z] { return m->stress[z].yy; };
  if (q == "sxy") return [m, z] { return m->stress[z].xy; };
  if (q == "szz") return [m, z] { return m->stress[z].zz; };
  if (q == "s1") return [m, z] { return in_plane_principal(m->stress[z]).s1; };
  return [m, z] { return in_plane_principal(m->stress[z]).s3; };
}


}  // namespace

std::function<double()> Model::history_sampler(std::string_view quantity,
                                                std::optional<Vec2> at) const {
  History h;
  h.quantity = quantity;
  h.at = at;
  follow(h);
  return h.sample;
}

void Model::follow(History& h) const {
  const auto& global = history_model_quantities();
  const auto& local = history_point_quantities();
  const std::string_view quantity = h.quantity;
  const bool is_global = std::find(global.begin(), global.end(), quantity) != global.end();
  const bool is_local = std::find(local.begin(), local.end(), quantity) != local.end();
  if (!is_global && !is_local) {
    std::vector<std::string> all = global;
    all.insert(all.end(), local.begin(), local.end());
    fail("unknown history quantity '{}'{}", quantity, did_you_mean(quantity, all));
  }
  const Mechanics* m = mechanics_.get();
  if (is_global) {
    h.sample = global_sampler(m, quantity);
    return;
  }
  if (!h.at) fail("history quantity '{}' needs at = {{x, y}}", quantity);
  const Vec2 at = *h.at;
  if (h.node < 0 && h.zone < 0) {
    if (quantity.starts_with("joint_")) {
      const int id = contact_near(at);
      if (id < 0) fail("no contact to follow near ({}, {})", at.x, at.y);
      h.node = m->contacts.list[static_cast<size_t>(id)].node;
    } else if (quantity[0] == 'u' || quantity[0] == 'v') {
      const int gp = gridpoint_near(at);
      if (gp < 0) fail("there are no gridpoints to follow: zone{{...}} the blocks first");
      h.node = m->gp_node[static_cast<size_t>(gp)];
    } else {
      h.zone = zone_at(at);
      if (h.zone < 0) fail("no zone contains the point ({}, {})", at.x, at.y);
    }
  }
  h.sample = point_sampler(m, h.quantity, h.node, h.zone);
}

void Model::follow_histories_past_excavation() {
  Mechanics& m = *mechanics_;
  std::vector<char> in_rock(static_cast<size_t>(m.node_count), 0);
  for (int z = 0; z < mesh_.zone_count(); ++z)
    if (zone_in_rock(m, static_cast<size_t>(z)))
      for (const int gp : mesh_.zone_gp[static_cast<size_t>(z)])
        in_rock[static_cast<size_t>(m.gp_node[static_cast<size_t>(gp)])] = 1;
  const auto place = [&](int node) {
    return Vec2{m.position[2 * static_cast<size_t>(node)], m.position[2 * static_cast<size_t>(node) + 1]};
  };
  for (History& h : m.histories) {
    if (!h.ended.empty()) continue;
    if (h.zone >= 0 && !zone_in_rock(m, static_cast<size_t>(h.zone))) {
      h.ended = fmt::format("its zone at ({:.4g}, {:.4g}) was excavated at stage {}", h.at->x, h.at->y, m.stage);
    } else if (h.node >= 0 && !in_rock[static_cast<size_t>(h.node)]) {
      // The rock on the other side of the excavation's outline, at the same place, if any.
      const Vec2 here = place(h.node);
      int next = -1;
      if (!h.quantity.starts_with("joint_"))
        for (int n = 0; n < m.node_count && next < 0; ++n)
          if (in_rock[static_cast<size_t>(n)] && norm(place(n) - here) <= tolerance()) next = n;
      if (next >= 0) {
        h.node = next;
        h.sample = point_sampler(&m, h.quantity, h.node, h.zone);
        notices_.push_back({false, fmt::format("history '{}' goes on at the gridpoint of block {} at ({:.4g}, {:.4g}): "
                                               "the excavation took its own",
                                               h.name, m.node_block[static_cast<size_t>(next)] + 1, here.x, here.y)});
        continue;
      }
      h.ended = fmt::format("its gridpoint at ({:.4g}, {:.4g}) was excavated at stage {}", here.x, here.y, m.stage);
    } else {
      continue;
    }
    notices_.push_back(
        {true, fmt::format("history '{}' records nothing more: {} (measure where rock stays)", h.name, h.ended)});
  }
}

std::vector<Model::Notice> Model::take_notices() { return std::exchange(notices_, {}); }

const std::vector<History>& Model::histories() const { return mechanics_->histories; }

namespace {
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
}
}  // namespace

void Model::write_histories(const std::string& path) const {
  const auto& histories = mechanics_->histories;
  if (histories.empty()) fail("there are no histories to write: history{{...}} first");
  std::map<long, std::vector<const double*>> rows;
  for (size_t h = 0; h < histories.size(); ++h)
    for (size_t i = 0; i < histories[h].cycles.size(); ++i) {
      auto& row = rows[histories[h].cycles[i]];
      row.resize(histories.size(), nullptr);
      row[h] = &histories[h].values[i];
    }
  TempFile temporary(path);
  {
    std::ofstream out(temporary.path());
    if (!out) fail("cannot write '{}'", path);
    out << "cycle";
    // RFC 4180: a header field with a comma, quote or line break is quoted, quotes doubled.
    for (const History& h : histories) out << ',' << csv_field(fmt::format("{} [{}]", h.name, h.unit));
    out << '\n';
    for (const auto& [cycle, row] : rows) {
      out << cycle;
      for (const double* value : row) {
        out << ',';
        if (value) out << fmt::format("{}", *value);
      }
      out << '\n';
    }
    if (!out) fail("cannot write '{}'", path);
  }
  temporary.move_into_place();
}

// ---- views ----------------------------------------------------------------------------------

bool zone_in_rock(const Mechanics& m, size_t z) {
  const int material = m.zone_material.empty() ? -1 : m.zone_material[z];
  return material >= 0 && m.zone_excavated[z] == 0 && !zone_law(m.params[static_cast<size_t>(material)].model).is_void;
}

int Model::gridpoint_near(Vec2 point) const {
  // Of gridpoints at one place (both sides of a joint, or of a wall excavate{} freed), the one
  // of a block with rock in place.
  const Mechanics& m = *mechanics_;
  std::vector<char> rock(blocks_.blocks.size(), 0);
  for (int z = 0; z < mesh_.zone_count(); ++z)
    if (zone_in_rock(m, static_cast<size_t>(z))) rock[static_cast<size_t>(mesh_.zone_block[static_cast<size_t>(z)])] = 1;
  int best = -1;
  double best_distance = INFINITY;
  bool best_rock = false;
  for (int gp = 0; gp < mesh_.gp_count(); ++gp) {
    const Vec2 d = mesh_.gp_position[static_cast<size_t>(gp)] - point;
    const double distance = dot(d, d);
    const bool in_rock = rock[static_cast<size_t>(mesh_.gp_block[static_cast<size_t>(gp)])] != 0;
    if (distance < best_distance || (distance == best_distance && in_rock && !best_rock))
      best_distance = distance, best = gp, best_rock = in_rock;
  }
  return best;
}

int Model::zone_at(Vec2 point) const {
  const double slack = 1e-12 * (1.0 + std::fabs(point.x) + std::fabs(point.y));
  for (int z = 0; z < mesh_.zone_count(); ++z) {
    const auto& corners = mesh_.zone_gp[static_cast<size_t>(z)];
    bool inside = true;
    for (int i = 0; i < 3 && inside; ++i) {
      const Vec2 a = mesh_.gp_position[static_cast<size_t>(corners[static_cast<size_t>(i)])];
      const Vec2 b = mesh_.gp_position[static_cast<size_t>(corners[static_cast<size_t>((i + 1) % 3)])];
      inside = cross(b - a, point - a) >= -slack * norm(b - a);
    }
    if (inside) return z;
  }
  return -1;
}

GridpointView Model::gridpoint(int id) const {
  if (id < 0 || id >= mesh_.gp_count()) fail("no gridpoint {}", id + 1);
  const Mechanics& m = *mechanics_;
  GridpointView view;
  view.id = id;
  view.position = mesh_.gp_position[static_cast<size_t>(id)];
  if (m.gp_node.empty()) return view;
  const size_t n = static_cast<size_t>(m.gp_node[static_cast<size_t>(id)]);
  view.u = {m.u[2 * n], m.u[2 * n + 1]};
  view.v = {m.v[2 * n], m.v[2 * n + 1]};
  view.f = {m.force[2 * n], m.force[2 * n + 1]};
  view.fixed_x = m.fix[n] & 1;
  view.fixed_y = m.fix[n] & 2;
  for (double value : {view.u.x, view.u.y, view.v.x, view.v.y, view.f.x, view.f.y})
    if (!std::isfinite(value))
      fail("gridpoint {} holds no finite state: the run went unstable earlier", id + 1);
  return view;
}

ZoneView Model::zone_view(int id) const {
  if (id < 0 || id >= mesh_.zone_count()) fail("no zone {}", id + 1);
  const Mechanics& m = *mechanics_;
  ZoneView view;
  view.id = id;
  view.centroid = mesh_.zone_centroid(id);
  if (m.stress.empty()) return view;
  const Stress& s = m.stress[static_cast<size_t>(id)];
  for (double value : {s.xx, s.yy, s.xy, s.zz})
    if (!std::isfinite(value))
      fail("zone {} holds no finite stress: the run went unstable earlier", id + 1);
  view.sxx = s.xx, view.syy = s.yy, view.sxy = s.xy, view.szz = s.zz;
  const Principal p = in_plane_principal(s);
  view.s1 = p.s1, view.s3 = p.s3;
  view.state = m.zone_state[static_cast<size_t>(id)];
  const int material = m.zone_material[static_cast<size_t>(id)];
  if (material >= 0) {
    view.material = m.materials[static_cast<size_t>(material)].name;
    view.history_name = zone_law(m.params[static_cast<size_t>(material)].model).history;
    if (!view.history_name.empty()) view.history = m.zone_history[static_cast<size_t>(id)];
  }
  view.plastic_work = m.zone_plastic_work[static_cast<size_t>(id)];
  view.excavated = m.zone_excavated.empty() ? 0 : m.zone_excavated[static_cast<size_t>(id)];
  return view;
}

// Mucking out fallen rock asks this of every block every few hundred cycles, so it reads the
// arrays directly instead of building a view per gridpoint.
BlockMotion Model::block_motion(int block) const {
  if (block < 0 || block >= static_cast<int>(blocks_.blocks.size())) fail("no block {}", block + 1);
  BlockMotion motion;
  const Mechanics& m = *mechanics_;
  const size_t b = static_cast<size_t>(block);
  if (b + 1 >= mesh_.block_first_gp.size() || m.gp_node.empty()) return motion;
  double largest = 0.0;
  for (int gp = mesh_.block_first_gp[b]; gp < mesh_.block_first_gp[b + 1]; ++gp) {
    const size_t n = static_cast<size_t>(m.gp_node[static_cast<size_t>(gp)]);
    const double u2 = m.u[2 * n] * m.u[2 * n] + m.u[2 * n + 1] * m.u[2 * n + 1];
    if (!std::isfinite(u2)) fail("block {} holds no finite state: the run went unstable earlier", block + 1);
    largest = std::max(largest, u2);
  }
  motion.max_displacement = std::sqrt(largest);
  if (m.zone_excavated.empty()) return motion;
  const int first = mesh_.block_first_zone[b], last = mesh_.block_first_zone[b + 1];
  for (int z = first; z < last; ++z) {
    const int stage = m.zone_excavated[static_cast<size_t>(z)];
    if (stage <= 0) return {motion.max_displacement, 0};
    motion.excavated = std::max(motion.excavated, stage);
  }
  return motion;
}

std::vector<int> Model::loose_blocks(double speed) const {
  if (!(speed >= 0.0 && std::isfinite(speed))) fail("speed must be a finite number >= 0, got {}", speed);
  const Mechanics& m = *mechanics_;
  const size_t blocks = blocks_.blocks.size();
  if (m.gp_node.empty() || mesh_.block_first_gp.size() != blocks + 1) return {};
  // Blocks with rock in place, and the blocks glued to them (sharing a node) as one body.
  std::vector<char> in_place(blocks, 0);
  for (int z = 0; z < mesh_.zone_count(); ++z) {
    const int material = m.zone_material[static_cast<size_t>(z)];
    if (material >= 0 && !zone_law(m.params[static_cast<size_t>(material)].model).is_void &&
        m.zone_excavated[static_cast<size_t>(z)] == 0)
      in_place[static_cast<size_t>(mesh_.zone_block[static_cast<size_t>(z)])] = 1;
  }
  std::vector<int> body(blocks), node_body(static_cast<size_t>(m.node_count), -1);
  for (size_t b = 0; b < blocks; ++b) body[b] = static_cast<int>(b);
  const auto root = [&](int b) { return find_root(body, b); };
  for (size_t b = 0; b < blocks; ++b) {
    if (!in_place[b]) continue;
    for (int gp = mesh_.block_first_gp[b]; gp < mesh_.block_first_gp[b + 1]; ++gp) {
      int& owner = node_body[static_cast<size_t>(m.gp_node[static_cast<size_t>(gp)])];
      if (owner < 0) owner = static_cast<int>(b);
      else body[static_cast<size_t>(root(static_cast<int>(b)))] = root(owner);
    }
  }
  // Held: a gridpoint held, or a contact pressed against another body.
  std::vector<char> held(blocks, 0);
  std::vector<double> speed_sum(blocks, 0.0);
  std::vector<int> moving(blocks, 0);
  for (size_t n = 0; n < node_body.size(); ++n) {
    if (node_body[n] < 0) continue;
    const size_t r = static_cast<size_t>(root(node_body[n]));
    if (m.fix[n]) held[r] = 1;
    if (n < m.mass.size() && m.mass[n] > 0.0) {
      speed_sum[r] += std::hypot(m.v[2 * n], m.v[2 * n + 1]);
      ++moving[r];
    }
  }
  // The load of an excavation still coming off holds the new face it pushes on: the rock dug
  // away bears on it until its release ends.
  const ReleaseLoad& release = m.release;
  if (release.factor > 0.0)
    for (size_t i = 0; i < release.dof.size(); ++i) {
      const int body_of = node_body[static_cast<size_t>(release.dof[i] / 2)];
      if (body_of >= 0 && release.force[i] != 0.0) held[static_cast<size_t>(root(body_of))] = 1;
    }
  for (const Contact& c : m.contacts.list) {
    if (c.state == ContactState::open || !(c.sn > 0.0)) continue;
    const int a = node_body[static_cast<size_t>(c.node)];
    const int e = node_body[static_cast<size_t>(m.faces.edges[static_cast<size_t>(c.edge)].a)];
    if (a < 0 || e < 0 || root(a) == root(e)) continue;
    held[static_cast<size_t>(root(a))] = held[static_cast<size_t>(root(e))] = 1;
  }
  std::vector<int> loose;
  for (size_t b = 0; b < blocks; ++b) {
    if (!in_place[b]) continue;
    const size_t r = static_cast<size_t>(root(static_cast<int>(b)));
    const bool fast = speed > 0.0 && moving[r] > 0 && speed_sum[r] / moving[r] > speed;
    if (!held[r] || fast) loose.push_back(static_cast<int>(b));
  }
  return loose;
}

}  // namespace edem
