// Zone materials: what a MaterialDef becomes once checked, in the form the kernels use.
//
// One MaterialParams per material; zones refer to it by index. Moduli are plane-strain ready
// (e1 = K + 4G/3, e2 = K - 2G/3); the Mohr-Coulomb constants are precomputed once.
#pragma once

#include "model/physics_defs.hpp"

namespace edem {

struct MaterialParams {
  MaterialModel model = MaterialModel::elastic;
  double density = 0.0;  // [kg/m^3]
  double bulk = 0.0;     // K [Pa]
  double shear = 0.0;    // G [Pa]
  double e1 = 0.0;       // K + 4G/3 [Pa]
  double e2 = 0.0;       // K - 2G/3 [Pa]
  // Mohr-Coulomb (compression negative): shear failure when s1 - nphi s3 + 2 c sqrt(nphi) < 0,
  // tension failure when s3 > tension.
  double cohesion = 0.0;   // [Pa]
  double nphi = 1.0;       // (1 + sin phi) / (1 - sin phi) [-]
  double npsi = 1.0;       // (1 + sin psi) / (1 - sin psi) [-]
  double csnp = 0.0;       // 2 c sqrt(nphi) [Pa]
  double tension = 0.0;    // tensile strength, capped at c / tan(phi) [Pa]
};

// Checks a definition (a name; finite, physical values; exactly one elastic pair, both of it;
// strength only for model mohr) and derives the parameters. Throws edem::Error naming the key
// and the bad value. The one place a material is checked: material{} passes its message on.
MaterialParams material_params(const MaterialDef& def);

// The definition with the strengths left unset read as 0, as the model keeps it.
MaterialDef with_strength_defaults(MaterialDef def);

}  // namespace edem
