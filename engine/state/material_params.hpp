// A zone material once checked, in the form the kernels use (constitutive/material.hpp makes it).
//
// One MaterialParams per material; zones refer to it by index. Moduli are plane-strain ready
// (e1 = K + 4G/3, e2 = K - 2G/3); the Mohr-Coulomb constants are precomputed once.
#pragma once

#include <vector>

#include "core/physics_defs.hpp"

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
  // A law's own constants beyond these, packed by its derive and read by its update (its tables).
  std::vector<double> law_data;
};

}  // namespace edem
