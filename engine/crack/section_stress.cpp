#include "crack/section_stress.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace edem {
namespace {

// The best uniform field: the mean of the zones' stresses, less the body force's potential at
// each (it is zero at the point).
SectionWeights mean_weights(Vec2 point, std::span<const Vec2> centroids, Vec2 body_force) {
  SectionWeights out;
  const size_t n = centroids.size();
  out.w.assign(n, std::array<double, 9>{});
  if (n == 0) return out;
  const double share = 1.0 / static_cast<double>(n);
  for (size_t k = 0; k < n; ++k) {
    out.w[k] = {share, 0, 0, 0, share, 0, 0, 0, share};
    const Vec2 d = centroids[k] - point;
    const double v = -(body_force.x * d.x + body_force.y * d.y);
    out.offset[0] -= share * v;
    out.offset[1] -= share * v;
  }
  return out;
}

}  // namespace

SectionWeights section_weights(Vec2 point, std::span<const Vec2> centroids, Vec2 body_force) {
  const Eigen::Index n = static_cast<Eigen::Index>(centroids.size());
  if (n < 3) return mean_weights(point, centroids, body_force);
  double spread = 0.0;
  for (const Vec2 c : centroids) spread += dot(c - point, c - point);
  const double h = std::sqrt(spread / static_cast<double>(n));
  if (!(h > 0.0)) return mean_weights(point, centroids, body_force);

  // Unknowns, with x = h xi, y = h eta: c = (2 a1, 2 a3, -a2, 6 b1 h, 2 b2 h, 2 b3 h, 6 b4 h),
  //   syy = c0 + c3 xi + c4 eta,  sxx = c1 + c5 xi + c6 eta,  sxy = c2 - c4 xi - c5 eta.
  // Rows per zone: its syy - V, sxx - V, sxy.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3 * n, 7);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vec2 d = centroids[static_cast<size_t>(k)] - point;
    const double xi = d.x / h, eta = d.y / h;
    const Eigen::Index yy = 3 * k, xx = 3 * k + 1, xy = 3 * k + 2;
    a(yy, 0) = 1.0, a(yy, 3) = xi, a(yy, 4) = eta;
    a(xx, 1) = 1.0, a(xx, 5) = xi, a(xx, 6) = eta;
    a(xy, 2) = 1.0, a(xy, 4) = -xi, a(xy, 5) = -eta;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 7) return mean_weights(point, centroids, body_force);
  // The least-squares solution operator, rows c0..c6 over the 3n data.
  const Eigen::MatrixXd solve = qr.solve(Eigen::MatrixXd::Identity(3 * n, 3 * n));
  SectionWeights out;
  out.linear = true;
  out.w.resize(static_cast<size_t>(n));
  // Rows of the result: sxx = c1, syy = c0, sxy = c2.
  const Eigen::Index row_of[3] = {1, 0, 2};
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vec2 d = centroids[static_cast<size_t>(k)] - point;
    const double v = -(body_force.x * d.x + body_force.y * d.y);
    auto& w = out.w[static_cast<size_t>(k)];
    for (int r = 0; r < 3; ++r) {
      const Eigen::Index row = row_of[r];
      w[static_cast<size_t>(3 * r + 0)] = solve(row, 3 * k + 1);  // from the zone's sxx
      w[static_cast<size_t>(3 * r + 1)] = solve(row, 3 * k);      // from its syy
      w[static_cast<size_t>(3 * r + 2)] = solve(row, 3 * k + 2);  // from its sxy
      out.offset[static_cast<size_t>(r)] -= (solve(row, 3 * k) + solve(row, 3 * k + 1)) * v;
    }
  }
  return out;
}

Stress apply_weights(const SectionWeights& weights, std::span<const Stress> stresses) {
  Stress s;
  double out[3] = {weights.offset[0], weights.offset[1], weights.offset[2]};
  for (size_t k = 0; k < stresses.size(); ++k) {
    const auto& w = weights.w[k];
    const Stress& z = stresses[k];
    for (int r = 0; r < 3; ++r)
      out[r] += w[static_cast<size_t>(3 * r)] * z.xx + w[static_cast<size_t>(3 * r + 1)] * z.yy +
                w[static_cast<size_t>(3 * r + 2)] * z.xy;
    s.zz += z.zz;
  }
  s.xx = out[0], s.yy = out[1], s.xy = out[2];
  if (!stresses.empty()) s.zz /= static_cast<double>(stresses.size());
  return s;
}

SectionStress section_stress(Vec2 point, std::span<const ZoneSample> zones, Vec2 body_force) {
  std::vector<Vec2> centroids;
  std::vector<Stress> stresses;
  for (const ZoneSample& z : zones) {
    centroids.push_back(z.centroid);
    stresses.push_back(z.stress);
  }
  const SectionWeights weights = section_weights(point, centroids, body_force);
  const Stress s = apply_weights(weights, stresses);
  return {s, in_plane_principal(s), weights.linear};
}

}  // namespace edem
