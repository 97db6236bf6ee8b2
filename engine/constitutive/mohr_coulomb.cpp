#include "constitutive/mohr_coulomb.hpp"

#include <cmath>

#include "core/physics_defs.hpp"

namespace edem {

Principal in_plane_principal(const Stress& s) {
  const double centre = 0.5 * (s.xx + s.yy);
  const double half = 0.5 * (s.xx - s.yy);
  const double radius = std::sqrt(half * half + s.xy * s.xy);  // no hypot: it is slow
  return {centre - radius, centre + radius};
}

std::uint8_t mohr_coulomb_update(const MaterialParams& m, Stress& s, double dexx, double deyy,
                                 double dgxy, double dezz) {
  elastic_update(m, s, dexx, deyy, dgxy, dezz);

  // In-plane principal stresses a <= b and the direction of b (cos 2t, sin 2t).
  const double centre = 0.5 * (s.xx + s.yy), half = 0.5 * (s.xx - s.yy);
  const double radius = std::sqrt(half * half + s.xy * s.xy);  // hypot is several times slower
  const double a = centre - radius, b = centre + radius;
  const double cos2 = radius > 0.0 ? half / radius : 1.0;
  const double sin2 = radius > 0.0 ? s.xy / radius : 0.0;

  // Order the three principal stresses; szz is the out-of-plane one.
  double p[3];  // s1 <= s2 <= s3
  int zz_at;    // where szz sits in p
  if (s.zz <= a) {
    p[0] = s.zz, p[1] = a, p[2] = b, zz_at = 0;
  } else if (s.zz <= b) {
    p[0] = a, p[1] = s.zz, p[2] = b, zz_at = 1;
  } else {
    p[0] = a, p[1] = b, p[2] = s.zz, zz_at = 2;
  }

  const double fs = p[0] - m.nphi * p[2] + m.csnp;  // < 0: shear failure
  const double ft = m.tension - p[2];               // < 0: tension failure
  if (fs >= 0.0 && ft >= 0.0) return 0;

  // Which surface: the sign of h, the function on the bisector of the shear and tension
  // surfaces in the (s1, s3) plane.
  const double alpha_p = std::sqrt(1.0 + m.nphi * m.nphi) + m.nphi;
  const double sigma_p = m.nphi * m.tension - m.csnp;
  const double h = p[2] - m.tension + alpha_p * (p[0] - sigma_p);
  std::uint8_t state = 0;
  if (fs < 0.0 && h <= 0.0) {
    const double e1 = m.e1, e2 = m.e2;
    const double lambda = fs / ((e1 - e2 * m.npsi) - (e2 - e1 * m.npsi) * m.nphi);
    p[0] -= lambda * (e1 - e2 * m.npsi);
    p[1] -= lambda * e2 * (1.0 - m.npsi);
    p[2] -= lambda * (e2 - e1 * m.npsi);
    state = kShearNow;
  } else {
    const double drop = m.tension - p[2];  // < 0
    p[0] += drop * m.e2 / m.e1;
    p[1] += drop * m.e2 / m.e1;
    p[2] = m.tension;
    state = kTensionNow;
  }

  // Back to xx, yy, xy along the unchanged principal directions.
  double na, nb;
  if (zz_at == 0) {
    s.zz = p[0], na = p[1], nb = p[2];
  } else if (zz_at == 1) {
    na = p[0], s.zz = p[1], nb = p[2];
  } else {
    na = p[0], nb = p[1], s.zz = p[2];
  }
  const double new_centre = 0.5 * (na + nb), new_radius = 0.5 * (nb - na);
  s.xx = new_centre + new_radius * cos2;
  s.yy = new_centre - new_radius * cos2;
  s.xy = new_radius * sin2;
  return state;
}

}  // namespace edem
