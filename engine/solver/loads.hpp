// Boundary conditions on the solver's arrays: which nodes a boundary{} selects, tractions lumped.
#pragma once

#include <vector>

#include "geom/mesh.hpp"
#include "state/mechanics.hpp"

namespace edem {

// Nodes of the outer boundary that a boundary{} selects (sorted); throws edem::Error when the
// definition is bad or selects nothing.
std::vector<int> select_boundary_nodes(const Mechanics& m, const BoundaryDef& def);

// Lumps the tractions of loaded boundary segments to the nodes (m.load), exactly for stresses
// that vary linearly along a segment.
void lump_boundary_loads(Mechanics& m);

}  // namespace edem
