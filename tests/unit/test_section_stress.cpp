// The stress at a potential-crack section (engine/crack/section_stress.hpp) and the crack
// criteria (engine/crack/criteria.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "crack/criteria.hpp"
#include "crack/section_stress.hpp"

namespace edem {
namespace {

// A linear stress field: s(x, y) = s0 + x sx + y sy per component.
struct LinearField {
  Stress s0, sx, sy;
  Stress at(Vec2 p) const {
    return {s0.xx + p.x * sx.xx + p.y * sy.xx, s0.yy + p.x * sx.yy + p.y * sy.yy,
            s0.xy + p.x * sx.xy + p.y * sy.xy, s0.zz + p.x * sx.zz + p.y * sy.zz};
  }
};

// Four zone centroids on each side of a crack through `point` at `angle` (deg), as the seed
// takes them: along the crack at -1.5 .. 1.5 h, a third of h off it, a little scattered.
std::vector<Vec2> centroids_around(Vec2 point, double angle, double h, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.1 * h, 0.1 * h);
  const double a = angle * std::numbers::pi / 180.0;
  const Vec2 along{std::cos(a), std::sin(a)}, across{-std::sin(a), std::cos(a)};
  std::vector<Vec2> points;
  for (const double side : {-1.0, 1.0})
    for (const double t : {-1.5, -0.5, 0.5, 1.5})
      points.push_back(point + (t * h + jitter(random)) * along +
                       (side * h / 3.0 + jitter(random)) * across);
  return points;
}

std::vector<ZoneSample> sample(const LinearField& field, const std::vector<Vec2>& centroids) {
  std::vector<ZoneSample> zones;
  for (const Vec2 c : centroids) zones.push_back({c, field.at(c)});
  return zones;
}

void expect_stress_near(const Stress& got, const Stress& want, double tolerance) {
  EXPECT_NEAR(got.xx, want.xx, tolerance);
  EXPECT_NEAR(got.yy, want.yy, tolerance);
  EXPECT_NEAR(got.xy, want.xy, tolerance);
}

TEST(SectionStress, ReproducesAUniformField) {
  const LinearField field{{-3e6, -7e6, 1.2e6, -4e6}, {}, {}};
  const Vec2 point{120.0, -45.0};  // far from the origin: coordinates are centred on the point
  const auto zones = sample(field, centroids_around(point, 30.0, 1.5, 1));
  const SectionStress s = section_stress(point, zones);
  EXPECT_TRUE(s.linear);
  expect_stress_near(s.stress, field.s0, 1e-12 * 7e6);
  EXPECT_NEAR(s.stress.zz, -4e6, 1e-12 * 7e6);
}

// Every linear field in equilibrium without body force (seven free coefficients), at random.
TEST(SectionStress, ReproducesLinearFieldsInEquilibrium) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const double a1 = coefficient(random) * 1e6, a2 = coefficient(random) * 1e6,
                 a3 = coefficient(random) * 1e6, b1 = coefficient(random) * 1e5,
                 b2 = coefficient(random) * 1e5, b3 = coefficient(random) * 1e5,
                 b4 = coefficient(random) * 1e5;
    // From Phi = a1 x^2 + a2 x y + a3 y^2 + b1 x^3 + b2 x^2 y + b3 x y^2 + b4 y^3.
    const LinearField field{{2 * a3, 2 * a1, -a2, 0.0},
                            {2 * b3, 6 * b1, -2 * b2, 0.0},
                            {6 * b4, 2 * b2, -2 * b3, 0.0}};
    const Vec2 point{coefficient(random) * 50, coefficient(random) * 50};
    const auto zones = sample(field, centroids_around(point, 180 * coefficient(random), 2.0,
                                                      static_cast<unsigned>(trial)));
    const SectionStress s = section_stress(point, zones);
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_TRUE(s.linear);
    expect_stress_near(s.stress, field.at(point), 1e-9 * 1e6);
  }
}

// Gravity with K0: sv = -rho g (H - y), sh = K0 sv is in equilibrium with the body force
// b = rho g = (0, -rho * 9.81) and is reproduced exactly with it.
TEST(SectionStress, ReproducesTheInsituFieldUnderGravity) {
  const double rho_g = 2688 * 9.81, surface = 182.0, k0 = 0.6;
  const LinearField field{{-k0 * rho_g * surface, -rho_g * surface, 0.0, -k0 * rho_g * surface},
                          {},
                          {k0 * rho_g, rho_g, 0.0, k0 * rho_g}};
  const Vec2 point{10.0, -30.0};
  const auto zones = sample(field, centroids_around(point, 60.0, 4.0, 3));
  const SectionStress s = section_stress(point, zones, {0.0, -rho_g});
  EXPECT_TRUE(s.linear);
  expect_stress_near(s.stress, field.at(point), 1e-12 * rho_g * surface);
  // Without the body force the fit is the best field in equilibrium without one: not exact.
  const SectionStress without = section_stress(point, zones);
  EXPECT_GT(std::fabs(without.stress.yy - field.at(point).yy), 1e-6 * rho_g * surface);
}

