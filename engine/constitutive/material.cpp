#include "constitutive/material.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"

namespace edem {
namespace {

bool given(double value) { return !std::isnan(value); }

void check(bool ok, const char* key, double value, const char* rule) {
  if (!ok) fail("{} must be {}, got {}", key, rule, value);
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

const char* model_name(MaterialModel model) {
  switch (model) {
    case MaterialModel::elastic: return "elastic";
    case MaterialModel::mohr: return "mohr";
    case MaterialModel::null: return "null";
  }
  return "elastic";
}

}  // namespace

MaterialDef with_strength_defaults(MaterialDef def) {
  for (double* value : {&def.cohesion, &def.friction, &def.dilation, &def.tension})
    if (!given(*value)) *value = 0.0;
  return def;
}

MaterialParams material_params(const MaterialDef& def) {
  if (def.name.empty()) fail("name must not be empty");
  MaterialParams p;
  p.model = def.model;
  check(std::isfinite(def.density) && def.density >= 0.0, "density", def.density, ">= 0");
  p.density = def.density;

  // Exactly one pair of elastic constants, both of it (a null material needs none).
  const bool young = given(def.young), poisson = given(def.poisson);
  const bool bulk = given(def.bulk), shear = given(def.shear);
  if ((young || poisson) && (bulk || shear)) fail("give young and poisson, or bulk and shear, not both pairs");
  if (young != poisson)
    fail("{} needs {} too (or give bulk and shear)", young ? "young" : "poisson", young ? "poisson" : "young");
  if (bulk != shear)
    fail("{} needs {} too (or give young and poisson)", bulk ? "bulk" : "shear", bulk ? "shear" : "bulk");
  if (!young && !bulk && def.model != MaterialModel::null)
    fail("missing elastic constants: give young and poisson, or bulk and shear");
  // Strength belongs to the Mohr-Coulomb model: given to another, it would be silently unused.
  if (def.model != MaterialModel::mohr) {
    std::vector<std::string> strengths;
    for (const auto& [key, value] : {std::pair{"cohesion", def.cohesion}, std::pair{"friction", def.friction},
                                     std::pair{"dilation", def.dilation}, std::pair{"tension", def.tension}})
      if (given(value)) strengths.emplace_back(key);
    if (!strengths.empty())
      fail("{} need{} model = \"mohr\" (this material's model is \"{}\")", fmt::join(strengths, ", "),
           strengths.size() == 1 ? "s" : "", model_name(def.model));
  }
  if (def.model == MaterialModel::null) return p;
  if (young) {
    check(std::isfinite(def.young) && def.young > 0.0, "young", def.young, "> 0");
    check(def.poisson > -1.0 && def.poisson < 0.5, "poisson", def.poisson, "in (-1, 0.5)");
    p.bulk = def.young / (3.0 * (1.0 - 2.0 * def.poisson));
    p.shear = def.young / (2.0 * (1.0 + def.poisson));
  } else {
    check(std::isfinite(def.bulk) && def.bulk > 0.0, "bulk", def.bulk, "> 0");
    check(std::isfinite(def.shear) && def.shear > 0.0, "shear", def.shear, "> 0");
    p.bulk = def.bulk;
    p.shear = def.shear;
  }
  p.e1 = p.bulk + 4.0 * p.shear / 3.0;
  p.e2 = p.bulk - 2.0 * p.shear / 3.0;
  if (def.model != MaterialModel::mohr) return p;

  const MaterialDef d = with_strength_defaults(def);
  check(std::isfinite(d.cohesion) && d.cohesion >= 0.0, "cohesion", d.cohesion, ">= 0");
  check(d.friction >= 0.0 && d.friction < 90.0, "friction", d.friction, "in [0, 90)");
  if (!(d.dilation <= d.friction)) fail("dilation must be <= friction ({}), got {}", d.friction, d.dilation);
  check(d.dilation >= 0.0, "dilation", d.dilation, ">= 0");
  check(std::isfinite(d.tension) && d.tension >= 0.0, "tension", d.tension, ">= 0");
  const double sphi = std::sin(radians(d.friction)), spsi = std::sin(radians(d.dilation));
  p.cohesion = d.cohesion;
  p.nphi = (1.0 + sphi) / (1.0 - sphi);
  p.npsi = (1.0 + spsi) / (1.0 - spsi);
  p.csnp = 2.0 * d.cohesion * std::sqrt(p.nphi);
  // The tension cut-off cannot lie beyond the apex of the shear cone (as in FLAC and UDEC).
  p.tension = d.tension;
  if (d.friction > 0.0)
    p.tension = std::min(p.tension, d.cohesion / std::tan(radians(d.friction)));
  return p;
}

}  // namespace edem
