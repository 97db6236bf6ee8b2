// Excavation's part in cycling (the commands are Model::excavate and Model::fill).
#pragma once

namespace edem {

struct Mechanics;

// Cycles the running excavate{ release = n } still has to go; 0 when none runs.
long release_cycles_left(const Mechanics& m);

// Takes one cycle's share off the loads a running release holds on the new surface; nothing when
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
