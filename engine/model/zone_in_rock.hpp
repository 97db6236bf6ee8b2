// Whether a mesh zone is rock in place, for the model's views (gridpoint_near, sections()).
#pragma once

#include <cstddef>

#include "state/mechanics.hpp"

namespace edem {

// A zone with a material that is not void and was not excavated.
bool zone_in_rock(const Mechanics& m, size_t z);

}  // namespace edem
