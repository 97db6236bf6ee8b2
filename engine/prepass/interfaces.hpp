// Joints in the prepass: zero-thickness interface elements between the two faces of a joint,
// lumped to node pairs (a gridpoint of one block and the gridpoint of the block across at the same
// place; the zoning puts them there). Each pair carries a traction over its share of the joint's
// length: normal stiffness kn and shear stiffness ks of the joint's material, Coulomb slip with
// its cohesion and friction, no tension once open or slipped (UDEC's Coulomb slip, as the
// explicit contacts: contact/joint_law.hpp). The traction starts from the stress of the zone
// beside the joint, so a state in equilibrium stays so.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec2.hpp"
#include "state/mechanics.hpp"

namespace edem {

struct InterfacePair {
  int a = -1, b = -1;   // solver nodes: a on the first block, b across
  double length = 0.0;  // its share of the joint [m]
  Vec2 n;               // unit normal out of a's block
  int material = -1;    // joint material
};

// The joint's direction at a pair: its normal turned counter-clockwise (the shear axis).
inline Vec2 along(Vec2 n) { return {-n.y, n.x}; }

// u_b - u_a of a pair, from displacements per node component.
inline Vec2 opening(const InterfacePair& pair, const std::vector<double>& u) {
  const size_t a = static_cast<size_t>(pair.a), b = static_cast<size_t>(pair.b);
  return {u[2 * b] - u[2 * a], u[2 * b + 1] - u[2 * a + 1]};
}

// A pair's state: traction on a's face (normal, tension positive; shear along the normal turned
// counter-clockwise) [Pa], relative displacement u_b - u_a [m], and whether it has slipped or
// opened (then no tension and residual strength).
struct InterfaceState {
  double sn = 0.0, ss = 0.0;
  Vec2 d;
  bool broken = false;
  std::uint8_t mode = 0;  // kShearNow (slipping) or kTensionNow (open) in the last trial
  double slope = 0.0;     // tan(friction) the last trial slipped with
};

// The node pairs of every joint face whose two sides are zoned alike, and their state now.
// Throws edem::Error for a joint without a material or with a normal law other than linear.
void make_interfaces(const Mechanics& m, std::vector<InterfacePair>& pairs, std::vector<InterfaceState>& state);

// The trial state of a pair after relative displacement d (u_b - u_a, total), from `start`.
InterfaceState interface_trial(const JointParams& p, const InterfacePair& pair, const InterfaceState& start, Vec2 d);

// d traction / d (u_b - u_a) in global axes for the trial `now` (2 x 2, row major).
std::array<double, 4> interface_tangent(const JointParams& p, const InterfacePair& pair, const InterfaceState& now);

}  // namespace edem
