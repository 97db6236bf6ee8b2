// The stress at a potential-crack section (seed paper §2.3): an equilibrium-satisfying linear
// stress field fitted by least squares to the stresses of the zones around the section's
// calculation point, evaluated at the point.
//
// The field comes from an Airy stress function with quadratic and cubic terms,
//   Phi = a1 x^2 + a2 x y + a3 y^2 + b1 x^3 + b2 x^2 y + b3 x y^2 + b4 y^3,
// in coordinates centred on the point, plus the potential V = -(bx x + by y) of a uniform body
// force b = rho g [N/m^3]:
//   sxx = Phi_yy + V = 2 a3 + 2 b3 x + 6 b4 y + V
//   syy = Phi_xx + V = 2 a1 + 6 b1 x + 2 b2 y + V
//   sxy = -Phi_xy    = -a2 - 2 b2 x - 2 b3 y,
// which satisfies div(sigma) + b = 0 for every choice of the seven coefficients: the linear
// fields in equilibrium (nine coefficients of a linear field less the two equilibrium
// equations). Each zone gives three equations (its sxx, syy, sxy at its centroid, where a
// constant-strain triangle's stress is best); the seven coefficients minimise the sum of
// squared differences, with the coordinates scaled by their RMS distance from the point so
// that the constant and the linear columns are of one size. At the point, sxx = 2 a3,
// syy = 2 a1, sxy = -a2 (V = 0 there). Uniform fields and linear fields in equilibrium (with
// this body force) are reproduced exactly, to round-off.
//
// Fewer than three zones, or zones whose centroids do not span the plane (all on one line),
// cannot fix the linear terms: the fit then falls back to the mean of their stresses, the
// best uniform field, and says so (`linear` false). szz is not part of the plane fit; the
// result carries the zones' mean szz.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "constitutive/mohr_coulomb.hpp"
#include "core/vec2.hpp"

namespace edem {

struct ZoneSample {
  Vec2 centroid;  // [m]
  Stress stress;  // [Pa], compression negative
};

struct SectionStress {
  Stress stress;        // at the point [Pa]
  Principal principal;  // in-plane, s1 <= s3 (compression negative: s1 the most compressive)
  bool linear = false;  // the linear terms were fitted (else: the mean of the zones)
};

// The fit is linear in the zones' stresses: the stress at the point is
//   s = sum_k W_k (sxx_k, syy_k, sxy_k) + offset,
// with W_k and the offset (the body force's part) fixed by the centroids alone. A solver that
// judges a section many times computes them once.
struct SectionWeights {
  std::vector<std::array<double, 9>> w;  // per zone, row-major: rows sxx, syy, sxy at the point,
                                         // columns the zone's sxx, syy, sxy
  std::array<double, 3> offset{};        // sxx, syy, sxy [Pa]
  bool linear = false;                   // as SectionStress::linear
};

SectionWeights section_weights(Vec2 point, std::span<const Vec2> centroids, Vec2 body_force = {});

// s = sum W_k sigma_k + offset (szz: the zones' mean).
Stress apply_weights(const SectionWeights& weights, std::span<const Stress> stresses);

// The fitted stress at `point` from `zones`; `body_force` = rho g [N/m^3] (zero: none).
SectionStress section_stress(Vec2 point, std::span<const ZoneSample> zones, Vec2 body_force = {});

}  // namespace edem
