// Grouted bolts as the model holds them: per metre of thickness, a structure of arrays over every
// node and segment of every bolt, indices not pointers; a bolt's nodes and segments are
// contiguous. The laws that move them are in bolt/bolt_law.hpp.
//
// Per metre of thickness: a bolt row repeats every `spacing` metres out of the plane, so every
// force, stiffness and mass is a bolt's own divided by its spacing (Itasca practice): forces
// [N/m], stiffnesses [N/m per m], masses [kg/m]. Axial force is tension positive. Segments run
// from the head (the outer end) towards the end (the bottom of the hole): node a is the one
// nearer the head.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace edem {

// The same per metre of model thickness: a bolt's values divided by its spacing.
struct BoltLaw {
  double ea = 0.0;                 // axial stiffness E A / spacing [N/m]
  double yield_tension = 0.0;      // [N/m]
  double yield_compression = 0.0;  // positive [N/m]
  double failure_strain = 0.0;     // [-]
  double bond_stiffness = 0.0;     // [N/m per m of bolt, per m of thickness]
  double bond_strength = 0.0;      // [N per m of bolt, per m of thickness]
  double line_mass = 0.0;  // density x area / spacing [kg per m of bolt, per m of thickness]
};

enum class SegmentState : std::uint8_t {
  elastic,  // has never reached a yield force
  yielded,  // has reached one (and may be unloading elastically from it now)
  broken,   // strained past failure_strain: carries nothing from then on
  removed,  // an end's rock was dug out or mucked away: carries nothing from then on
};

// Whether a segment in `state` can carry force.
inline bool carries(SegmentState state) {
  return state == SegmentState::elastic || state == SegmentState::yielded;
}

// Per node. Hot: u, v, force (every cycle); warm: the grout's state; cold: x, mass, lengths.
struct BoltNodes {
  std::vector<Vec2> x;              // position at installation [m]
  std::vector<Vec2> u;              // displacement since installation [m]
  std::vector<Vec2> v;              // velocity [m/s]
  std::vector<Vec2> force;          // on the node from its segments and its grout, this cycle [N/m]
  std::vector<double> mass;         // line_mass x tributary length [kg/m]
  std::vector<double> tributary;    // half of each adjacent segment [m]
  std::vector<double> bond_length;  // grouted length the node stands for [m]; 0: ungrouted
  std::vector<double> grout_stiffness;  // bond_stiffness x bond_length [N/m per m]
  std::vector<double> grout_strength;   // bond_strength x bond_length [N/m]
  std::vector<Vec2> axis;           // unit bolt axis at the node, towards the end, as last updated
  std::vector<double> grout_force;  // GroutUpdate::force [N/m]
  std::vector<double> grout_slip;   // GroutUpdate::slip [m]
  std::vector<std::uint8_t> slipping;  // GroutUpdate::slipping
  std::vector<Vec2> grout_rel;         // u - host u at the last update [m]: increments come from it

  size_t size() const { return x.size(); }
};

// Per segment: node a (nearer the head) to node b.
struct BoltSegments {
  std::vector<int> a, b;
  std::vector<int> material;       // index into BoltSet::laws
  std::vector<double> rest;        // rest length [m]
  std::vector<double> elongation;  // current length - rest, as last updated [m]
  std::vector<Vec2> direction;     // unit vector from a to b, as last updated
  std::vector<double> force;       // axial, tension positive [N/m]
  std::vector<SegmentState> state;
  // 1 once it has broken, kept when its rock is cut away (state removed), so a count of broken
  // segments does not lose those that fell with a mucked-out block.
  std::vector<std::uint8_t> broke;

  size_t size() const { return a.size(); }
};

struct BoltSet {
  std::vector<BoltLaw> laws;  // the materials, by index
  BoltNodes nodes;
  BoltSegments segments;
  // Per bolt: its first node and first segment (the rest follow contiguously), + 1 at the end.
  std::vector<int> bolt_first_node{0}, bolt_first_segment{0};

  int bolts() const { return static_cast<int>(bolt_first_node.size()) - 1; }
};

}  // namespace edem
