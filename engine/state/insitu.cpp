#include "state/insitu.hpp"

#include <cmath>

#include "core/error.hpp"
#include "geom/polygon.hpp"

namespace edem {

void check_insitu(const InsituDef& def) {
  auto finite = [](double value, const char* key) {
    if (!std::isfinite(value)) fail("{} must be a finite number, got {}", key, value);
  };
  if (def.from_surface) {
    finite(def.surface, "surface");
    finite(def.surcharge, "surcharge");
    if (!(def.density >= 0.0) || !std::isfinite(def.density))
      fail("density must be >= 0, got {}", def.density);
    if (!(def.k0 >= 0.0) || !std::isfinite(def.k0)) fail("k0 must be >= 0, got {}", def.k0);
    return;
  }
  finite(def.sxx, "sxx");
  finite(def.syy, "syy");
  finite(def.sxy, "sxy");
  if (!std::isnan(def.szz)) finite(def.szz, "szz");
  for (double g : def.ygrad) finite(g, "ygrad");
}

Stress insitu_stress(const InsituDef& def, Vec2 point, double g) {
  Stress s;
  if (def.from_surface) {
    const double vertical = -(def.surcharge + def.density * g * (def.surface - point.y));
    s.yy = vertical;
    s.xx = s.zz = def.k0 * vertical;
    return s;
  }
  const double y = point.y;
  s.xx = def.sxx + def.ygrad[0] * y;
  s.yy = def.syy + def.ygrad[1] * y;
  s.xy = def.sxy + def.ygrad[2] * y;
  s.zz = std::isnan(def.szz) ? s.xx : def.szz + def.ygrad[3] * y;
  return s;
}

std::optional<Stress> insitu_stress_if_any(const Mechanics& m, Vec2 point) {
  const auto& regions = m.insitu_regions;
  const double g = m.gravity_set ? norm(m.gravity) : 9.81;
  for (size_t i = m.insitu.size(); i-- > 0;)
    if (regions[i].empty() || contains(regions[i], point))
      return insitu_stress(m.insitu[i], point, g);
  return std::nullopt;
}

Stress insitu_stress_at(const Mechanics& m, Vec2 point) {
  if (const auto s = insitu_stress_if_any(m, point)) return *s;
  fail("stress = \"insitu\" needs an insitu{{...}} covering ({:.6g}, {:.6g}) first", point.x,
       point.y);
}

}  // namespace edem
