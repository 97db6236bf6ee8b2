// Field output for ParaView: frames of the model in HDF5, indexed by an XDMF file.
//
// A series is a pair of files: NAME.xdmf (the XDMF 3 index ParaView opens: one temporal
// collection, a spatial collection per frame) and NAME.h5 (the data, a group /frames/N per frame).
// Each frame holds four grids, all at the current (deformed) positions:
//   zones     triangles in place (not excavated): stresses, principal stresses, plastic state,
//             material and block per cell; displacement and velocity per point
//   contacts  a line per contact along its plane, of its length: normal and shear force, normal
//             and shear displacement, slip, state (0 bonded, 1 elastic, 2 slip, 3 open), kind
//             (0 joint, 1 crack)
//   cracks    a line per broken potential-crack section: mode (1 shear, 2 tension), cycle, stage
//   bolts     a line per bolt segment: axial force, strain, state (0 elastic, 1 yielded,
//             2 broken, 3 removed: its rock gone)
// The index is rewritten after every frame, so it is valid whenever the run stops.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec2.hpp"

namespace edem {

// Line cells (contacts, cracks, bolts) are point pairs: cell i runs from points[2i] to points[2i + 1].
struct FieldFrame {
  double time = 0.0;  // [s] (static mode: cycles)
  long cycle = 0;
  int stage = 0;
  // zones
  std::vector<Vec2> points;                   // per mesh gridpoint, current [m]
  std::vector<std::array<double, 3>> displacement, velocity;  // per gridpoint, z = 0 [m], [m/s]
  std::vector<std::array<int, 3>> triangles;  // zones in place, counter-clockwise
  std::vector<double> sxx, syy, sxy, szz, s1, s3;  // per zone in place [Pa]
  std::vector<int> state, material, block;    // state: ZoneState bits; material, block: 0-based
  // contacts
  std::vector<Vec2> contact_points;
  std::vector<double> fn, fs, un, us, slip;   // [N/m], [m]
  std::vector<int> contact_state, contact_kind;
  // cracks
  std::vector<Vec2> crack_points;
  std::vector<int> crack_mode, crack_stage;
  std::vector<double> crack_cycle;
  // bolts
  std::vector<Vec2> bolt_points;
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
  };
  void write_index() const;
  std::string xdmf_, data_;
  std::vector<Entry> index_;
};

}  // namespace edem
