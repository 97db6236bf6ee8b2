// Definitions of geometry inputs, as the command language fills them (units in comments).
//
// Each XxxDef is plain data with defaults; the interpreter validates ranges and types
// against its schema, the Model validates what needs the model (names, geometry).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/vec2.hpp"

namespace edem {

// A region given by name (a region{} cut earlier) or by a polygon.
struct RegionRef {
  std::string name;  // non-empty: a named region
  Polygon polygon;   // used when name is empty
  bool empty() const { return name.empty() && polygon.empty(); }
};

struct ModelDef {
  std::string title;
  double tolerance = 1e-9;  // geometric tolerance, relative to the model's extent [-]
  double max_blocks = 1e5;  // most blocks the joint sets, cracks and crack seeds may cut [-]
};

struct BlockDef {
  Polygon polygon;  // [m]
};

struct JointSetDef {
  double angle = 0.0;                 // counter-clockwise from +x [deg]
  std::vector<double> spacing{1.0};   // normal distance between traces, used in turn [m]
  Vec2 origin;                        // a point on one joint [m]
  double trace = std::numeric_limits<double>::infinity();  // trace length [m]
  double gap = 0.0;                   // gap between traces along a joint [m]
  double angle_dev = 0.0;             // uniform random deviation of each trace's angle [deg]
  double spacing_dev = 0.0;           // uniform random deviation of each spacing [m]
  double trace_dev = 0.0;             // uniform random deviation of each trace length [m]
  double gap_dev = 0.0;               // uniform random deviation of each gap [m]
  std::uint64_t seed = 1;             // random stream of the deviations
  RegionRef region;                   // only inside this region (empty: everywhere)
};

struct CrackDef {
  Vec2 from, to;  // [m]
};

// Potential cracks (seed paper §2.2): sets of parallel cuts with the intact rock's strength,
// tied shut until a section of them fails (state/sections.hpp).
struct CrackSeedDef {
  RegionRef region;            // only inside this region (empty: everywhere)
  std::vector<double> angles;  // one set of parallel cuts per angle, from +x [deg]
  double spacing = 1.0;        // normal distance between cuts [m]
  Vec2 origin;                 // a point on one cut of each set [m]
  std::string material;        // rock material whose c, phi, sigma_t judge it ("": the zone's)
  std::string after;           // joint material its cracks take ("": the joints')
  // Cuts placed as given (crackseed{ auto }), instead of sets of parallel lines at `angles`.
  std::vector<std::array<Vec2, 2>> cuts;
  std::vector<std::array<Vec2, 2>> outline;  // glued cuts the `cuts` end on (auto)
  // Auto: where a cut meets another edge at a corner sharper than this, its stretch there is
  // cut back to the crossings either side [deg] (0: never).
  double min_angle = 0.0;
};

// A zone of a prepass result, as crackseed{ auto = } reads it back from the script.
struct PrepassZone {
  int zone = -1;            // mesh zone
  Vec2 centroid;            // where the prepass had it [m]
  bool shear = false;       // yielded in shear at some stage
  bool tension = false;     // yielded in tension at some stage
  bool excavated = false;   // gone by the prepass's last stage
  double angle = 0.0;       // direction of the most compressive principal stress at the end [deg]
};

struct AutoCrackSeedDef {
  std::vector<PrepassZone> zones;
  double spacing = 0.0;   // between the cuts of a set [m]; 0: a tenth of the opening's height
  double similar = 15.0;  // largest difference of principal direction within a group [deg]
  double min_angle = 0.0;  // corners sharper than this are not made (CrackSeedDef::min_angle) [deg]
  std::optional<Vec2> origin;  // on one cut of every set of every group (none: each group's centroid)
  bool by_mode = false;   // groups keep to one failure mode (else: one direction, mode by area)
  RegionRef region;       // only zones inside it (empty: all)
  std::string material;   // as CrackSeedDef's; its friction also sets the shear sets' angles
  std::string after;
};

struct RegionDef {
  std::string name;
  Polygon polygon;    // [m]
  bool glued = true;  // outline cuts never fail or slide
};

struct ZoneDef {
  double edge = 1.0;               // edge length near `near` [m]
  double far = 0.0;                // edge length far away; 0: same as edge [m]
  double growth = 0.2;             // size increase per metre of distance [-]
  std::vector<RegionRef> near;     // where zones are finest
  RegionRef region;                // zone only the blocks in this region (empty: all)
  // No block edge shorter than this fraction of the zone edge there: cuts are bent together
  // where they would make one (Model::cut); 0: only model{ tolerance }.
  double sliver = 0.1;
  // Refused before meshing when the finest edge would make about more zones than this
  // (Model::zone's estimate).
  double max_zones = 1e6;
};

// What a checkpoint records beside the model: the script that made it, when, and where.
struct CheckpointNote {
  std::string script_path = {};   // as given on the command line ("" if none)
  std::string script = {};        // its text
  std::string saved_at = {};      // local time, "2026-11-22 14:03:11" (save: now, when empty)
  std::string edem_version = {};  // of the EDEM that wrote it (set by save)
};

struct ModelInfo {
  int blocks = 0;
  int zones = 0;
  int gridpoints = 0;
  int joint_edges = 0;      // block edges made by joints, each counted once per side
  int dropped_cuts = 0;
  int cuts_left_out = 0;    // automatic potential-crack cuts (or stretches of their groups' outlines) that
                            // could not be laid clear of the rest
  int cuts_cut_back = 0;    // automatic potential-crack cuts cut back from a corner sharper than min_angle
  int snapped = 0;          // features smaller than the tolerance (zone{ sliver }) the cuts were bent to remove
  int slivers_kept = 0;     // spots where required cuts could not be bent clear of zone{ sliver }: kept
  // The shortest block edge over the zone edge there (its zone request's size at its midpoint);
  // 0 before zoning.
  double shortest_edge = 0.0;
  int regions = 0;
  int joint_sets = 0;
  int crack_seeds = 0;      // crackseed{} inputs
  int sections = 0;         // potential-crack sections (state/sections.hpp)
  int intact_sections = 0;  // of them, not yet broken and with rock on a side (SectionView::gone)
  int cracks = 0;           // sections broken, in either mode
  int shear_cracks = 0;
  int tension_cracks = 0;
  int stage = 0;            // excavations so far
};

}  // namespace edem
