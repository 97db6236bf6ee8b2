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

// The plastic work per unit volume [J/m^3] of a step from `before` through the elastic `trial`
// to `after`: the mid-step stress on the plastic strain, C^-1 (trial - after). With the zone's
// strain energy, half of s : C^-1 : s, it closes the zone's balance exactly: the mid-step stress
// on the whole strain increment is their sum.
inline double plastic_work(const MaterialParams& m, const Stress& before, const Stress& trial, const Stress& after) {
  const Stress mid{0.5 * (before.xx + after.xx), 0.5 * (before.yy + after.yy), 0.5 * (before.xy + after.xy),
                   0.5 * (before.zz + after.zz)};
  const Stress returned{trial.xx - after.xx, trial.yy - after.yy, trial.xy - after.xy, trial.zz - after.zz};
  return compliance_product(m, mid, returned);
}

// The constants of the return mapping: moduli and one strength.
struct MohrConstants {
  double e1, e2;           // K + 4G/3, K - 2G/3 [Pa]
  double nphi, npsi, csnp;  // as in MaterialParams
  double tension;          // capped [Pa]
};
inline MohrConstants mohr_constants(const MaterialParams& p) {
  return {p.e1, p.e2, p.nphi, p.npsi, p.csnp, p.tension};
}

// The return mapping alone, of a stress that is already the elastic trial. On shear failure,
// `*shear_lambda` (when not null) gets the plastic multiplier: the plastic principal strain
// increments are lambda * (1, 0, -npsi) along (s1, s2, s3). With `before`, the stress at the
// start of the step, `*work` gets the step's plastic work per unit volume [J/m^3] when it
// yields (the value of plastic_work). Returns the state bits.
std::uint8_t mohr_coulomb_return(const MohrConstants& m, Stress& s, double* shear_lambda,
                                 const Stress* before = nullptr, double* work = nullptr);

// The elastic trial and the return mapping. Returns the zone state bits of this step
// (kShearNow, kTensionNow, or 0 when elastic).
std::uint8_t mohr_coulomb_update(const MaterialParams& m, Stress& s, double dexx, double deyy,
                                 double dgxy, double dezz = 0.0);

// The return mapping's constants of a strength: cohesion and tension [Pa], friction and dilation
// [deg], with the moduli e1, e2. Unchecked.
MohrConstants mohr_strength(double e1, double e2, double cohesion, double friction, double dilation,
                            double tension);

// Sets the Mohr-Coulomb constants of `p` (nphi, npsi, csnp, the capped tension) from a
// strength: cohesion and tension [Pa], friction and dilation [deg]. Unchecked.
void set_mohr_strength(MaterialParams& p, double cohesion, double friction, double dilation, double tension);

// In-plane principal stresses of s: first the most compressive.
struct Principal {
  double s1 = 0.0, s3 = 0.0;
};
Principal in_plane_principal(const Stress& s);

}  // namespace edem
