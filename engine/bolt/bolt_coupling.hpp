// Bolts in a zoned model: each bolt node tied to a material point of a host zone, the grout's
// reaction spread back over that zone's nodes, the bolts' share of the time step, and their
// part of a cycle (the laws are bolt/bolt_law.hpp).
//
// Across its axis a bolt node moves with its host point (a 2D bolt has no bending stiffness, so
// nothing else would hold it there); along the axis it slides against the point, by `slide`,
// integrated like a rock node with the same damping and resisted by the grout and its segments.
// A node that has slid out of its host zone (beyond a quarter of the zone's size) is tied again,
// before the next batch of cycles, to the zone it is in now, in whichever block: bolts cross
// joints and cracks. One drawn out of the rock loses its grout.
#pragma once

#include "bolt/bolt_law.hpp"
#include "state/mechanics.hpp"
#include "state/motion.hpp"

namespace edem {

// Adds a bolt and returns its index. Its ends are points as the model was drawn (the frame of
// every point a script gives); each node is tied to the material point there and laid where that
// point is now, stress-free. Every grouted node must lie in a rock zone (material not null, not
// excavated; or within a quarter of one's size, for heads on a wall); an ungrouted node (the free
// length) may lie outside. Throws naming the first node that does not, and then changes nothing.
int install_bolt(Mechanics& m, const BoltLine& line, int material);

// Cuts the bolts where their rock is gone (a host zone excavated or null: dug out, or a fallen
// block mucked away): the nodes there let go and the segments reaching them carry nothing, the
// rest of each bolt stays in service (a bolt with no node left in rock goes out of service);
// then ties the bolts to the rock's nodes (the gather lists and the grout's share of each node's
// stiffness). After `active` is known (prepare()).
void tie_bolts(Mechanics& m);

// Whether bolt `bolt`'s head is still on it: the bolt in service and its first segment neither cut
// nor reaching a node whose rock is gone since the cuts were last made (an excavate{} before the
// next cycle).
bool head_on_bolt(const Mechanics& m, int bolt);

// The bolt nodes' cycling masses: with a step of 1 and the rock's rule in static mode
// (`amplification`, `fraction`), their real masses in dynamic mode. Returns the bolts' critical
// step with real masses [s] (infinity without bolts).
double bolt_masses(Mechanics& m, bool dynamic, double amplification, double fraction);

// The bolts' part of a cycle, before the rock's nodes move: host displacements, segment and grout
// forces, head drives, and the slide of every node. `measure`: adds the bolts' unbalanced force,
// applied force, kinetic energy and Rayleigh sums to `out`.
void bolt_cycle(Mechanics& m, const Motion& motion, bool record_start, bool measure, Measure& out);

// Adds the bolts' unbalanced and applied forces as their last cycle left them (no step).
void measure_bolts(const Mechanics& m, Measure& out);

// The bolts' force on rock node `n` [N/m], from the forces of the last bolt_cycle. A bolt node
// hosted by a zone moves with that zone's point and slides along the bolt (u = host + slide dir),
// so the rock takes every force on the node but the grout's, which acts between the slide and the
// rock: the segments' pulls, along the bolt and across it. Along it, the slide balances them
// against the grout (at rest they are the grout's force); across it, where a bolt bends at a
// slipping joint, only the rock holds them.
inline void add_bolt_forces(const Mechanics& m, size_t n, double f[2]) {
  const BoltHosts& h = m.bolt_hosts;
  const BoltNodes& b = m.bolts.nodes;
  for (int s = h.gather_first[n]; s < h.gather_first[n + 1]; ++s) {
    const size_t node = static_cast<size_t>(h.gather[static_cast<size_t>(s)] / 3);
    const double w = h.weight[node][static_cast<size_t>(h.gather[static_cast<size_t>(s)] % 3)];
    // The node's force is the segments' pulls less the grout's b.grout_force along b.axis.
    f[0] += w * (b.force[node].x + b.grout_force[node] * b.axis[node].x);
    f[1] += w * (b.force[node].y + b.grout_force[node] * b.axis[node].y);
  }
}

// Ties again the nodes that slid out of their host zone; true if any moved (the ties and the
// stiffnesses are then out of date: tie_bolts() and the masses again).
bool rehost_bolts(Mechanics& m);

// reset{ displacement }: the rock's u restarts from 0; the bolts' ties follow so that nothing moves.
void reset_bolt_displacements(Mechanics& m);

// The bolts' start of a cycling command (adaptive damping), like the rock's.
void start_bolt_damping(Mechanics& m);

}  // namespace edem
