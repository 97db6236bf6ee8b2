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
  // Staged law: stage i holds from stage_closure[i] on, with stiffness stage_kn[i] and the
  // stress stage_stress[i] at its start.
  std::vector<double> stage_closure, stage_kn, stage_stress;
  double kn_zero = 0.0;  // tangent at zero closure: the stiffness of a bonded joint in tension
  double kn_max = 0.0;   // the largest tangent anywhere: what the time step must allow for
};

// Checks a definition (names the bad key and value) and derives the parameters.
JointParams joint_params(const JointMaterialDef& def);

// Normal stress at a closure; for closure < 0 (opening) the tension a bonded joint would carry,
// kn_zero * closure (the caller limits it).
double normal_stress(const JointParams& p, double closure);

// The closure at which the law gives `stress` (its inverse; negative stress: opening).
double closure_at(const JointParams& p, double stress);

// The seed paper's curve itself, unclamped, in SI: sn [Pa] at closure v [m] (for tests).
double seed_cubic_raw(double v);

}  // namespace edem
