// Field output for ParaView: frames of the model in HDF5, indexed by an XDMF file.
//
// A series is a pair of files: NAME.xdmf (the XDMF 3 index ParaView opens: one temporal
// collection, a spatial collection per frame) and NAME.h5 (the data, a group /frames/N per frame).
// Each frame holds four grids, each at its reference positions with a displacement per point
// (ParaView's Warp By Vector on it, scale 1, shows where things are now; more magnifies):
//   zones     triangles in place (not excavated) and only their gridpoints: stresses, principal
//             stresses, plastic state (bits: kStateLegend), material (kept as names in the file)
//             and block per cell; displacement and velocity per point
//   contacts  a line per contact along its plane, of its length, moved back by its gridpoint's
//             displacement: normal and shear force, normal and shear displacement, slip, state
//             (kContactStateLegend), kind (0 joint, 1 crack)
//   cracks    a line per broken potential-crack section: mode (1 shear, 2 tension), cycle, stage
//   bolts     a line per bolt segment: axial force, strain, state (kBoltStateLegend)
// What the integers mean is written beside them: an Information element named "legend" in the
// index and a "legend" attribute on the dataset.
// The index is rewritten after every frame, so it is valid whenever the run stops.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec2.hpp"

namespace edem {

inline constexpr const char* kStateLegend = "bits: 1 shear now, 2 tension now, 4 shear in the past, 8 tension in the past";
inline constexpr const char* kContactStateLegend = "0 bonded, 1 elastic, 2 slipping, 3 open";
inline constexpr const char* kContactKindLegend = "0 joint, 1 crack";
inline constexpr const char* kCrackModeLegend = "1 shear, 2 tension";
inline constexpr const char* kBoltStateLegend = "0 elastic, 1 yielded, 2 broken, 3 removed (its rock excavated)";

// Line cells (contacts, cracks, bolts) are point pairs: cell i runs from points[2i] to points[2i + 1].
// Every grid's points are reference positions; `displacement` (per point) takes them to now.
struct FieldFrame {
  double time = 0.0;  // [s] (static mode: cycles)
  long cycle = 0;
  int stage = 0;
  // zones
  std::vector<Vec2> points;                   // per gridpoint of a zone in place, reference [m]
  std::vector<std::array<double, 3>> displacement, velocity;  // per point, z = 0 [m], [m/s]
  std::vector<std::array<int, 3>> triangles;  // zones in place, counter-clockwise, into points
  std::vector<double> sxx, syy, sxy, szz, s1, s3;  // per zone in place [Pa]
  std::vector<int> state, material, block;    // state: ZoneState bits; material, block: 0-based
  std::vector<std::string> material_names;    // by material number
  // contacts
  std::vector<Vec2> contact_points;
  std::vector<std::array<double, 3>> contact_displacement;
  std::vector<double> fn, fs, un, us, slip;   // [N/m], [m]
  std::vector<int> contact_state, contact_kind;
  // cracks
  std::vector<Vec2> crack_points;
  std::vector<std::array<double, 3>> crack_displacement;
  std::vector<int> crack_mode, crack_stage;
  std::vector<double> crack_cycle;
  // bolts
  std::vector<Vec2> bolt_points;
  std::vector<std::array<double, 3>> bolt_displacement;
  std::vector<double> bolt_force, bolt_strain;  // [N/m], [-]
  std::vector<int> bolt_state;
};

// Appends frames to NAME.h5 and keeps NAME.xdmf up to date. The first frame creates (replaces)
// both files.
class FieldSeries {
 public:
  // `xdmf` must end in .xdmf or .xmf; the data file is the same name ending in .h5.
  explicit FieldSeries(std::string xdmf);
  void append(const FieldFrame& frame);
  const std::string& xdmf_path() const { return xdmf_; }
  const std::string& data_path() const { return data_; }
  int frames() const { return static_cast<int>(index_.size()); }

 private:
  struct Entry {
    double time;
    int zones, points, contacts, cracks, bolt_segments;
    std::string materials;  // the material legend: "0 rock, 1 intact"
  };
  void write_index() const;
  std::string xdmf_, data_;
  std::vector<Entry> index_;
};

}  // namespace edem
