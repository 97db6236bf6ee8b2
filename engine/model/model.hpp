// The Model: owns every input and every derived store of one EDEM model.
//
// Geometry commands append inputs; the blocks (arrangement of all cuts) and the zones are
// derived from the inputs. A geometry command after zone{} re-cuts and re-zones with the same
// zoning requests. Every mutating call validates and derives first, and changes nothing when
// it throws.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "crack/auto_placement.hpp"
#include "geom/block_set.hpp"
#include "geom/mesh.hpp"
#include "geom/zoning.hpp"
#include "core/defs.hpp"
#include "core/physics_defs.hpp"
#include "prepass/prepass.hpp"
#include "solver/energy.hpp"

namespace edem {

struct CutInput;  // geom/cutter.hpp


struct Mechanics;  // state/mechanics.hpp: materials, loads and the solver's arrays
struct FieldFrame;  // io/field_output.hpp

class Model {
 public:
  explicit Model(ModelDef def = {});
  ~Model();
  Model(Model&&) noexcept;
  Model& operator=(Model&&) noexcept;

  const std::string& title() const { return def_.title; }

  // Geometry inputs.
  void add_block(const BlockDef& def);
  int add_joint_set(const JointSetDef& def);  // returns the set's index (0-based)
  void add_crack(const CrackDef& def);
  void add_region(const RegionDef& def);
  void add_crackseed(const CrackSeedDef& def);  // potential cracks (state/sections.hpp)
  // Potential cracks where a prepass found yielding (crack/auto_placement.hpp), in one rebuild: one
  // crack seed per group of yielded zones. Returns the groups placed.
  std::vector<CrackRegion> add_auto_crackseed(const AutoCrackSeedDef& def);
  void zone(const ZoneDef& def);

  // Derived stores.
  const BlockSet& blocks() const { return blocks_; }
  const Mesh& mesh() const { return mesh_; }
  bool zoned() const { return !inputs_.zone_requests.empty(); }
  ModelInfo info() const;

  // Named regions.
  const std::vector<RegionDef>& regions() const { return inputs_.regions; }
  int region_index(std::string_view name) const;  // throws, with a did-you-mean hint
  Polygon resolve(const RegionRef& ref) const;     // the polygon of a name or polygon
  // Zones of a region: of the blocks inside a named region, or whose centroid lies inside a
  // polygon; every zone for an empty reference (model/model_mechanics.cpp).
  std::vector<int> zones_in(const RegionRef& ref) const;

  int joint_set_count() const { return static_cast<int>(inputs_.joint_sets.size()); }
  double tolerance() const;  // absolute geometric tolerance [m]

  // ---- Mechanics (model/model_mechanics.cpp). Commands given before the first cycle are replayed
  // on the new zones when a geometry command re-zones the model; geometry commands after the
  // first cycle are an error. Each call validates everything before it changes anything.

  void add_material(const MaterialDef& def);          // redefining a name changes its zones too
                                                       // (but not to or from "null")
  void assign(const AssignDef& def);                   // needs zones
  void add_joint_material(const JointMaterialDef& def);  // redefining a name changes its contacts
  void jassign(const JassignDef& def);                 // needs zones
  void set_gravity(Vec2 g);                            // [m/s^2]
  void insitu(const InsituDef& def);                   // sets zone stresses (needs zones)
  void boundary(const BoundaryDef& def);               // needs zones
  void set_solver(const SolverSettings& settings);
  const SolverSettings& solver_settings() const;
  void set_threads(int threads);  // OpenMP threads for cycling; 0: OpenMP's default
  // `report` is called during cycle() and solve{} each time `every_seconds` of wall clock have
  // passed (never for a shorter run); a null function or 0 seconds: no reports.
  void set_progress(std::function<void(const RunProgress&)> report, double every_seconds);
  // `report` is called during prepass{} after a load step each time the progress interval has
  // passed (set_progress's); null: no reports.
  void set_prepass_progress(std::function<void(const PrepassProgress&)> report);
  // What a run says once about itself while cycling (it took fewer threads than asked).
  void set_notice(std::function<void(const std::string&)> say);
  // Cycling ends at the end of the cycle running when `*flag` turns non-zero (a signal's number:
  // Ctrl-C), with SolveResult::interrupted; null: never. The flag must outlive the model.
  void set_stop(const std::atomic<int>* flag);
  // Excavation (model/model_excavation.cpp): the zones of a region turn null and the stage count
  // goes up; fill{} gives excavated zones of a region a material again, stress-free.
  void excavate(const ExcavateDef& def);
  void fill(const FillDef& def);
  int stage() const;  // excavations so far (0: none)
  const std::vector<long>& stage_cycles() const;  // the cycle each stage was excavated at, in order
  // Bolts (model/model_bolts.cpp). A bolt is laid in the rock as it stands now, and goes out of
  // service when its ground is excavated; forces are per metre of thickness (/ spacing).
  void add_bolt_material(const BoltMaterialDef& def);  // redefining a name is an error
  int add_bolt(const BoltDef& def);                    // returns the bolt's index (0-based)
  void bolt_head(const BoltHeadDef& def);
  int bolt_count() const;
  BoltView bolt(int id) const;
  std::vector<std::string> bolt_material_names() const;
  // What reset() zeroes: gridpoint (and bolt) displacements, velocities, zones' plastic state
  // flags, and the contacts' shear displacement and slip records (UDEC's RESET JDISP: forces and
  // closures are kept, so the model stays in equilibrium).
  struct ResetWhat {
    bool displacement = false, velocity = false, state = false, joint = false;
  };
  void reset(const ResetWhat& what);

