// Mechanics of a zoned model: materials, loads, and the arrays the explicit solver cycles.
//
// Owned by the Model. Nodes are the mesh gridpoints with those on either side of a glued edge
// merged into one (glued blocks are one continuum). Arrays indexed by mesh zone hold the
// zone state (stress, material, plastic state) for every zone, null or not; the solver loops
// over `active` only. Node vectors interleave x and y: [2n] is x, [2n + 1] is y.
//
// Derived arrays (geometry, masses, partition) are rebuilt by prepare() whenever `dirty`;
// the state (stresses, displacements, velocities) persists across rebuilds.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/physics_defs.hpp"
#include "geom/mesh.hpp"
#include "state/bolts.hpp"
#include "state/contacts.hpp"
#include "state/energy_ledger.hpp"
#include "state/joint_params.hpp"
#include "state/material_params.hpp"
#include "state/sections.hpp"
#include "state/stress.hpp"
#include "state/thread_watch.hpp"

namespace edem {

// Per mesh zone, from the reference positions.
struct ZoneGeometry {
  std::array<int, 3> node{};  // solver nodes, counter-clockwise
  double area = 0.0;          // [m^2]
  double b[3] = {};           // dN_i/dx [1/m]
  double c[3] = {};           // dN_i/dy [1/m]
};

// A zone's strain from nodal values, engineering shear: from velocities its rate [1/s] (the
// cycle), from displacement increments its increment [-] (the prepass).
struct ZoneStrain {
  double xx, yy, xy;
};

[[gnu::always_inline]] inline ZoneStrain zone_strain(const double* v, const ZoneGeometry& g) {
  const size_t n0 = static_cast<size_t>(g.node[0]), n1 = static_cast<size_t>(g.node[1]),
               n2 = static_cast<size_t>(g.node[2]);
  const double vx0 = v[2 * n0], vy0 = v[2 * n0 + 1], vx1 = v[2 * n1], vy1 = v[2 * n1 + 1],
               vx2 = v[2 * n2], vy2 = v[2 * n2 + 1];
  return {g.b[0] * vx0 + g.b[1] * vx1 + g.b[2] * vx2, g.c[0] * vy0 + g.c[1] * vy1 + g.c[2] * vy2,
          g.c[0] * vx0 + g.c[1] * vx1 + g.c[2] * vx2 + g.b[0] * vy0 + g.b[1] * vy1 + g.b[2] * vy2};
}

// A segment of the model's outer boundary (a block{} outline), domain on its left.
struct BoundarySegment {
  int a = -1, b = -1;   // nodes
  bool loaded = false;  // carries a traction from a stress tensor
  Stress at_a, at_b;    // the stress whose traction it carries, at each end [Pa]
};

// Zones are split among threads in blocks of this many (contacts and nodes: kSplitChunk);
// partial sums are taken over the same blocks, so that reductions give the same bits for any
// thread count.
inline constexpr int kChunk = 1024;

// How zones, contacts and nodes are split among threads, and where each zone corner's contribution
// goes. Contributions to a node are always summed in the order zones are done (active order,
// the other members of a mixed group right after its first), so the result is the same bits
// for any thread count: a node whose zones are all done by one thread's range is accumulated
// in place; a node shared by ranges gathers its per-corner slots in that order.
struct Partition {
  int threads = 0;
  std::vector<int> zone_begin;          // thread t: active positions [zone_begin[t], [t+1])
  std::vector<double> contact_cut;      // thread t: the share of contacts before its own
  std::vector<double> node_cut;         // the same for nodes (load_balance.hpp)
  std::vector<std::array<int, 3>> dest; // per active zone corner: accumulator index
  std::vector<int> gather_first;        // per node + 1: its slots in `gather` (empty: owned)
  std::vector<int> gather;              // accumulator indices of shared nodes' slots, in order
  int accumulators = 0;                 // nodes + slots
};

struct Callback {
  int handle = 0;
  long every = 1;
  std::function<void(long)> fn;
};

// The adaptive damping of static mode: viscous damping c = 2 omega, omega^2 the Rayleigh
// quotient of the displacement since the start of the cycling command (see cycle.cpp).
struct AdaptiveDamping {
  double c = 0.0;                 // [1/s]
  std::vector<double> u_start;    // displacement at the start [m]
  std::vector<double> r_start;    // unbalanced force at the start (first cycle) [N/m]
  bool have_r_start = false;
};

// What an excavation took off the nodes of the rock left in place (the excavated zones' forces,
// the dug blocks' contacts), held as loads and taken off linearly over `cycles`
// (excavate{ release = n }).
struct ReleaseLoad {
  std::vector<int> dof;        // node components that carry a share
  std::vector<double> force;   // the share at excavation [N/m]
  long cycles = 0;             // over how many cycles it goes
  long done = 0;               // cycles run since
  double factor = 0.0;         // the fraction of `force` in Mechanics::load now
  // The work of the last cycle's share is summed once its nodes have moved (release_work):
  // with the velocities before it [m/s], while one is pending.
  std::vector<double> v_before;
  bool pending = false;
};

// How a bolt's head is held (bolt_head{}).
enum class HeadDrive : std::uint8_t { none, velocity, force };

// The bolts' ties to the rock (bolt/bolt_coupling.cpp). Each bolt node is tied to a material
// point of a host zone, at fixed shape-function weights: across the bolt's axis the node moves
// with that point (a bolt has no bending stiffness of its own), along it the node slides against
// it by `slide`, resisted by the grout. Per bolt node unless said otherwise.
struct BoltHosts {
  std::vector<int> zone;                      // host mesh zone; -1: none (outside the rock, ungrouted)
  std::vector<std::array<double, 3>> weight;  // its shape functions at the material point
  std::vector<Vec2> u0;        // the point's displacement (its corners' u) when it became the host [m]
  std::vector<Vec2> host_u;    // the point's displacement since the bolt's installation [m]
  std::vector<double> slide;   // along `dir` against the point [m]
  // The direction it slides in: the bolt's axis when the node was tied to its point. Fixed
  // between ties: following the axis as it turns would move the node across it by slide x turn,
  // which turns the axis further.
  std::vector<Vec2> dir;
  std::vector<double> rate;    // d slide / dt [m/s]
  std::vector<double> mass;    // cycling mass (scaled in static mode) [kg/m]
  std::vector<double> slide_start, r_start;  // adaptive damping: as for the rock's nodes
  // Per bolt.
  std::vector<int> material;   // bolt material
  std::vector<int> stage;      // installed at this excavation stage
  std::vector<char> removed;   // none of its rock is left: out of service
  std::vector<HeadDrive> drive;
  std::vector<double> drive_value;  // velocity [m/s], or force per metre of thickness [N/m]
  std::vector<double> head_force;   // axial pull on the head at the last cycle [N/m]
  // Per solver node + 1: the bolt node corners it takes grout forces from (bolt node * 3 + corner).
  std::vector<int> gather_first, gather;
  std::vector<double> rows;    // per solver node: grout stiffness in its Gershgorin row [N/m per m]
  double critical_step = std::numeric_limits<double>::infinity();  // the bolts' own, real masses [s]
};

struct Mechanics {
  // ---- inputs
  std::vector<MaterialDef> materials;
  std::vector<MaterialParams> params;  // same order as materials
  SolverSettings settings;
  Vec2 gravity;  // [m/s^2]
  bool gravity_set = false;
  int threads = 0;  // 0: OpenMP's default
  std::vector<InsituDef> insitu;         // in order; boundary stress="insitu" uses them
  std::vector<Polygon> insitu_regions;   // their regions resolved (empty: everywhere)
  std::vector<JointMaterialDef> joint_materials;
  std::vector<JointParams> joint_params;  // same order
  std::vector<JassignDef> jassign;        // in order; later ones win
  std::vector<Polygon> jassign_regions;   // their regions resolved (empty: everywhere)
  std::vector<int> jassign_material;      // their joint materials
  // Commands given before the first cycle, replayed after a re-zone.
  std::vector<std::function<void(class Model&)>> replay;
  bool replaying = false;
  bool cycling_now = false;

