// Zone law `mohr`: Mohr-Coulomb with tension cut-off (the kernel, mohr_coulomb.hpp), and its
// registry entry: keys cohesion, friction, dilation, tension.
#include "constitutive/mohr_coulomb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"
#include "core/physics_defs.hpp"

namespace edem {

Principal in_plane_principal(const Stress& s) {
  const double centre = 0.5 * (s.xx + s.yy);
  const double half = 0.5 * (s.xx - s.yy);
  const double radius = std::sqrt(half * half + s.xy * s.xy);  // no hypot: it is slow
  return {centre - radius, centre + radius};
}

namespace {

// The return mapping, one body for MaterialParams and MohrConstants (both name e1, e2, nphi,
// npsi, csnp, tension), inlined into each kernel so that none pays a call or a copy.
// `before` (nullptr: not wanted) is the stress at the start of the step; `*work` then gets the
// step's plastic work per unit volume: the plastic strain is diagonal in the trial's principal
// frame, so the work is the mid-step stress's normal components on those axes times it, the
// same as plastic_work (mohr_coulomb.hpp) at a fraction of its cost.
template <class P>
[[gnu::always_inline]] inline std::uint8_t return_mapping(const P& m, Stress& s, double* shear_lambda,
                                                          const Stress* before, double* work) {
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
  double strain_1 = 0.0, strain_3 = 0.0;  // the plastic strain along s1 and s3 (none along s2)
  if (fs < 0.0 && h <= 0.0) {
    const double e1 = m.e1, e2 = m.e2;
    const double lambda = fs / ((e1 - e2 * m.npsi) - (e2 - e1 * m.npsi) * m.nphi);
    p[0] -= lambda * (e1 - e2 * m.npsi);
    p[1] -= lambda * e2 * (1.0 - m.npsi);
    p[2] -= lambda * (e2 - e1 * m.npsi);
    if (shear_lambda) *shear_lambda = lambda;
    strain_1 = lambda, strain_3 = -lambda * m.npsi;
    state = kShearNow;
  } else {
    const double drop = m.tension - p[2];  // < 0
    p[0] += drop * m.e2 / m.e1;
    p[1] += drop * m.e2 / m.e1;
    p[2] = m.tension;
    strain_3 = -drop / m.e1;
    state = kTensionNow;
  }

  if (before) {
    // The start's normal stresses on the axes of a, b and zz.
    const double bc = 0.5 * (before->xx + before->yy);
    const double bh = 0.5 * (before->xx - before->yy) * cos2 + before->xy * sin2;
    const double on_a = bc - bh, on_b = bc + bh;
    const double start_1 = zz_at == 0 ? before->zz : on_a;
    const double start_3 = zz_at == 2 ? before->zz : on_b;
    *work = 0.5 * ((start_1 + p[0]) * strain_1 + (start_3 + p[2]) * strain_3);
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

}  // namespace

std::uint8_t mohr_coulomb_update(const MaterialParams& m, Stress& s, double dexx, double deyy,
                                 double dgxy, double dezz) {
  elastic_update(m, s, dexx, deyy, dgxy, dezz);
  return return_mapping(m, s, nullptr, nullptr, nullptr);
}

std::uint8_t mohr_coulomb_return(const MohrConstants& m, Stress& s, double* shear_lambda, const Stress* before,
                                 double* work) {
  return return_mapping(m, s, shear_lambda, before, work);
}

}  // namespace edem

namespace edem {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

void check(bool ok, const char* key, double value, const char* rule) {
  if (!ok) fail("{} must be {}, got {}", key, rule, value);
}

void derive_mohr(const MaterialDef& def, MaterialParams& p) {
  const MaterialDef d = with_strength_defaults(def);
  check(std::isfinite(d.cohesion) && d.cohesion >= 0.0, "cohesion", d.cohesion, ">= 0");
  check(d.friction >= 0.0 && d.friction < 90.0, "friction", d.friction, "in [0, 90)");
  if (!(d.dilation <= d.friction)) fail("dilation must be <= friction ({}), got {}", d.friction, d.dilation);
  check(d.dilation >= 0.0, "dilation", d.dilation, ">= 0");
  check(std::isfinite(d.tension) && d.tension >= 0.0, "tension", d.tension, ">= 0");
  set_mohr_strength(p, d.cohesion, d.friction, d.dilation, d.tension);
}

// The registry's kernel: the trial, the return mapping and the plastic work in one body.
std::uint8_t update_mohr(const MaterialParams& p, Stress& s, double dxx, double dyy, double dxy, double dzz,
                         double&, double* work) {
  const Stress before = s;
  elastic_update(p, s, dxx, dyy, dxy, dzz);
  return return_mapping(p, s, nullptr, work ? &before : nullptr, work);
}

bool unsymmetric_mohr(const MaterialParams& p) { return p.npsi != p.nphi; }

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

MohrConstants mohr_strength(double e1, double e2, double cohesion, double friction, double dilation,
                            double tension) {
  const double sphi = std::sin(radians(friction)), spsi = std::sin(radians(dilation));
  MohrConstants k{e1, e2, (1.0 + sphi) / (1.0 - sphi), (1.0 + spsi) / (1.0 - spsi), 0.0, tension};
  k.csnp = 2.0 * cohesion * std::sqrt(k.nphi);
  // The tension cut-off cannot lie beyond the apex of the shear cone (as in FLAC and UDEC).
  if (friction > 0.0) k.tension = std::min(k.tension, cohesion / std::tan(radians(friction)));
  return k;
}

void set_mohr_strength(MaterialParams& p, double cohesion, double friction, double dilation, double tension) {
  const MohrConstants k = mohr_strength(p.e1, p.e2, cohesion, friction, dilation, tension);
  p.cohesion = cohesion;
  p.nphi = k.nphi;
  p.npsi = k.npsi;
  p.csnp = k.csnp;
  p.tension = k.tension;
}

// The strength keys, shared with the laws that build on this one.
const ZoneLawParam kMohrParams[4] = {
    {.key = "cohesion", .unit = "Pa", .lo = 0, .hi = kInf, .help = "cohesion", .absent = "0",
     .number = &MaterialDef::cohesion},
    {.key = "friction", .unit = "deg", .lo = 0, .hi = 90, .hi_open = true, .help = "friction angle",
     .absent = "0", .number = &MaterialDef::friction},
    {.key = "dilation", .unit = "deg", .lo = 0, .hi = kInf, .help = "dilation angle, at most friction",
     .absent = "0", .number = &MaterialDef::dilation},
    {.key = "tension", .unit = "Pa", .lo = 0, .hi = kInf, .help = "tensile strength",
     .note = "; capped at cohesion / tan(friction)", .absent = "0", .number = &MaterialDef::tension},
};

extern const ZoneLaw mohr_coulomb_law;
const ZoneLaw mohr_coulomb_law{
    .name = "mohr",
    .description = "Mohr-Coulomb: elastic until it fails in shear or tension",
    .params = kMohrParams,
    .derive = derive_mohr,
    .update = update_mohr,
    .unsymmetric = unsymmetric_mohr,
    .has_strength = true,
};

}  // namespace edem
