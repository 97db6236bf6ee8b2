// In-situ stress fields: the stress an insitu{} definition gives at a point, and which one covers it.
#pragma once

#include <optional>

#include "core/physics_defs.hpp"
#include "state/mechanics.hpp"

namespace edem {

// Checks an in-situ definition; throws edem::Error naming the bad value.
void check_insitu(const InsituDef& def);

// The in-situ stress at a point; `g` is the gravity magnitude the surface form uses [m/s^2].
Stress insitu_stress(const InsituDef& def, Vec2 point, double g);

// The stress of the latest in-situ definition that covers `point`, if one does.
std::optional<Stress> insitu_stress_if_any(const Mechanics& m, Vec2 point);

// The stress of the latest in-situ definition that covers `point`; throws when none does.
Stress insitu_stress_at(const Mechanics& m, Vec2 point);

}  // namespace edem
