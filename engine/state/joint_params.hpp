// A joint material once checked, in the form the joint law uses (contact/joint_law.hpp):
// one JointParams per joint material; contacts refer to it by index.
#pragma once

#include <vector>

#include "core/physics_defs.hpp"

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
  // The closure over which the law follows its measured curve (seed-cubic: up to the straight
  // line that continues it; 0 for a law the user gives whole). A gridpoint sunk that far is the
  // law at work, not an overlap: the watchdog's default limit allows it (overlap_limit).
  double curve_closure = 0.0;  // [m]
};

}  // namespace edem
