// The seed's cubic, sn = -4.302 v^3 + 7.688 v^2 - 0.123 v (MPa, v in mm), is a lab curve with
// two defects: it gives tension (down to -0.0005 MPa) for v < 0.0161 mm and its tangent falls
// to zero at v = 1.183 mm and turns negative beyond, where no time step would be stable. Clamped
// here so that the stiffness is always positive and the polynomial never gives tension:
//   * the curve starts at its zero crossing v0 = 0.0161 mm, offset by it: sn(c) = f(c + v0),
//     tangent 122 MPa/m at c = 0;
//   * past the point of the descending branch where the tangent is back down to 1880 MPa/m (the
//     third stage of the seed's three-stage fit, reached at v = 1.042 mm, sn = 3.35 MPa), it goes
//     on straight with that stiffness.
// The tangent is largest, 4456 MPa/m, at the inflection v = 0.596 mm: the time step allows for it.
// Scaled by similarity (law_stress_scale S, law_closure_scale L) the law is S * f(closure / L):
// every stress times S, every closure times L, every stiffness times S / L.
#include "contact/joint_law.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace edem {
namespace {

constexpr double kMPa = 1e6, kMm = 1e-3;
constexpr double kA = -4.302, kB = 7.688, kC = -0.123;  // MPa and mm
constexpr double kThirdStage = 1880e6;                   // [Pa/m]

double cubic(double v_mm) { return ((kA * v_mm + kB) * v_mm + kC) * v_mm; }         // [MPa]
double cubic_slope(double v_mm) { return (3.0 * kA * v_mm + 2.0 * kB) * v_mm + kC; }  // [MPa/mm]

// Zero crossing between the local minimum and the rise: f(v)/v = 0 -> kA v^2 + kB v + kC = 0.
double start_mm() { return (-kB + std::sqrt(kB * kB - 4.0 * kA * kC)) / (2.0 * kA); }

// The descending-branch point where the tangent equals the third stage's stiffness.
double straight_from_mm() {
  const double a = 3.0 * kA, b = 2.0 * kB, c = kC - kThirdStage * kMm / kMPa;
  return (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

double cubic_stress(double closure) {
  const double v0 = start_mm(), v1 = straight_from_mm();
  const double v = closure / kMm + v0;
  if (v <= v1) return cubic(v) * kMPa;
  return cubic(v1) * kMPa + kThirdStage * (v - v1) * kMm;
}

// The integral of cubic_stress from 0 to `closure` [J/m^2].
double cubic_energy(double closure) {
  const auto antiderivative = [](double v_mm) {  // of cubic() [MPa mm]
    return ((0.25 * kA * v_mm + kB / 3.0) * v_mm + 0.5 * kC) * v_mm * v_mm;
  };
  const double v0 = start_mm(), v1 = straight_from_mm();
  const double v = closure / kMm + v0;
  constexpr double kMPaMm = kMPa * kMm;  // [J/m^2]
  if (v <= v1) return (antiderivative(v) - antiderivative(v0)) * kMPaMm;
  const double past = (v - v1) * kMm;  // [m]
  return (antiderivative(v1) - antiderivative(v0)) * kMPaMm + cubic(v1) * kMPa * past +
         0.5 * kThirdStage * past * past;
}

void check_finite_ge0(double value, const char* key) {
  if (!std::isfinite(value) || value < 0.0) fail("{} must be a finite number >= 0, got {}", key, value);
}

}  // namespace

double seed_cubic_raw(double v) { return cubic(v / kMm) * kMPa; }

JointParams joint_params(const JointMaterialDef& def) {
  if (def.name.empty()) fail("a joint material needs a name");
  JointParams p;
  p.law = def.law;
  if (!(std::isfinite(def.ks) && def.ks > 0.0)) fail("ks must be a finite number > 0, got {}", def.ks);
  p.ks = def.ks;
  if (!(std::isfinite(def.friction) && def.friction >= 0.0 && def.friction < 90.0))
    fail("friction must be in [0, 90) degrees, got {}", def.friction);
  if (!(std::isfinite(def.dilation) && def.dilation >= 0.0 && def.dilation <= def.friction))
    fail("dilation must be in [0, friction = {}] degrees, got {}", def.friction, def.dilation);
  check_finite_ge0(def.cohesion, "cohesion");
  check_finite_ge0(def.tension, "tension");
  p.tan_friction = std::tan(def.friction * M_PI / 180.0);
  p.tan_dilation = std::tan(def.dilation * M_PI / 180.0);
  p.cohesion = def.cohesion;
  p.tension = def.tension;
  check_finite_ge0(def.residual_cohesion, "residual_cohesion");
  if (def.residual_cohesion > def.cohesion)
    fail("residual_cohesion must be at most cohesion = {}, got {}", def.cohesion, def.residual_cohesion);
  p.residual_cohesion = def.residual_cohesion;
  const double residual_friction = std::isnan(def.residual_friction) ? def.friction : def.residual_friction;
  if (!(std::isfinite(residual_friction) && residual_friction >= 0.0 && residual_friction < 90.0))
    fail("residual_friction must be in [0, 90) degrees, got {}", residual_friction);
  if (def.dilation > residual_friction)  // it dilates while slipping, at residual strength
    fail("dilation must be at most residual_friction = {} degrees, got {}", residual_friction, def.dilation);
  p.tan_residual_friction = std::tan(residual_friction * M_PI / 180.0);
  check_finite_ge0(def.fracture_energy, "fracture_energy");
  check_finite_ge0(def.shear_fracture_energy, "shear_fracture_energy");
  if (def.fracture_energy > 0.0 && !(def.tension > 0.0))
    fail("fracture_energy = {} needs a tension > 0 to soften from", def.fracture_energy);
  if (def.shear_fracture_energy > 0.0 && !(def.cohesion > def.residual_cohesion))
    fail(
        "shear_fracture_energy = {} needs a cohesion above residual_cohesion = {} to soften from, "
        "got cohesion = {}",
        def.shear_fracture_energy, def.residual_cohesion, def.cohesion);
  p.softens = def.fracture_energy > 0.0 || def.shear_fracture_energy > 0.0;
  p.opening_at_loss = def.fracture_energy > 0.0 ? 2.0 * def.fracture_energy / def.tension : 0.0;
  p.slip_at_loss = def.shear_fracture_energy > 0.0
                       ? 2.0 * def.shear_fracture_energy / (def.cohesion - def.residual_cohesion)
                       : 0.0;
  const bool kn_given = !std::isnan(def.kn);
  const bool scaled = def.law_stress_scale != 1.0 || def.law_closure_scale != 1.0;
  if (scaled && def.law != NormalLaw::seed_cubic)
    fail("stress_scale and closure_scale scale a named law: give kn_law, or leave them out");
  for (auto [value, key] :
       {std::pair{def.law_stress_scale, "stress_scale"}, {def.law_closure_scale, "closure_scale"}})
    if (!(std::isfinite(value) && value > 0.0))
      fail("{} must be a finite number > 0, got {}", key, value);
  p.law_stress_scale = def.law_stress_scale;
  p.law_closure_scale = def.law_closure_scale;
  switch (def.law) {
    case NormalLaw::linear:
      if (!kn_given) fail("kn is missing: give kn, kn_table or kn_law");
      if (!(std::isfinite(def.kn) && def.kn > 0.0)) fail("kn must be a finite number > 0, got {}", def.kn);
      p.kn = p.kn_zero = p.kn_max = def.kn;
      break;
    case NormalLaw::table: {
      if (kn_given) fail("give kn or kn_table, not both");
      const auto& t = def.kn_table;
      if (t.empty()) fail("kn_table needs at least one stage {{closure, kn}}");
      if (t[0][0] != 0.0) fail("kn_table's first stage must start at closure 0, got {}", t[0][0]);
      double stress = 0.0;
      for (size_t i = 0; i < t.size(); ++i) {
        if (!(std::isfinite(t[i][1]) && t[i][1] > 0.0))
          fail("kn_table stage {}: kn must be a finite number > 0, got {}", i + 1, t[i][1]);
        if (i > 0) {
          if (!(std::isfinite(t[i][0]) && t[i][0] > t[i - 1][0]))
            fail("kn_table stage {}: closures must increase, got {} after {}", i + 1, t[i][0], t[i - 1][0]);
          stress += t[i - 1][1] * (t[i][0] - t[i - 1][0]);
        }
        p.stage_closure.push_back(t[i][0]);
        p.stage_kn.push_back(t[i][1]);
        p.stage_stress.push_back(stress);
        p.kn_max = std::max(p.kn_max, t[i][1]);
      }
      p.kn_zero = t[0][1];
      break;
    }
    case NormalLaw::seed_cubic: {
      if (kn_given) fail("give kn or kn_law, not both");
      const double stiffness = p.law_stress_scale / p.law_closure_scale;
      p.kn_zero = stiffness * cubic_slope(start_mm()) * kMPa / kMm;
      const double inflection = -2.0 * kB / (6.0 * kA);
      p.kn_max = stiffness * cubic_slope(inflection) * kMPa / kMm;
      p.curve_closure = p.law_closure_scale * (straight_from_mm() - start_mm()) * kMm;
      break;
    }
  }
  // Past the peak the traction must fall as the opening grows: the linear branch from the peak
  // opening tension / kn_zero to 2 G_I / tension needs G_I above the elastic energy at the peak.
  if (def.fracture_energy > 0.0 && !(p.opening_at_loss > def.tension / p.kn_zero))
    fail(
        "fracture_energy must be more than tension^2 / (2 kn) = {:.6g} J/m^2 (the elastic energy "
        "at the peak), got {}",
        def.tension * def.tension / (2.0 * p.kn_zero), def.fracture_energy);
  return p;
}

double bond_left(const JointParams& p, double opened, double slip) {
  const double peak = p.tension / p.kn_zero;
  double in_opening = 1.0;
  if (opened > peak)
    in_opening = p.opening_at_loss > 0.0
                     ? std::max(0.0, (p.opening_at_loss - opened) / (p.opening_at_loss - peak))
                     : 0.0;
  const double in_slip =
      p.slip_at_loss > 0.0 ? std::max(0.0, 1.0 - slip / p.slip_at_loss) : (slip > 0.0 ? 0.0 : 1.0);
  return std::min(in_opening, in_slip);
}

double normal_stress(const JointParams& p, double closure) {
  if (closure <= 0.0) return p.kn_zero * closure;
  switch (p.law) {
    case NormalLaw::linear:
      return p.kn * closure;
    case NormalLaw::table: {
      size_t i = p.stage_closure.size() - 1;
      while (i > 0 && closure < p.stage_closure[i]) --i;
      return p.stage_stress[i] + p.stage_kn[i] * (closure - p.stage_closure[i]);
    }
    case NormalLaw::seed_cubic:
      return p.law_stress_scale * cubic_stress(closure / p.law_closure_scale);
  }
  return 0.0;
}

double normal_energy(const JointParams& p, double closure) {
  if (closure <= 0.0) return 0.5 * p.kn_zero * closure * closure;
  switch (p.law) {
    case NormalLaw::linear:
      return 0.5 * p.kn * closure * closure;
    case NormalLaw::table: {
      double energy = 0.0;
      for (size_t i = 0; i < p.stage_closure.size(); ++i) {
        const double from = p.stage_closure[i];
        const double to = i + 1 < p.stage_closure.size() ? std::min(closure, p.stage_closure[i + 1]) : closure;
        if (!(to > from)) break;
        energy += (p.stage_stress[i] + 0.5 * p.stage_kn[i] * (to - from)) * (to - from);
      }
      return energy;
    }
    case NormalLaw::seed_cubic:
      return p.law_stress_scale * p.law_closure_scale * cubic_energy(closure / p.law_closure_scale);
  }
  return 0.0;
}

double closure_at(const JointParams& p, double stress) {
  if (stress <= 0.0) return stress / p.kn_zero;
  switch (p.law) {
    case NormalLaw::linear:
      return stress / p.kn;
    case NormalLaw::table: {
      size_t i = p.stage_stress.size() - 1;
      while (i > 0 && stress < p.stage_stress[i]) --i;
      return p.stage_closure[i] + (stress - p.stage_stress[i]) / p.stage_kn[i];
    }
    case NormalLaw::seed_cubic: {
      // Monotone: bisection to machine precision on a bracket that holds the answer, on the
      // unscaled curve.
      const double lab_stress = stress / p.law_stress_scale;
      const double lab_kn_zero = p.kn_zero * p.law_closure_scale / p.law_stress_scale;
      double lo = 0.0, hi = lab_stress / lab_kn_zero + 1e-3;
      while (cubic_stress(hi) < lab_stress) hi *= 2.0;
      for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (cubic_stress(mid) < lab_stress ? lo : hi) = mid;
      }
      return p.law_closure_scale * 0.5 * (lo + hi);
    }
  }
  return 0.0;
}

}  // namespace edem