  // Cycling. Throws edem::Error when the model is not ready (no zones, a zone without
  // material) or when the watchdog stops an unstable run (the model stays at that cycle).
  // Exceptions thrown by callbacks and history samplers pass through unchanged.
  SolveResult cycle(long count);
  SolveResult solve(const SolveDef& def);
  // The implicit elastoplastic prepass (model/model_prepass.cpp): solves the present state and
  // then each stage excavated in turn, on copies; the model itself is left as it was.
  PrepassResult prepass(const PrepassDef& def);
  // Per mesh zone, the yield bits (kShearNow | kTensionNow) the last prepass{} found over all its
  // stages; empty before any (for plot{ show = {"prepass"} }).
  const std::vector<std::uint8_t>& prepass_yield() const { return prepass_yield_; }
  // The last prepass{} result on the present zones (kept, and saved in checkpoints), if any.
  const std::optional<PrepassResult>& last_prepass() const { return last_prepass_; }
  SolverInfo solver_info() const;
  // The energy balance since the first cycle or the last reset_energy() (solver/energy.hpp).
  EnergyReport energy() const;
  void reset_energy();  // the balance starts again from the state now
  // Whether each contact keeps its own balance from now (ContactView::energy_made).
  void book_energy_by_contact(bool on);
  bool cycling_started() const;
  // Why the model would fall as a whole when cycled (gravity acts and no gridpoint is held), or
  // empty: said as a warning before its first cycle.
  std::string unheld() const;
  bool cycling_now() const;  // inside cycle() or solve(), e.g. while a callback runs

  // Callbacks run after every cycle whose number is a multiple of `every`; returns a handle.
  int add_callback(long every, std::function<void(long cycle)> fn);
  void cancel_callback(int handle);  // throws for an unknown or cancelled handle

  // Histories, sampled after every cycle whose number is a multiple of their `every`: a script's
  // function (def.sample) or a built-in quantity (def.quantity) of the whole model
  // (history_model_quantities()) or at def.at (history_point_quantities(): the nearest
  // gridpoint's ux, uy, vx, vy, rock in place first; the stresses sxx, syy, sxy, szz, s1, s3 of
  // the zone containing it; the joint_* quantities of the contact nearest to it, followed by its
  // gridpoint, 0 while that has none). A point history follows its rock: when an excavation
  // takes its gridpoint it goes on at the gridpoint of rock at the same place (across the
  // excavation's outline; a note), or else it ends (History::ended; a warning).
  int add_history(HistoryDef def);
  // A built-in quantity's value now (one sample, as a history would take it).
  std::function<double()> history_sampler(std::string_view quantity,
                                          std::optional<Vec2> at) const;
  // Finds what a history of a built-in quantity follows (when not known yet) and gives it its
  // sampler (also for a restored one).
  void follow(History& h) const;
  static const std::vector<std::string>& history_model_quantities();
  static const std::vector<std::string>& history_point_quantities();
  static std::string history_unit(std::string_view quantity);  // "m", "Pa", "-", ...
  const std::vector<History>& histories() const;
  void write_histories(const std::string& path) const;  // CSV, one column per history

