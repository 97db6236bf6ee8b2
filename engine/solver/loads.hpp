// In-situ stress fields and boundary conditions on the solver's arrays.
#pragma once

#include <optional>
#include <vector>

#include "geom/mesh.hpp"
#include "solver/mechanics.hpp"

namespace edem {

// Checks an in-situ definition; throws edem::Error naming the bad value.
void check_insitu(const InsituDef& def);

// The in-situ stress at a point; `g` is the gravity magnitude the surface form uses [m/s^2].
Stress insitu_stress(const InsituDef& def, Vec2 point, double g);

// The stress of the latest in-situ definition that covers `point`, if one does.
std::optional<Stress> insitu_stress_if_any(const Mechanics& m, Vec2 point);

// The stress of the latest in-situ definition that covers `point`; throws when none does.
Stress insitu_stress_at(const Mechanics& m, Vec2 point);

// Nodes of the outer boundary that a boundary{} selects (sorted); throws edem::Error when the
// definition is bad or selects nothing.
std::vector<int> select_boundary_nodes(const Mechanics& m, const BoundaryDef& def);

// Lumps the tractions of loaded boundary segments to the nodes (m.load), exactly for stresses
// that vary linearly along a segment.
void lump_boundary_loads(Mechanics& m);

}  // namespace edem
