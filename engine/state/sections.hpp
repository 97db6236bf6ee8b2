// Potential-crack sections (seed paper §2.4).
//
// A potential crack is a cut through intact rock (crackseed{}) whose two faces are tied: their
// gridpoints, which zoning places at the same points on both faces, are one solver node, so
// the rock deforms exactly as if the cut were not there. The zones along it divide it into
// sections, one per zone edge; each is judged on its own (judge.hpp) and, when it fails,
// breaks: the tie along it is released and its faces touch through contacts like a joint's.
// A gridpoint stays tied across the crack while any intact section (or glued edge) still joins
// it to its twin, so a crack opens between the sections that have broken and is held at its
// tips, as a crack in a continuum is.
#pragma once

#include <array>
#include <vector>

#include "core/vec2.hpp"
#include "core/physics_defs.hpp"
#include "geom/mesh.hpp"

namespace edem {

struct Section {
  // The two faces: side 0 is the block whose boundary loop meets the section first.
  std::array<int, 2> a{-1, -1}, b{-1, -1};  // mesh gridpoints at its ends A and B, per side
  std::array<int, 2> edge{-1, -1};          // flat boundary-loop edge per side (loop_edges())
  std::array<int, 2> block{-1, -1};         // mesh block per side
  int seed = -1;                            // the crackseed{} input (0-based)
  Vec2 point;                               // calculation point: the midpoint [m]
  double angle = 0.0;                       // direction A -> B, in [0, 180) [deg]
  double length = 0.0;                      // [m]
  CrackMode mode = CrackMode::none;         // how it broke; none while intact
  int crack = -1;                           // its crack record, once broken
  bool fresh = false;                       // broken since the last contact detection
};

// What judging needs per section, derived from the zones and materials (judge.hpp): the zones
// the stress is fitted to (up to four each side, nearest the point, among those touching the
// section's ends; with judge{ radius }, also the rest of its two blocks' within that distance)
// with the fit's weights, the rock strength, and the joint material it takes when it breaks.
struct SectionFits {
  std::vector<int> first;                      // per section + 1: its range in zone / weight
  std::vector<int> zone;                       // mesh zones
  std::vector<std::array<double, 9>> weight;   // per zone (section_stress.hpp)
  std::vector<std::array<double, 3>> offset;   // per section: the body force's part [Pa]
  std::vector<Vec2> body;                      // per section: the body force fitted [N/m^3]
  std::vector<RockStrength> strength;          // per section
  std::vector<int> after;                      // per section: joint material once broken
};

struct SectionLayout {
  std::vector<Section> sections;   // in boundary-loop order of side 0
  std::vector<int> edge_section;   // per flat loop edge: its section, or -1
  std::vector<char> edge_glued;    // per flat loop edge: joins its blocks into one continuum
};

// Flat index of every block boundary-loop edge: blocks in order, loops in order, edges in
// order (the order of ContactBoundary::edges).
int loop_edge_count(const Mesh& mesh);

// The sections of every potential cut between two zoned blocks, all intact; and the glued
// flags of the loop edges (glued outlines and intact potential edges).
SectionLayout find_sections(const Mesh& mesh);

}  // namespace edem