  // ---- state per mesh zone
  std::vector<int> zone_material;  // -1: none assigned
  std::vector<Stress> stress;
  // Per zone, the mean stress (sxx + syy + szz) / 3 as last initialised (insitu, or zero): the
  // mixed discretisation averages the change from it, so an initial state in equilibrium stays so.
  std::vector<double> mean_stress_ref;
  std::vector<std::uint8_t> zone_state;
  // Per zone, the state variable of its zone law (ZoneLaw::history: ss's plastic shear strain);
  // 0 for laws that keep none. A fresh material (assign of null, excavate, fill) starts it at 0.
  std::vector<double> zone_history;
  // Per zone, the plastic work done in it per unit volume [J/m^3] since it was last cleared
  // (reset{ "state" }, a fresh material): how far it went past its strength, where the state's
  // flags say only that it got there.
  std::vector<double> zone_plastic_work;

  // ---- state per node
  int node_count = 0;
  std::vector<int> gp_node;         // mesh gridpoint -> node
  std::vector<double> position;     // reference [m], 2 per node
  std::vector<double> u, v;         // displacement [m], velocity [m/s]
  // Where u is measured from [m]: the position, moved by the displacement a reset{} cleared, so
  // that origin + u is where the node is now (what contacts and the watchdog look at).
  std::vector<double> origin;
  std::vector<double> force;        // unbalanced force of the last cycle [N/m]
  std::vector<double> load;         // boundary tractions lumped to nodes [N/m]
  std::vector<std::uint8_t> fix;    // bit 0: x held, bit 1: y held
  std::vector<int> node_block;      // a block of the node (for messages)
  // Nodes of bodies solve{ balance } found with no equilibrium near, moved undamped while it runs
  // (empty: none; solver/run.cpp).
  std::vector<char> undamped;
  std::vector<BoundarySegment> boundary;

