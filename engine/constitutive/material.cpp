// Zone materials: the checks every law shares (name, density, the elastic pair), then the law's own
// (its registry entry's derive).
#include "constitutive/material.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

bool given(double value) { return !std::isnan(value); }

void check(bool ok, const char* key, double value, const char* rule) {
  if (!ok) fail("{} must be {}, got {}", key, rule, value);
}

// The keys of the other laws given to this one: they would be silently unused.
void check_foreign_keys(const MaterialDef& def, const ZoneLaw& law) {
  std::vector<std::string> foreign;
  std::string takers;
  for (const ZoneLaw* other : zone_laws())
    for (const ZoneLawParam& param : other->params) {
      const bool set = param.number ? given(def.*param.number) : !law_table(def, param.key).empty();
      if (!set) continue;
      bool own = false;
      for (const ZoneLawParam& mine : law.params) own = own || mine.key == param.key;
      if (own || std::find(foreign.begin(), foreign.end(), param.key) != foreign.end()) continue;
      foreign.emplace_back(param.key);
      if (takers.empty()) takers = laws_taking(param.key);
    }
  if (!foreign.empty())
    fail("{} need{} model = {} (this material's model is \"{}\")", fmt::join(foreign, ", "),
         foreign.size() == 1 ? "s" : "", takers, law.name);
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
  const ZoneLaw& law = zone_law(def.model);
  if (!young && !bulk && !law.is_void) fail("missing elastic constants: give young and poisson, or bulk and shear");
  check_foreign_keys(def, law);
  if (law.is_void) return p;
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
  if (law.derive) law.derive(def, p);
  return p;
}

}  // namespace edem
