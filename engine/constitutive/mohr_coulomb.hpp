// Zone constitutive kernels: elastic and Mohr-Coulomb with tension cut-off, plane strain.
//
// Both take a strain increment (dexx, deyy, engineering dgxy, and dezz: zero in plane strain
// except for the isotropic share the mixed discretisation gives a zone) and update the stress
// in place. Mohr-Coulomb is the return mapping of FLAC/UDEC in principal stresses: an elastic
// trial, then a correction onto the shear surface (non-associated flow with the dilation
// angle) or the tension cut-off, the region chosen by the bisector h of the two surfaces.
// Compression is negative; s1 <= s2 <= s3, so s1 is the most compressive.
#pragma once

#include <cstdint>

#include "constitutive/material.hpp"
#include "state/stress.hpp"

namespace edem {

inline void elastic_update(const MaterialParams& m, Stress& s, double dexx, double deyy,
                           double dgxy, double dezz = 0.0) {
  s.xx += m.e1 * dexx + m.e2 * (deyy + dezz);
  s.yy += m.e1 * deyy + m.e2 * (dexx + dezz);
  s.zz += m.e1 * dezz + m.e2 * (dexx + deyy);
  s.xy += m.shear * dgxy;
}

// a : C^-1 : b, C the isotropic elastic stiffness: the work one stress does on the elastic
// strain of another [J/m^3]. Half of s : C^-1 : s is the elastic energy a zone stores at s.
inline double compliance_product(const MaterialParams& m, const Stress& a, const Stress& b) {
  const double ma = mean_stress(a), mb = mean_stress(b);
  const double deviatoric = (a.xx - ma) * (b.xx - mb) + (a.yy - ma) * (b.yy - mb) + (a.zz - ma) * (b.zz - mb) +
                            2.0 * a.xy * b.xy;
  return ma * mb / m.bulk + deviatoric / (2.0 * m.shear);
}

// Returns the zone state bits of this step (kShearNow, kTensionNow, or 0 when elastic).
std::uint8_t mohr_coulomb_update(const MaterialParams& m, Stress& s, double dexx, double deyy,
                                 double dgxy, double dezz = 0.0);

// In-plane principal stresses of s: first the most compressive.
struct Principal {
  double s1 = 0.0, s3 = 0.0;
};
Principal in_plane_principal(const Stress& s);

}  // namespace edem