  // ---- contacts
  ContactBoundary faces;   // the touchable block boundaries (per mesh)
  ContactSet contacts;
  // What a query from a callback saw while the contacts were not current: found on a copy, for
  // the cycle `viewed_cycle` (model/model_contacts.cpp). A cache, not state: not saved.
  ContactSet viewed_contacts;
  long viewed_cycle = -1;

  // ---- potential cracks (state/sections.hpp, crack/judge.hpp)
  std::vector<CrackSeedDef> crack_seeds;  // the model's crackseed{} inputs
  std::vector<Section> sections;
  std::vector<int> edge_section;          // per flat loop edge: its section, or -1
  std::vector<char> edge_glued;           // per flat loop edge: ties its blocks now
  std::vector<CrackView> cracks;          // in the order they broke
  JudgeDef judge;
  // A restored checkpoint's judge{} had a criterion function, which the script must give again.
  bool judge_criterion_missing = false;
  int stage = 0;                          // excavation stage (0: before any)
  std::vector<int> zone_excavated;        // per mesh zone: the stage that excavated it (0: none)
  std::vector<long> stage_cycles;         // per stage, the cycle it was excavated at
  ReleaseLoad release;
  // ---- bolts (state/bolts.hpp, bolt/bolt_coupling.cpp)
  std::vector<BoltMaterialDef> bolt_materials;  // same order as bolts.laws
  BoltSet bolts;
  BoltHosts bolt_hosts;
  bool fresh_cracks = false;              // broken since the last contact detection

  // ---- derived by prepare()
  SectionFits fits;
  bool keep_fits = false;              // the next prepare() keeps them (only nodes changed)
  bool dirty = true;
  // A prepare() of a changed model since the adaptive damping last started: the next cycle starts
  // it again, whoever prepared (a view between cycles must not change the run).
  bool restart_damping = false;
  std::vector<ZoneGeometry> geometry;  // per mesh zone
  std::vector<int> active;             // mesh zones that are cycled (material not null)
  std::vector<char> block_live;        // per mesh block: has an active zone
  // Mixed discretisation: per active position, the other members of its zone group (-1
  // padded; {-1, -1}: alone). Empty when the mixed discretisation is off.
  std::vector<std::array<int, 2>> mates;
  std::vector<double> mass;            // per node, inertial (scaled in static mode) [kg/m]
  std::vector<double> zone_rows;       // per node, Gershgorin row sum of the zone stiffness [N/m^2]
  std::vector<double> real_mass;       // per node [kg/m]
  std::vector<double> stiffness;       // per node, zone_rows + contact rows [N/m^2]
  std::vector<double> weight;          // gravity force, 2 per node [N/m]
  double step = 1.0;                   // time step [s]
  double critical_step = 0.0;          // estimate: 2 min sqrt(m / k) with real masses [s]
  double applied_magnitude = 0.0;      // sum of |weight| + |load| over nodes [N/m]
  Partition partition;
  std::vector<double> acc_force;       // accumulators, 2 per entry
  std::vector<double> u_batch_start;   // u - v dt / 2 when the running batch began (scratch) [m]

  // ---- solver progress
  SolverInfo info;
  long cycles_run = 0;  // cycles since the model was made; > 0 locks geometry
  AdaptiveDamping adaptive;
  double last_kinetic = 0.0;
  int growth_checks = 0;  // consecutive checks with fast kinetic energy growth
  int growth_span = 0;    // cycles since last_kinetic was taken
  std::vector<Callback> callbacks;
  int next_handle = 1;
  std::function<void(const RunProgress&)> progress;  // reports a long run (Model::set_progress)
  const std::atomic<int>* stop = nullptr;            // cycling ends when it is non-zero (Model::set_stop)
  std::function<void(const std::string&)> notice;    // says something once about a run (Model::set_notice)
  ThreadWatch thread_watch;                          // how the threads are doing (runtime only)
  std::function<void(const PrepassProgress&)> prepass_progress;  // every progress_every [s] of a prepass
  double progress_every = 0.0;                       // [s] between reports; 0: none
  std::vector<History> histories;
  EnergyLedger energy;  // the energy balance (state/energy_ledger.hpp)
};

// The threads asked for: set_threads's, else OpenMP's default.
int asked_threads(const Mechanics& m);

// The number of threads cycling would use unwatched: OpenMP's (or the model's own) for a model
// with enough work for them.
int wanted_threads(const Mechanics& m);

// The number of threads cycling uses: the wanted ones, fewer while the thread watch has found
// that a smaller team is faster (solver/thread_watch.hpp).
int thread_count(const Mechanics& m);

}  // namespace edem
