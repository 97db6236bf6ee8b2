// Excavation on the solver's arrays: zones taken out or put back, and the release of what the
// excavated rock bore on the rock in place while cycling (the commands: model/model_excavation.cpp).
#pragma once

#include <vector>

#include "geom/mesh.hpp"

namespace edem {

struct Mechanics;

// Excavates `zones` (checked: in place, with material): null from now on, their stress gone, and
// what the excavation takes off each node of the rock left (the zones' forces, the dug blocks'
// contacts) held and taken off over `release` cycles (0: at once; with a release the contacts are
// found again now). Glued edges that now face the opening come apart, and the energy the zones
// and the contacts that went held is booked as dug out. `new_stage`: counts as an excavation
// stage (mucking out a fallen block does not).
void excavate_zones(Mechanics& m, const Mesh& mesh, const std::vector<int>& zones, long release,
                    bool new_stage);

// Puts rock of `material` back into the excavated `zones`, unstressed.
void fill_zones(Mechanics& m, const std::vector<int>& zones, int material);

// Cycles the running excavate{ release = n } still has to go; 0 when none runs.
long release_cycles_left(const Mechanics& m);

// Takes one cycle's share off the loads a running release holds on the rock; nothing when
// none runs or all its steps are taken. Touches only Mechanics::load and the release, so the cycle
// may call it while the zones' forces are summed.
void step_release(Mechanics& m);

// Books the work the release's loads did over the last cycle stepped (once its nodes have moved)
// as the excavation's.
void release_work(Mechanics& m);

// The release's last step: it ends, and the boundary gets its own loads back exactly (the steps
// summed would leave rounding behind on the new surface).
void end_release(Mechanics& m);

}  // namespace edem
