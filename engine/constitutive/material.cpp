#include "constitutive/material.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace edem {
namespace {

bool given(double value) { return !std::isnan(value); }

void check(bool ok, const char* key, double value, const char* rule) {
  if (!ok) fail("{} must be {}, got {}", key, rule, value);
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

MaterialParams material_params(const MaterialDef& def) {
  MaterialParams p;
  p.model = def.model;
  check(std::isfinite(def.density) && def.density >= 0.0, "density", def.density, ">= 0");
  p.density = def.density;
  if (def.model == MaterialModel::null) return p;

  const bool young_pair = given(def.young) || given(def.poisson);
  const bool bulk_pair = given(def.bulk) || given(def.shear);
  if (young_pair && bulk_pair) fail("give either young and poisson, or bulk and shear, not both");
  if (!young_pair && !bulk_pair) fail("elastic constants missing: give young and poisson, or bulk and shear");
  if (young_pair) {
    if (!given(def.young) || !given(def.poisson)) fail("young and poisson go together: give both");
    check(std::isfinite(def.young) && def.young > 0.0, "young", def.young, "> 0");
    check(def.poisson > -1.0 && def.poisson < 0.5, "poisson", def.poisson, "in (-1, 0.5)");
    p.bulk = def.young / (3.0 * (1.0 - 2.0 * def.poisson));
    p.shear = def.young / (2.0 * (1.0 + def.poisson));
  } else {
    if (!given(def.bulk) || !given(def.shear)) fail("bulk and shear go together: give both");
    check(std::isfinite(def.bulk) && def.bulk > 0.0, "bulk", def.bulk, "> 0");
    check(std::isfinite(def.shear) && def.shear > 0.0, "shear", def.shear, "> 0");
    p.bulk = def.bulk;
    p.shear = def.shear;
  }
  p.e1 = p.bulk + 4.0 * p.shear / 3.0;
  p.e2 = p.bulk - 2.0 * p.shear / 3.0;
  if (def.model != MaterialModel::mohr) return p;

  check(std::isfinite(def.cohesion) && def.cohesion >= 0.0, "cohesion", def.cohesion, ">= 0");
  check(def.friction >= 0.0 && def.friction < 90.0, "friction", def.friction, "in [0, 90)");
  check(def.dilation >= 0.0 && def.dilation <= def.friction, "dilation", def.dilation,
        "in [0, friction]");
  check(std::isfinite(def.tension) && def.tension >= 0.0, "tension", def.tension, ">= 0");
  const double sphi = std::sin(radians(def.friction)), spsi = std::sin(radians(def.dilation));
  p.cohesion = def.cohesion;
  p.nphi = (1.0 + sphi) / (1.0 - sphi);
  p.npsi = (1.0 + spsi) / (1.0 - spsi);
  p.csnp = 2.0 * def.cohesion * std::sqrt(p.nphi);
  // The tension cut-off cannot lie beyond the apex of the shear cone (as in FLAC and UDEC).
  p.tension = def.tension;
  if (def.friction > 0.0)
    p.tension = std::min(p.tension, def.cohesion / std::tan(radians(def.friction)));
  return p;
}

}  // namespace edem
