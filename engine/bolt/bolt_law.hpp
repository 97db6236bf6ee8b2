// Grouted bolts and cables: the physics kernel, in the spirit of Itasca's cable element. A bolt is
// a line of nodes joined by axial segments; a grout spring-slider ties each node to the rock at
// that point, along the bolt's axis.
//
// Per metre of thickness. The model is plane strain: it carries one metre of tunnel, and a bolt
// row repeats every `spacing` metres out of the plane. So every force, stiffness and mass here is
// a bolt's own divided by its spacing (Itasca practice): forces [N/m], stiffnesses [N/m per m],
// masses [kg/m]. BoltParams holds a single bolt's values; BoltLaw those per metre of thickness.
//
// Signs: axial force tension positive. Segments run from the head (the outer end, where a plate or
// a jack acts) towards the end (the bottom of the hole): node a is the one nearer the head.
//
// The laws are incremental and perfectly plastic:
//   segment: axial force += EA/L x elongation increment, held to [-yield_compression,
//            yield_tension]; once its tensile strain (elongation / rest length) exceeds
//            failure_strain it is broken and carries nothing, in tension or compression, for ever.
//   grout:   force += k x (axial slip increment of the node against the rock), with
//            k = bond_stiffness x bonded length, held to +-bond_strength x bonded length; what goes
//            past the strength is plastic slip.
// Elongation is measured on the current length, so a rigid rotation stresses nothing. The grout
// acts along the axis only: across it a bolt node has no stiffness of its own (no bending), and the
// solver is expected to make it follow the host rock there.
//
// Data: structure of arrays over every node and segment of every bolt (BoltSet), indices not
// pointers; a bolt's nodes and segments are contiguous. One cycle's bolt stage is
// bolt_forces(set, host_u); the solver then integrates the nodes (v, u) with its own damping, and
// hands the grout's reaction on the rock (grout_on_host) to the host zone's gridpoints by its
// shape functions, as it interpolated host_u from them.
#pragma once

#include <span>
#include <vector>

#include "core/vec2.hpp"
#include "state/bolts.hpp"

namespace edem {

// One bolt's properties, as a user gives them (SI). Every value must be finite and > 0.
struct BoltParams {
  double young = 0.0;              // Young's modulus of the steel [Pa]
  double area = 0.0;               // cross-section [m^2]
  double density = 0.0;            // [kg/m^3]
  double yield_tension = 0.0;      // axial force at which it yields in tension [N]
  double yield_compression = 0.0;  // the same in compression, as a positive number [N]
  double failure_strain = 0.0;     // tensile strain at which a segment breaks [-]
  double bond_stiffness = 0.0;     // grout shear stiffness [N/m per m of bolt]
  double bond_strength = 0.0;      // grout shear strength [N/m, i.e. N per m of bolt]
  double spacing = 1.0;            // out of the plane, between bolts of a row [m]
};

// Throws edem::Error naming the first bad value ("young must be a finite number > 0 [Pa], got 0").
void check_bolt_params(const BoltParams& p);

// Checks `p` and derives its values per metre of thickness.
BoltLaw bolt_law(const BoltParams& p);

// --- The two laws, one segment or one grout spring at a time -----------------------------------

struct SegmentUpdate {
  double force = 0.0;  // axial, tension positive [N/m]
  SegmentState state = SegmentState::elastic;
};

// A segment of rest length `rest` [m] whose elongation went from `elongation_old` to
// `elongation_new` [m] while it carried `force` in `state`.
SegmentUpdate segment_law(const BoltLaw& law, double rest, double force, SegmentState state,
                          double elongation_old, double elongation_new);

struct GroutUpdate {
  double force = 0.0;     // on the rock along the bolt axis, = minus that on the bolt node [N/m]
  double slip = 0.0;      // plastic slip so far, signed along the axis [m]
  bool slipping = false;  // at its strength in this increment
};

// A grout spring of stiffness `stiffness` [N/m per m] and strength `strength` [N/m] carrying
// `force` with plastic slip `slip`, after the node moved `ds` [m] along the axis relative to the
// rock. Zero stiffness (an ungrouted node): no force.
GroutUpdate grout_law(double stiffness, double strength, double force, double slip, double ds);

// --- A set of bolts ----------------------------------------------------------------------------

// A straight bolt to add to a set.
struct BoltLine {
  Vec2 head;          // the outer end [m]
  Vec2 end;           // the inner end, the bottom of the hole [m]
  int segments = 10;  // over the grouted length
  // Ungrouted length from the head [m], one segment of its own before the grouted ones (a
  // tendon's free length, or the bolt's tail out of the hole where a jack grips it); 0: none.
  double free_length = 0.0;
  int material = 0;  // index into BoltSet::laws
};

// Appends a bolt (nodes from the head to the end, unstressed, at rest) and returns its index.
// Its first node is set.bolt_first_node[index].
int add_bolt(BoltSet& set, const BoltLine& line);

// --- One cycle's bolt stage --------------------------------------------------------------------

// Segment directions, forces and states from the nodes' current positions (x + u); a removed
// segment keeps the direction it had. Returns what the segments dissipated [J/m]: yielding's
// plastic work, and the elastic energy of those that broke.
double update_segments(BoltSet& set);

// Node axes: the mean direction of each node's (one or two) segments not removed, as last updated;
// a removed one's where it has no other.
void update_axes(BoltSet& set);

// Node axes (update_axes) and grout forces from the nodes' displacements and the
// rock's at each node (`host_u`: one per node, since the bolt's installation [m]; the grout force
// grows as the node moves towards the bolt's end relative to the rock). Returns the plastic work
// of the grout that slipped [J/m].
double update_grout(BoltSet& set, std::span<const Vec2> host_u);

// Each node's force (set, not added to) from its segments and its grout, as last updated.
void gather_node_forces(BoltSet& set);

// The three above, in that order: the bolt stage of a cycle. Returns what it dissipated [J/m].
double bolt_forces(BoltSet& set, std::span<const Vec2> host_u);

// The elastic energy the bolts store [J/m]: their segments' N^2 L / (2 EA) and their grout's
// F^2 / (2 k).
double bolt_energy(const BoltSet& set);

// The force the grout of `node` puts on the rock [N/m] (equal and opposite to its pull on the
// node): what the solver spreads over the host zone's gridpoints.
inline Vec2 grout_on_host(const BoltSet& set, size_t node) {
  return set.nodes.grout_force[node] * set.nodes.axis[node];
}

// --- Time step ---------------------------------------------------------------------------------

// Per node: the Gershgorin row sum of the stiffness along the bolt's axis [N/m per m]: 2 EA/L for
// each unbroken adjacent segment (both its ends move) and 2 x the grout's stiffness (the rock at
// the node moves too; a host gridpoint with shape function N_j takes 2 N_j x the grout's
// stiffness in its own row sum). With the node's mass, central differences are stable for steps
// up to 2 sqrt(mass / stiffness), the rule the solver applies to zones and contacts.
std::vector<double> bolt_node_stiffness(const BoltSet& set);

// min over nodes of 2 sqrt(mass / stiffness) [s]; infinity for a set without stiffness.
double bolt_critical_step(const BoltSet& set);

}  // namespace edem
