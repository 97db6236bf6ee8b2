// Zone materials: a MaterialDef checked and turned into the MaterialParams the kernels use
// (state/material_params.hpp).
#pragma once

#include "core/physics_defs.hpp"
#include "state/material_params.hpp"

namespace edem {

// Checks a definition (a name; finite, physical values; exactly one elastic pair, both of it;
// each law's own keys only for that law) and derives the parameters. Throws edem::Error naming the key
// and the bad value. The one place a material is checked: material{} passes its message on.
MaterialParams material_params(const MaterialDef& def);

// The definition with the strengths left unset read as 0, as the model keeps it.
MaterialDef with_strength_defaults(MaterialDef def);

}  // namespace edem
