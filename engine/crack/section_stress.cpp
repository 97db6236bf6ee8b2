#include "crack/section_stress.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace edem {
namespace {

SectionStress finish(Stress s, bool linear) {
  return {s, in_plane_principal(s), linear};
}

// The best uniform field: the mean of the zones' stresses, less the body force's potential at
// each (it is zero at the point).
SectionStress mean_field(Vec2 point, std::span<const ZoneSample> zones, Vec2 body_force) {
  Stress s;
  if (zones.empty()) return finish(s, false);
  for (const ZoneSample& z : zones) {
    const Vec2 d = z.centroid - point;
    const double v = -(body_force.x * d.x + body_force.y * d.y);
    s.xx += z.stress.xx - v;
    s.yy += z.stress.yy - v;
    s.xy += z.stress.xy;
    s.zz += z.stress.zz;
  }
  const double n = static_cast<double>(zones.size());
  s.xx /= n, s.yy /= n, s.xy /= n, s.zz /= n;
  return finish(s, false);
}

}  // namespace

SectionStress section_stress(Vec2 point, std::span<const ZoneSample> zones, Vec2 body_force) {
  const Eigen::Index n = static_cast<Eigen::Index>(zones.size());
  if (n < 3) return mean_field(point, zones, body_force);
  double spread = 0.0;
  for (const ZoneSample& z : zones) spread += dot(z.centroid - point, z.centroid - point);
  const double h = std::sqrt(spread / static_cast<double>(n));
  if (!(h > 0.0)) return mean_field(point, zones, body_force);

  // Unknowns, with x = h xi, y = h eta: c = (2 a1, 2 a3, -a2, 6 b1 h, 2 b2 h, 2 b3 h, 6 b4 h),
  //   syy = c0 + c3 xi + c4 eta,  sxx = c1 + c5 xi + c6 eta,  sxy = c2 - c4 xi - c5 eta.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3 * n, 7);
  Eigen::VectorXd rhs(3 * n);
  double szz = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const ZoneSample& z = zones[static_cast<size_t>(k)];
    const Vec2 d = z.centroid - point;
    const double xi = d.x / h, eta = d.y / h;
    const double v = -(body_force.x * d.x + body_force.y * d.y);
    const Eigen::Index yy = 3 * k, xx = 3 * k + 1, xy = 3 * k + 2;
    a(yy, 0) = 1.0, a(yy, 3) = xi, a(yy, 4) = eta;
    rhs(yy) = z.stress.yy - v;
    a(xx, 1) = 1.0, a(xx, 5) = xi, a(xx, 6) = eta;
    rhs(xx) = z.stress.xx - v;
    a(xy, 2) = 1.0, a(xy, 4) = -xi, a(xy, 5) = -eta;
    rhs(xy) = z.stress.xy;
    szz += z.stress.zz;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 7) return mean_field(point, zones, body_force);
  const Eigen::VectorXd c = qr.solve(rhs);
  Stress s;
  s.yy = c(0);
  s.xx = c(1);
  s.xy = c(2);
  s.zz = szz / static_cast<double>(n);
  return finish(s, true);
}

}  // namespace edem
