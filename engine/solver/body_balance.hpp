// The net force on each body of the model (rock joined by its zones and intact sections, apart
// from the rest across joints and cracks): at an equilibrium each body's own forces balance,
// whatever the ratio over the whole model says.
#pragma once

#include <vector>

#include "core/vec2.hpp"

namespace edem {

struct Mechanics;

struct BodyBalance {
  double share = 0.0;  // |net unbalanced force| over the forces on it (weight, contacts, loads)
  int block = -1;      // a block of the body
  Vec2 at{};           // where a node of the body is now [m]
};

// The body whose net unbalanced force is the largest share of the forces on it. Local damping
// can hold rock that has no equilibrium, creeping, with a whole-model ratio below 1e-5: its
// body's share shows it (tests/bench/RESULTS.md, "Rock that local damping holds").
BodyBalance worst_body_balance(const Mechanics& m);

// Each node's body's share (the measure above; 0 for nodes of no moving body), for solve{ balance }
// to let the bodies with no equilibrium near move undamped.
std::vector<double> body_share_by_node(const Mechanics& m);

}  // namespace edem
