// Definitions of the mechanical inputs (materials, loads, boundaries, solver settings) and the
// read-only views a script gets back, as the command language fills and reads them.
//
// Plain data with defaults and units; the interpreter checks types and ranges against its
// schema, the Model checks what needs the model (names, regions, consistency). Stresses are
// compression negative [Pa]; angles in degrees.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/vec2.hpp"
#include "core/defs.hpp"

namespace edem {

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

// A zone law's id: its position in the registry (constitutive/zone_laws.cpp). The enumerators
// name the first laws there; the registry may hold more, named by no enumerator.
enum class MaterialModel : std::uint8_t { elastic, mohr, null };

// A piecewise-linear table of a zone law's parameter: {abscissa, value} pairs.
using ZoneTable = std::vector<std::array<double, 2>>;

// A table key of a zone law as given (material{ cohesion_table = ... }).
struct ZoneLawTable {
  std::string key;
  ZoneTable points;
};

struct MaterialDef {
  std::string name;
  MaterialModel model = MaterialModel::elastic;
  double density = 0.0;     // [kg/m^3]
  double young = kUnset;    // Young's modulus [Pa]; with poisson, or give bulk and shear
  double poisson = kUnset;  // [-]
  double bulk = kUnset;     // bulk modulus [Pa]
  double shear = kUnset;    // shear modulus [Pa]
  // Strength, mohr only (unset: 0; the model keeps it so, with_strength_defaults).
  double cohesion = kUnset;  // [Pa]
  double friction = kUnset;  // [deg]
  double dilation = kUnset;  // [deg], at most friction
  double tension = kUnset;   // tensile strength [Pa]; capped at cohesion / tan(friction)
  std::vector<ZoneLawTable> tables;  // the law's table keys given, by key (zone_law.hpp)
};

// How a joint's normal stress grows with closure.
enum class NormalLaw : std::uint8_t {
  linear,      // sn = kn * closure
  table,       // kn by stages of closure (kn_table)
  seed_cubic,  // the seed paper's lab curve, clamped (contact/joint_law.hpp)
};

// A joint material: the law of the contacts along joints and cracks (contact/joint_law.hpp).
struct JointMaterialDef {
  std::string name;
  double kn = kUnset;      // normal stiffness [Pa/m] (linear law; optional with a table)
  double ks = kUnset;      // shear stiffness [Pa/m]
  double friction = 0.0;   // [deg]
  double cohesion = 0.0;   // [Pa], drops to residual_cohesion once the contact slips or opens
  double tension = 0.0;    // tensile strength [Pa], lost likewise (no residual tension)
  double residual_cohesion = 0.0;      // [Pa], at most cohesion
  double residual_friction = kUnset;   // [deg], unset: friction
  double dilation = 0.0;   // [deg], at most friction
  // Softening instead of the drop (joint_law.hpp): the energy per unit area the bond takes to
  // break in opening and in slip [J/m^2]; 0: it drops at once.
  double fracture_energy = 0.0;
  double shear_fracture_energy = 0.0;
  NormalLaw law = NormalLaw::linear;
  // A named law scaled by similarity: sn = stress_scale * f(closure / closure_scale), so that
  // its stiffnesses go by stress_scale / closure_scale (a lab curve read at prototype scale).
  double law_stress_scale = 1.0;
  double law_closure_scale = 1.0;
  // Stages {closure from [m], kn [Pa/m]}: closures increasing from 0.
  std::vector<std::array<double, 2>> kn_table;
};

// Gives contacts a joint material by what made their edge: a joint set (set >= 0, 0-based),
// a kind ("joint", "crack"), a region (edges whose midpoint is inside); all that are given
// must hold. Later assignments win.
struct JassignDef {
  std::string material;
  int set = -1;
  std::string kind;
  RegionRef region;
};

// Gives the zones inside `region` (all zones when empty) the material `material`.
struct AssignDef {
  std::string material;
  RegionRef region;
};

// Excavation of a region (solver/excavation.cpp): its zones turn null, as UDEC 7 does.
struct ExcavateDef {
  RegionRef region;
  int block = -1;    // or a block (0-based): a loose block taken out (mucked out) wherever it is
  long release = 0;  // cycles over which the excavated rock's forces are taken off (0: at once)
};

// Backfill of excavated zones in a region with a material, stress-free.
struct FillDef {
  RegionRef region;
  std::string material;
};

// A bolt material (bolt/bolt_law.hpp): one bolt's values, as a user gives them [SI]; forces and
// stiffnesses in the model are these divided by `spacing` (per metre of thickness).
struct BoltMaterialDef {
  std::string name;
  double young = kUnset;              // [Pa]
  double area = kUnset;               // [m^2]
  double density = 7850.0;            // [kg/m^3]
  double yield_tension = kUnset;      // [N]
  double yield_compression = kUnset;  // [N], positive; unset: yield_tension
  double failure_strain = kUnset;     // [-]
  double bond_stiffness = kUnset;     // [N/m per m of bolt]
  double bond_strength = kUnset;      // [N/m]
  double spacing = 1.0;               // out of the plane [m]
};

// A straight grouted bolt from its head (`from`, at the wall) to its end (`to`, in the rock).
struct BoltDef {
  Vec2 from, to;
  int segments = 0;                // over the grouted length; 0: from segment_length
  double segment_length = kUnset;  // [m]
  double free_length = 0.0;        // ungrouted length from the head [m]
  std::string material;
};

// What holds a bolt's head: a jack pulling it out of the hole at `velocity` [m/s; m per cycle in
// static mode], a constant pull `force` [N per bolt], or nothing (both unset: free again).
struct BoltHeadDef {
  int bolt = -1;  // 0-based
  double velocity = kUnset;
  double force = kUnset;
};

// A bolt segment as bolts() shows it.
struct BoltSegmentView {
  Vec2 a, b;              // current positions of its ends [m]
  double force = 0.0;     // axial, tension positive [N per m of thickness]
  double strain = 0.0;    // elongation / rest length [-]
  double slip = 0.0;      // bolt against rock along the axis, mean of its ends [m]
  double plastic_slip = 0.0;  // the grout's plastic part of it [m]
  std::string state;          // "elastic", "yielded", "broken", "removed" (an end's rock is gone)
  bool broke = false;         // it has broken, also if it was removed with its rock since
};

struct BoltView {
  int id = -1;              // 0-based
  std::string material;
  int stage = 0;            // the excavation stage when it was installed
  Vec2 head, end;           // as installed [m]
  double length = 0.0;      // [m]
  double head_force = 0.0;  // axial pull on the head [N per m of thickness]
  bool removed = false;     // none of its rock is left (excavated, mucked out): out of service
  std::vector<BoltSegmentView> segments;
};

// Initial stresses. Either a field sxx.. + ygrad * y, or (from_surface) the lithostatic state
// sv = -(surcharge + density * g * (surface - y)), sh = szz = k0 * sv.
struct InsituDef {
  bool from_surface = false;
  // field form [Pa], ygrad [Pa/m]: s(y) = s0 + ygrad * y
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  double szz = kUnset;                 // unset: equal to sxx
  std::array<double, 4> ygrad{};       // d/dy of sxx, syy, sxy, szz [Pa/m]
  // surface form
  double surface = 0.0;    // y of the ground surface [m]
  double density = 0.0;    // [kg/m^3]
  double k0 = 1.0;         // horizontal over vertical stress [-]
  double surcharge = 0.0;  // vertical stress at the surface, positive for a load [Pa]
  double gravity = 9.81;   // [m/s^2]; the Model uses |gravity{}| when one is set
  RegionRef region;        // only zones inside it (empty: all)
};

// Conditions on the model's outer boundary gridpoints: those on one side of its bounding box,
// or those inside a polygon.
struct BoundaryDef {
  std::string side;  // "left", "right", "top", "bottom", or empty with `polygon`
  Polygon polygon;
  // traction from a stress tensor [Pa]; or from the in-situ field (stress_insitu)
  std::optional<std::array<double, 3>> stress;  // sxx, syy, sxy
  bool stress_insitu = false;
  std::string fix;   // "", "x", "y", "xy": hold these velocity components
  std::string free;  // "", "x", "y", "xy": release these (and their applied velocity)
  double xvel = kUnset;  // held x velocity [m/s] (implies fix x)
  double yvel = kUnset;  // held y velocity [m/s] (implies fix y)
};

enum class SolverMode : std::uint8_t { static_, dynamic };
enum class Damping : std::uint8_t { adaptive, local, none };

struct SolverSettings {
  SolverMode mode = SolverMode::static_;
  Damping damping = Damping::adaptive;  // static mode; dynamic mode has none unless asked
  double local_damping = 0.8;           // coefficient of local damping [-]
  double step = 0.0;                    // forced time step [s] (dynamic); 0: automatic
  double step_fraction = 0.9;           // automatic step over the critical estimate [-]
  // Mixed discretisation over pairs of zones (see solver/cycle.cpp): no volumetric locking.
  // Off by default: with non-associated flow its zones localise more readily (Salencon psi = 0).
  bool mixed = false;
  // The overlap watchdog's limit: a gridpoint deeper than this inside another block stops the run
  // [m]; 0: half the median length of the blocks' touchable edges (UDEC's rounding is a length
  // of this kind) plus the largest closure a joint law follows its measured curve over (0.41 m
  // for the seed's curve x 400).
  double overlap = 0.0;
};

struct SolveDef {
  double ratio = 1e-5;        // stop when the unbalanced-force ratio is at most this [-]
  long max_cycles = 100000;   // and stop after this many cycles whatever the ratio
  long stall = 0;             // and after this many without the ratio falling a tenth (0: never)
  double settle = 0.0;        // a state at the ratio then solved on to this under adaptive damping (0: not)
  double balance = 0.0;       // and no body more out of balance than this (solver/body_balance.hpp; 0: not asked)
};

// A body with more than this share of the forces on it unbalanced, in a state the ratio calls
// converged, is out of balance: a settled body's share falls with the ratio (6e-4 at 1e-7 on
// tests/verification/unbalanced_body.lua's block), one that slides keeps its own (0.36 there).
inline constexpr double kBodyOutOfBalance = 0.01;

struct SolveResult {
  long cycles = 0;         // cycles done by this solve
  double ratio = 0.0;      // ratio reached
  bool converged = false;
  // With judge{ at = "equilibrium" }: the judgments made on equilibrium states (each that broke
  // sections, and the last, which broke none, if the solve converged) and the sections broken.
  int judgments = 0;
  int broke = 0;
  // Stopped short of the ratio with sections intact: its last state was not judged.
  bool unjudged = false;
  // Stopped at the end of a cycle because the stop flag was raised (Model::set_stop).
  bool interrupted = false;
  // Stopped because the ratio had not fallen a tenth below its lowest in `stall` cycles: the model
  // keeps moving without coming nearer to an equilibrium.
  bool stalled = false;
  // At the solve's end: the body (rock its zones and intact sections join) whose net unbalanced
  // force is the largest share of the forces holding it (solver/body_balance.hpp), one of its
  // blocks and where a node of it is.
  double body_share = 0.0;
  int body_block = -1;
  Vec2 body_at{};
};

// Where a long cycle() or solve{} stands, for a progress line (Model::set_progress).
struct RunProgress {
  long cycle = 0;         // the model's cycle count
  long run_cycles = 0;    // cycles of this run so far
  long max_cycles = 0;    // its limit
  double ratio = 0.0;     // unbalanced-force ratio now
  double target = 0.0;    // the ratio solve{} runs to; 0 for cycle()
  long cracks = 0;        // new cracks so far
  int stage = 0;          // excavation stage
  double seconds = 0.0;   // wall clock since the run started
  // What can make the ratio jump between two reports: contacts that slip or open, a release.
  long slipping = 0;      // contacts slipping now
  long open = 0;          // contacts open now
  long releasing = 0;     // cycles an excavation's release still has to go
};

// Where a long prepass{} stands, for a progress line (Model::set_prepass_progress).
struct PrepassProgress {
  std::string stage;       // "present state", or the stage's region
  int index = 0, count = 0;  // the stage's place (0: the present state) and the stages to solve
  double load = 0.0;       // load factor of the stage reached so far
  int iterations = 0;      // Newton iterations of the whole prepass so far
  double seconds = 0.0;    // wall clock since the prepass started
};

// Zone state flags (bits): failing now and failed in the past, in shear and in tension.
enum ZoneState : std::uint8_t {
  kShearNow = 1,
  kTensionNow = 2,
  kShearPast = 4,
  kTensionPast = 8,
};
// "elastic", "shear", "tension", "shear-past", "tension-past", "shear tension" ...
std::string zone_state_name(std::uint8_t state);

struct GridpointView {
  int id = -1;     // 0-based mesh gridpoint
  Vec2 position;   // reference position [m]
  Vec2 u;          // displacement [m]
  Vec2 v;          // velocity [m/s]
  Vec2 f;          // unbalanced force of the last cycle [N/m]
  bool fixed_x = false, fixed_y = false;
};

// A contact between a gridpoint and the edge of another block (state/contacts.hpp).
struct ContactView {
  int id = -1;            // 0-based
  Vec2 position;          // the gridpoint's current position [m]
  Vec2 normal;            // unit normal of the contact plane, out of the edge's block [-]
  double length = 0.0;    // contact length [m]
  double fn = 0.0, fs = 0.0;  // normal (compression negative) and shear force [N/m]
  double un = 0.0;        // normal displacement, opening positive [m]
  // How far its gridpoint is inside the edge's block, less a given prestress's closure (what
  // the overlap watchdog measures; negative: a gap) [m].
  double overlap = 0.0;
  double us = 0.0;        // shear displacement since the contact formed [m]
  double slip = 0.0;      // plastic part of it, accumulated as a length [m]
  std::string state;      // "bonded", "elastic", "slip", "open"
  std::string kind;       // "joint", "crack"
  std::string material;
  int block = -1, other = -1;  // the gridpoint's block and the edge's block, 0-based
  // One of a corner's two contacts with the other block, each on its own face (a gridpoint in a
  // concave corner of that block), and which: face 0 or 1 (0 for a contact on its own).
  bool corner = false;
  int face = 0;
  // The energy it made since the balance started, while contacts book their own (energy{
  // by_contact = true }) [J/m]; NaN otherwise.
  double energy_made = std::numeric_limits<double>::quiet_NaN();
};

// How far a block has moved and whether it is still there (Model::block_motion).
struct BlockMotion {
  double max_displacement = 0.0;  // the largest displacement of its gridpoints [m]
  int excavated = 0;              // the last stage that excavated its zones, 0 while any is in place
};

struct ZoneView {
  int id = -1;          // 0-based zone
  Vec2 centroid;        // [m]
  double sxx = 0, syy = 0, sxy = 0, szz = 0;  // [Pa]
  double s1 = 0, s3 = 0;                      // in-plane principal, s1 <= s3 [Pa]
  std::uint8_t state = 0;
  std::string material;  // "" when none assigned
  int excavated = 0;     // the stage that excavated it (0: in place)
  // The state variable of its zone law, when the law keeps one (ZoneLaw::history): its name
  // ("" when none) and value.
  std::string history_name;
  double history = 0.0;
  double plastic_work = 0.0;  // done in it per unit volume since its state was cleared [J/m^3]
};

// How a potential-crack section broke (crack/criteria.hpp).
enum class CrackMode : unsigned char { none, shear, tension };

// The intact rock's strength that judges a section.
struct RockStrength {
  double cohesion = 0.0;  // [Pa]
  double friction = 0.0;  // [deg]
  double tension = 0.0;   // tensile strength [Pa], >= 0
};

// A potential-crack section as a crack criterion sees it (judge{ criterion = ... }): the fitted
// stress at its calculation point and the rock's strength there.
struct SectionView {
  int id = -1;            // 0-based section
  Vec2 position;          // calculation point [m]
  double angle = 0.0;     // direction of the section, [0, 180) from +x [deg]
  double length = 0.0;    // [m]
  double sxx = 0, syy = 0, sxy = 0;  // fitted stress at the point [Pa]
  double s1 = 0, s3 = 0;  // in-plane principal, s1 <= s3 [Pa]
  double sn = 0;          // normal stress on the section, compression negative [Pa]
  double tau = 0;         // shear stress on it (along the direction `angle`) [Pa]
  RockStrength strength;  // cohesion [Pa], friction [deg], tension [Pa]
  // How far the stress is towards the built-in criteria: the larger of s3 / tension and the Mohr
  // circle's radius over the shear strength at its centre (1 breaks it; judge{ most } ranks by it).
  double overstress = 0;
  // Its rock dug or mucked out on both sides: no stress to fit (its stress, strength and
  // overstress are zero), and never judged.
  bool gone = false;
};

// A section that broke: a new crack.
struct CrackView {
  int id = -1;            // 0-based, in the order they broke
  int section = -1;       // 0-based section
  Vec2 position;          // midpoint [m]
  double angle = 0.0;     // [0, 180) from +x [deg]
  double length = 0.0;    // [m]
  CrackMode mode = CrackMode::none;
  long cycle = 0;         // the cycle of the judgment that broke it
  int stage = 0;          // the excavation stage then
  double sxx = 0, syy = 0, sxy = 0;  // the fitted stress that broke it [Pa]
};

// When sections are judged: every n cycles while the model moves (the seed's way), or only on
// states of equilibrium, each time a solve reaches its ratio, and again after each round of breaks
// until a round breaks none (what breaks then does not depend on how fast loads were applied).
enum class JudgeAt : std::uint8_t { cycles, equilibrium };

// How sections are judged: when (`at`, `every`), by the built-in criteria (crack/criteria.hpp)
// or by `criterion`.
struct JudgeDef {
  JudgeAt at = JudgeAt::cycles;
  long every = 10;  // cycles between judgments with at = cycles
  // At most this many sections break at one judgment, those furthest past the built-in criteria
  // first (crack/criteria.hpp, overstress); the rest wait for the next. 0: every one that fails.
  long most = 0;
  // A failing section waits while a failing section it touches is further past its strength
  // (crack/judge.cpp): of a row of neighbours, the worst breaks and the rest are judged again on
  // the state its breaking leaves. True by default at equilibrium; the seed breaks all at once.
  bool neighbours_wait = false;
  // The stress at a section is fitted to the zones of its two blocks whose centroids lie within
  // this distance of its point [m], besides the four nearest each side that the seed uses: a
  // length of the rock's, not of the mesh's, so that finer zones judge the same averaged stress
  // (crack/judge.cpp). 0: the four nearest each side only.
  double radius = 0.0;
  std::function<CrackMode(const SectionView&)> criterion;  // empty: built in
};

// A history: a quantity sampled every `every` cycles.
struct HistoryDef {
  std::string name;
  long every = 10;
  std::function<double()> sample;  // evaluated between cycles
  std::string unit = "-";          // for the CSV header
  // A built-in quantity (Model::history_sampler) and its point, so that a restored checkpoint
  // can sample it again; empty for a script's function.
  std::string quantity;
  std::optional<Vec2> at;
};

struct History {
  std::string name;
  long every = 10;
  std::function<double()> sample;  // empty in a restored model until the script gives its fn again
  std::string unit;
  std::string quantity;
  std::optional<Vec2> at;
  std::vector<long> cycles;
  std::vector<double> values;
  // What a point quantity follows: a node (ux, uy, vx, vy, joint_*) or a zone (stresses); -1: none.
  int node = -1;
  int zone = -1;
  // Why it records no more (its rock was excavated); empty while it records.
  std::string ended;
};

struct SolverInfo {
  long cycle = 0;
  double time = 0.0;   // [s] (static mode: cycles, with a step of 1)
  double step = 0.0;   // [s]
  double ratio = 0.0;  // last measured unbalanced-force ratio [-]
  double kinetic = 0.0;  // last measured kinetic energy [J/m]
  double damping_rate = 0.0;  // adaptive damping's c = 2 omega as last set [1/s]; 0 under local or none
  int contacts = 0;      // contacts as last found (0 until found: first cycle or query)
  long late_contacts = 0;  // contacts found already pressed in (ContactSet::late)
  long contact_searches = 0;  // gridpoints searched for contacts (ContactSet::searched)
  int threads = 1;  // the threads cycling uses (before the first cycle: those it may use)
};

}  // namespace edem
