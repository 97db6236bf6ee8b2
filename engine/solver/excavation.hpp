// Excavation's part in cycling (the commands are Model::excavate and Model::fill).
#pragma once

namespace edem {

struct Mechanics;

// Takes one cycle's share off the loads an excavate{ release = n } holds on the new surface;
// false when no release is running.
bool step_release(Mechanics& m);

}  // namespace edem
