// The joint law of a contact: normal stress from closure (linear, staged kn, or the seed
// paper's cubic lab curve, clamped), shear stiffness, Coulomb slip with cohesion, tensile
// strength and dilation.
//
// Closure is positive when the faces press together [m]; the normal stress these functions
// speak of is compression positive [Pa] (the model's views turn it to compression negative).
#pragma once

#include "core/physics_defs.hpp"
#include "state/joint_params.hpp"

namespace edem {

// Checks a definition (names the bad key and value) and derives the parameters.
JointParams joint_params(const JointMaterialDef& def);

// Normal stress at a closure; for closure < 0 (opening) the tension a bonded joint would carry,
// kn_zero * closure (the caller limits it).
double normal_stress(const JointParams& p, double closure);

// The energy a unit length of joint stores pressed to `closure` [J/m^2]: the integral of
// normal_stress from zero closure (for closure < 0, the bonded tension's, kn_zero closure^2 / 2).
double normal_energy(const JointParams& p, double closure);

// The closure at which the law gives `stress` (its inverse; negative stress: opening).
double closure_at(const JointParams& p, double stress);

// What is left of a softening bond's strength [0, 1], after the largest opening `opened`
// (its closure's negative) and the plastic slip `slip` since it formed [m].
double bond_left(const JointParams& p, double opened, double slip);

// Coulomb's shear strength of a joint [Pa] under the normal stress `compression` (positive in
// compression): `cohesion` plus friction while intact (cohesion: as far as a bond has softened),
// the residual strength once broken. Negative where tension exceeds what cohesion holds: the
// caller decides what that means. The explicit contacts and the prepass's interfaces both slip
// by it.
inline double coulomb_strength(const JointParams& p, bool intact, double compression, double cohesion) {
  return intact ? cohesion + p.tan_friction * compression
                : p.residual_cohesion + p.tan_residual_friction * compression;
}

// The seed paper's curve itself, unclamped, in SI: sn [Pa] at closure v [m] (for tests).
double seed_cubic_raw(double v);

}  // namespace edem
