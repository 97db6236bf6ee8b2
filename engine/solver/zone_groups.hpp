// Groups of neighbouring zones for the mixed discretisation: pairs of triangles that share an
// edge, as FLAC's quadrilaterals are pairs of triangles, and a left-over triangle joined to a
// neighbouring pair. See solver/cycle.cpp for what the groups are for.
#pragma once

#include <array>
#include <vector>

#include "state/mechanics.hpp"

namespace edem {

// Per position in `zones` (indices into `geometry`): the positions of the other members of its
// group, -1 padded; {-1, -1} for a zone left alone. Zones are neighbours when they share two
// nodes. Deterministic: the same groups for the same input.
std::vector<std::array<int, 2>> group_zones(const std::vector<ZoneGeometry>& geometry,
                                            const std::vector<int>& zones,
                                            const std::vector<double>& position);

}  // namespace edem
