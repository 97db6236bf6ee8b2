// The joint law of a contact: normal stress from closure (linear, staged kn, or the seed
// paper's cubic lab curve, clamped), shear stiffness, Coulomb slip with cohesion, tensile
// strength and dilation.
//
// Closure is positive when the faces press together [m]; the normal stress these functions
// speak of is compression positive [Pa] (the model's views turn it to compression negative).
#pragma once

#include <vector>

#include "model/physics_defs.hpp"

namespace edem {

struct JointParams {
  NormalLaw law = NormalLaw::linear;
  double kn = 0.0;            // linear law [Pa/m]
  double ks = 0.0;            // [Pa/m]
  double tan_friction = 0.0;  // [-]
  double cohesion = 0.0;      // [Pa]
  double tension = 0.0;       // [Pa]
  // Once the contact has slipped or opened (no longer intact): no tension, and these.
  double residual_cohesion = 0.0;      // [Pa]
  double tan_residual_friction = 0.0;  // [-]
  double tan_dilation = 0.0;  // [-]
  // A softening bond (JointMaterialDef::fracture_energy, shear_fracture_energy > 0) loses its
  // strength over an opening or a slip instead of at once (Hillerborg's cohesive crack, linear):
  //   tension: up to the peak, kn_zero times the opening; past it, the tensile strength falls
  //     linearly to 0 at the opening 2 G_I / tension, and unloading heads back to zero opening
  //     (secant), so that the area under traction against the opening past the elastic part
  //     is G_I;
  //   shear: the cohesion falls linearly to residual_cohesion at the plastic slip
  //     2 G_II / (cohesion - residual_cohesion), the friction staying at its peak meanwhile.
  // What is left of the bond is the smaller of the two fractions (bond_left); when none is
  // left the contact is no longer intact. 0: that mode drops at once, as without softening.
  bool softens = false;
  double opening_at_loss = 0.0;  // 2 G_I / tension [m]
  double slip_at_loss = 0.0;     // 2 G_II / (cohesion - residual_cohesion) [m]
  // Staged law: stage i holds from stage_closure[i] on, with stiffness stage_kn[i] and the
  // stress stage_stress[i] at its start.
  std::vector<double> stage_closure, stage_kn, stage_stress;
  // The seed law scaled (JointMaterialDef::law_stress_scale, law_closure_scale).
  double law_stress_scale = 1.0, law_closure_scale = 1.0;
  double kn_zero = 0.0;  // tangent at zero closure: the stiffness of a bonded joint in tension
  double kn_max = 0.0;   // the largest tangent anywhere: what the time step must allow for
};

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