  // Read-only views; ids are 0-based mesh gridpoints and zones.
  int gridpoint_near(Vec2 point) const;  // -1 when there are no gridpoints
  int zone_at(Vec2 point) const;         // -1 when no zone contains the point
  GridpointView gridpoint(int id) const;
  ZoneView zone_view(int id) const;
  BlockMotion block_motion(int block) const;  // 0-based block; all zero for a block not zoned
  // Blocks come loose (0-based, ascending): those in place that, with the blocks glued to them,
  // have no gridpoint held and no contact pressed against another block (falling), or whose
  // gridpoints' mean speed is above `speed` (moving; 0: that test is left out) [m/s, m per cycle
  // in static mode]. What mucking out takes, where a displacement would take rock still in place
  // under soft joints.
  std::vector<int> loose_blocks(double speed) const;
  // Contacts as last found (found now if cycling has not begun); ids are 0-based positions.
  int contact_count() const;
  // How many contacts there are now, found on a copy if the model changed since they were last
  // found, so that asking does not change how the run goes on (info().contacts).
  int contacts_now() const;
  ContactView contact(int id) const;
  int contact_near(Vec2 point) const;  // -1 when there are none
  std::vector<std::string> joint_material_names() const;

  // ---- Checkpoints (model/checkpoint.cpp, io/checkpoint_file.hpp): the whole model in one HDF5
  // file, so that a restored model cycles on bit for bit as the saved one would have. Lua
  // functions are not saved: after restore the script registers its callbacks again, and gives
  // fn histories and a judge criterion again (cycling refuses to start until it has). A save from
  // a callback while cycling holds the state at the end of that cycle (the energy balance's
  // stored energy is taken before callbacks run), so periodic checkpoints of one cycle() go on bit
  // for bit. A restored model's geometry is fixed.
  void save(const std::string& path, const CheckpointNote& note) const;
  static Model restore(const std::string& path, CheckpointNote* note = nullptr);

  // The model as it stands, for field output (model/field_frame.cpp, io/field_output.hpp).
  FieldFrame field_frame() const;

  // What the calls since the last take have to tell the script: a note (a history went on at
  // the rock across an excavation's outline) or a warning (likely not what the script meant: a
  // history whose rock was excavated ended). Said once each, with the script line, by the
  // interpreter.
  struct Notice {
    bool warning = false;
    std::string text;
  };
  std::vector<Notice> take_notices();

  // ---- Potential cracks (model/model_cracks.cpp).
  void judge(const JudgeDef& def);     // how and how often sections are judged
  int section_count() const;           // potential-crack sections (known once zoned)
  SectionView section(int id) const;   // with the fitted stress of now (prepares the model)
  int crack_count() const;             // sections broken so far
  const CrackView& crack(int id) const;
  std::vector<std::string> material_names() const;

 private:
  struct ZoneRequest {
    SizeField size;
    double sliver = 0.0;             // ZoneDef::sliver
    int region = -1;                 // only blocks in this named region (-1: see polygon)
    std::optional<Polygon> polygon;  // only blocks whose centroid is inside it
  };
  // Everything the geometry is derived from.
  struct Inputs {
    std::vector<BlockDef> bases;
    std::vector<JointSetDef> joint_sets;
    std::vector<CrackDef> cracks;
    std::vector<CrackSeedDef> crack_seeds;
    std::vector<RegionDef> regions;
    std::vector<ZoneRequest> zone_requests;
  };

  // Derive blocks (and the mesh, if zoned) from `next` and only then make it current, so a
  // command that fails leaves the model as it was.
  void commit(Inputs next);
  BlockSet cut(const Inputs& inputs) const;
  // Throws when the cuts of `input` would make more than def_.max_blocks blocks.
  void check_block_count(const Inputs& inputs, const CutInput& input) const;
  Mesh zone_all(const Inputs& inputs, const BlockSet& blocks) const;
  // Per block, the size field of the last zone request that covers it (nullptr: none).
  std::vector<const SizeField*> size_fields(const Inputs& inputs, const BlockSet& blocks) const;
  double tolerance_of(const Inputs& inputs) const;
  void check_geometry_open() const;  // throws once cycling has begun
  // target <= 0: no ratio stop; stall > 0: stop after that many cycles without progress (SolveDef)
  SolveResult run(long max_cycles, double target_ratio, long stall = 0, double settle = 0.0,
                  double balance = 0.0);
  Polygon resolve_in(const Inputs& inputs, const RegionRef& ref) const;
  void add_crack_counts(ModelInfo& info) const;
  void follow_histories_past_excavation();  // model/model_mechanics.cpp

  ModelDef def_;
  Inputs inputs_;
  BlockSet blocks_;
  Mesh mesh_;
  std::unique_ptr<Mechanics> mechanics_;
  std::vector<std::uint8_t> prepass_yield_;
  std::optional<PrepassResult> last_prepass_;
  bool restored_ = false;  // made by restore(): its geometry inputs cannot be re-derived
  std::vector<Notice> notices_;  // take_notices()

  friend struct CheckpointAccess;  // model/checkpoint.cpp
};

}  // namespace edem
