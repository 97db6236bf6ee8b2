// Building the solver's arrays from the mesh and the mechanical inputs.
#pragma once

#include "geom/mesh.hpp"
#include "state/mechanics.hpp"

namespace edem {

// Fresh mechanics state for a new mesh: nodes (gridpoints merged across glued edges), zone
// state arrays, outer boundary segments. Materials, gravity and settings are kept from `old`.
void reset_for_mesh(Mechanics& m, const Mesh& mesh);

// After sections broke (m.edge_glued changed): gridpoints no longer tied become nodes of their
// own, numbered after the existing ones, which keep their numbers; each starts with the state
// of the node it leaves. Rebuilds what refers to nodes and marks the model dirty.
void reconnect(Mechanics& m, const Mesh& mesh);

// Recomputes the derived arrays (active zones, masses, time step, loads, partition) if
// m.dirty; else only the partition, if the thread count changed. Throws edem::Error when the model cannot be cycled (no zones, a zone without
// material, dynamic mode with zero density, a forced step at or above the critical step is
// allowed but noted by the watchdog).
void prepare(Mechanics& m, const Mesh& mesh);

// Masses and time step from the zone and contact stiffness (after prepare(), and again after
// every contact detection).
void update_masses(Mechanics& m);

// Splits the active zones and the nodes among thread_count(m) threads (m.partition, m.acc_force).
void split_among_threads(Mechanics& m);

}  // namespace edem