// Too few zones, or centroids on one line, cannot fix the linear terms: the mean, flagged.
TEST(SectionStress, FallsBackToTheMeanWhereTheZonesCannotFixASlope) {
  const LinearField field{{-1e6, -2e6, 0.3e6, 0.0}, {}, {}};
  std::vector<Vec2> on_a_line;
  for (int i = 0; i < 6; ++i) on_a_line.push_back({1.0 + i, 2.0 + 0.5 * i});
  const SectionStress line = section_stress({0.0, 1.5}, sample(field, on_a_line));
  EXPECT_FALSE(line.linear);
  expect_stress_near(line.stress, field.s0, 1e-9);
  const SectionStress two = section_stress({0.0, 0.0}, sample(field, {{1, 0}, {0, 1}}));
  EXPECT_FALSE(two.linear);
  expect_stress_near(two.stress, field.s0, 1e-9);
  const SectionStress none = section_stress({0.0, 0.0}, {});
  EXPECT_FALSE(none.linear);
}

TEST(SectionStress, PrincipalStressesAreOrderedMostCompressiveFirst) {
  const LinearField field{{-1e6, -5e6, 0.0, 0.0}, {}, {}};
  const SectionStress s = section_stress({0, 0}, sample(field, centroids_around({0, 0}, 0, 1, 5)));
  EXPECT_NEAR(s.principal.s1, -5e6, 1e-6);
  EXPECT_NEAR(s.principal.s3, -1e6, 1e-6);
}

// The seed's rock (c = 0.143 MPa, phi = 34, sigma_t = 0.0546 MPa): uniaxial compression fails
// in shear just above UCS = 2 c cos phi / (1 - sin phi), not below; uniaxial tension fails in
// tension just above sigma_t; triaxial compression at Kp sigma3 + UCS.
TEST(CrackCriteria, OnsetAtTheClosedForms) {
  const RockStrength rock{0.143e6, 34.0, 0.0546e6};
  const double phi = 34.0 * std::numbers::pi / 180.0;
  const double ucs = 2 * rock.cohesion * std::cos(phi) / (1 - std::sin(phi));
  const double kp = (1 + std::sin(phi)) / (1 - std::sin(phi));
  EXPECT_NEAR(ucs, 0.5379e6, 0.0001e6);
  EXPECT_EQ(crack_mode({-0.999 * ucs, 0.0}, rock), CrackMode::none);
  EXPECT_EQ(crack_mode({-1.001 * ucs, 0.0}, rock), CrackMode::shear);
  EXPECT_NEAR(shear_function({-ucs, 0.0}, rock), 0.0, 1e-9 * ucs);
  for (const double s3 : {0.25e6, 0.5e6}) {
    const double peak = kp * s3 + ucs;
    EXPECT_EQ(crack_mode({-0.999 * peak, -s3}, rock), CrackMode::none) << s3;
    EXPECT_EQ(crack_mode({-1.001 * peak, -s3}, rock), CrackMode::shear) << s3;
  }
  EXPECT_EQ(crack_mode({0.0, 0.999 * rock.tension}, rock), CrackMode::none);
  EXPECT_EQ(crack_mode({0.0, 1.001 * rock.tension}, rock), CrackMode::tension);
  // The seed's printed sign (- 2 c cos phi) would fail the rock under no load at all.
  const double printed = (1 - std::sin(phi)) * 0.0 - (1 + std::sin(phi)) * 0.0 -
                         2 * rock.cohesion * std::cos(phi);
  EXPECT_LT(printed, 0.0);
  EXPECT_EQ(crack_mode({0.0, 0.0}, rock), CrackMode::none);
}

TEST(CrackCriteria, TensionWinsWhereBothFail) {
  const RockStrength rock{0.01e6, 30.0, 0.01e6};
  const Principal p{-1e6, 0.02e6};
  EXPECT_LT(shear_function(p, rock), 0.0);
  EXPECT_LT(tension_function(p, rock), 0.0);
  EXPECT_EQ(crack_mode(p, rock), CrackMode::tension);
}

// overstress is 1 on the envelope (where crack_mode turns), in shear and in tension, and grows
// with the load past it: the ranking judge{ most } breaks by.
TEST(CrackCriteria, OverstressIsOneOnTheEnvelopeAndGrowsPastIt) {
  const RockStrength rock{0.143e6, 34.0, 0.0546e6};
  const double phi = 34.0 * std::numbers::pi / 180.0;
  const double ucs = 2 * rock.cohesion * std::cos(phi) / (1 - std::sin(phi));
  const double kp = (1 + std::sin(phi)) / (1 - std::sin(phi));
  for (const double s3 : {0.0, 0.25e6, 0.5e6}) {
    const double peak = kp * s3 + ucs;
    EXPECT_NEAR(overstress({-peak, -s3}, rock), 1.0, 1e-12) << s3;
    EXPECT_LT(overstress({-0.9 * peak, -s3}, rock), 1.0) << s3;
    EXPECT_GT(overstress({-1.2 * peak, -s3}, rock), overstress({-1.1 * peak, -s3}, rock)) << s3;
  }
  EXPECT_NEAR(overstress({0.0, rock.tension}, rock), 1.0, 1e-12);
  EXPECT_NEAR(overstress({0.0, 2 * rock.tension}, rock), 2.0, 1e-12);
  EXPECT_LT(overstress({-1e6, -1e6}, rock), 1e-12);  // hydrostatic: no circle, nothing past it
}

}  // namespace
}  // namespace edem
