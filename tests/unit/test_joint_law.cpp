// The joint law's normal stress (linear, staged kn, the seed's clamped cubic) and its inverse,
// and joint_params: what it derives (kn_zero, kn_max, residual strength) and what it rejects.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "contact/joint_law.hpp"
#include "core/error.hpp"
#include "error_of.hpp"

namespace edem {
namespace {

constexpr double kMm = 1e-3;

JointMaterialDef linear_def() {
  JointMaterialDef def;
  def.name = "joint";
  def.kn = 2e10;
  def.ks = 5e9;
  def.friction = 30.0;
  def.cohesion = 1e5;
  def.tension = 5e4;
  def.dilation = 5.0;
  return def;
}

// Stages: 1 GPa/m from 0, 5 GPa/m from 0.1 mm (the stiffest), 2 GPa/m from 0.3 mm.
JointMaterialDef table_def() {
  JointMaterialDef def = linear_def();
  def.kn = kUnset;
  def.law = NormalLaw::table;
  def.kn_table = {{{0.0, 1e9}}, {{1e-4, 5e9}}, {{3e-4, 2e9}}};
  return def;
}

JointMaterialDef seed_def() {
  JointMaterialDef def = linear_def();
  def.kn = kUnset;
  def.law = NormalLaw::seed_cubic;
  return def;
}

// The seed curve's zero crossing [mm]: -4.302 v^2 + 7.688 v - 0.123 = 0, the smaller root.
double seed_v0_mm() {
  const double a = -4.302, b = 7.688, c = -0.123;
  return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

// Where the seed curve's tangent is back down to 1880 MPa/m on its descending side [mm]:
// 3a v^2 + 2b v + c = 1.88 (MPa/mm), the larger root.
double seed_v1_mm() {
  const double a = 3.0 * -4.302, b = 2.0 * 7.688, c = -0.123 - 1.88;
  return (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

// The message joint_params rejects `def` with; empty when it accepts it.
std::string rejection(const JointMaterialDef& def) { return error_of([&] { joint_params(def); }); }

// `def` is rejected with a message holding each of `parts` (the bad key and value).
void expect_rejected(const JointMaterialDef& def, std::initializer_list<const char*> parts) {
  const std::string message = rejection(def);
  ASSERT_FALSE(message.empty()) << "accepted, expected an error naming " << *parts.begin();
  for (const char* part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(JointLaw, LinearStressIsKnTimesClosureBothWays) {
  const JointParams p = joint_params(linear_def());
  EXPECT_EQ(p.law, NormalLaw::linear);
  EXPECT_EQ(p.kn, 2e10);
  EXPECT_EQ(p.kn_zero, 2e10);
  EXPECT_EQ(p.kn_max, 2e10);
  EXPECT_EQ(normal_stress(p, 0.0), 0.0);
  for (double c : {1e-6, 3e-5, 1e-3}) EXPECT_DOUBLE_EQ(normal_stress(p, c), p.kn * c) << c;
  for (double c : {-1e-6, -3e-5}) EXPECT_DOUBLE_EQ(normal_stress(p, c), p.kn_zero * c) << c;
}

TEST(JointLaw, LinearClosureAtInvertsStress) {
  const JointParams p = joint_params(linear_def());
  for (double c : {-2e-5, -1e-7, 0.0, 1e-7, 4e-5, 1e-3})
    EXPECT_NEAR(closure_at(p, normal_stress(p, c)), c, 1e-12 * std::abs(c)) << c;
  EXPECT_DOUBLE_EQ(closure_at(p, 1e6), 1e6 / 2e10);
  EXPECT_DOUBLE_EQ(closure_at(p, -1e4), -1e4 / 2e10);
}

TEST(JointLaw, TableStiffnessesAreTheFirstAndTheStiffestStage) {
  const JointParams p = joint_params(table_def());
  EXPECT_EQ(p.law, NormalLaw::table);
  EXPECT_EQ(p.kn_zero, 1e9);
  EXPECT_EQ(p.kn_max, 5e9);
}

TEST(JointLaw, TableStressIsTheIntegralOfTheStages) {
  const JointParams p = joint_params(table_def());
  // By hand: 1e9 * 0.1 mm = 0.1 MPa at the second stage, + 5e9 * 0.2 mm = 1.1 MPa at the third;
  // opening (negative closure) goes on with the first stage's kn.
  const double closures[] = {0.0, 0.5e-4, 1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 1.3e-3, -1e-4};
  const double stresses[] = {0.0, 0.5e5, 1e5, 6e5, 1.1e6, 1.3e6, 1.5e6, 3.1e6, -1e5};
  for (size_t i = 0; i < std::size(closures); ++i)
    EXPECT_NEAR(normal_stress(p, closures[i]), stresses[i], 1e-9 * std::abs(stresses[i]) + 1e-9)
        << closures[i];
}

TEST(JointLaw, TableIsContinuousAtTheStageBoundaries) {
  const JointParams p = joint_params(table_def());
  for (double boundary : {0.0, 1e-4, 3e-4}) {
    const double eps = 1e-12;  // [m]; the stress jumps by at most kn_max * 2 eps across it
    const double below = normal_stress(p, boundary - eps), above = normal_stress(p, boundary + eps);
    EXPECT_NEAR(above, below, 2.0 * eps * p.kn_max * (1.0 + 1e-9) + 1e-9) << boundary;
    EXPECT_LE(below, above) << boundary;
  }
}

TEST(JointLaw, TableClosureAtInvertsStress) {
  const JointParams p = joint_params(table_def());
  for (double c : {-3e-5, 1e-6, 0.5e-4, 1e-4, 1.7e-4, 3e-4, 3.2e-4, 2e-3}) {
    const double back = closure_at(p, normal_stress(p, c));
    EXPECT_NEAR(back, c, 1e-12 * std::abs(c)) << c;
  }
  for (double s : {1e3, 1e5, 6e5, 1.1e6, 5e6})
    EXPECT_NEAR(normal_stress(p, closure_at(p, s)), s, 1e-12 * s) << s;
}

TEST(JointLaw, SeedCubicStiffnessesAreTheClampsPromises) {
  const JointParams p = joint_params(seed_def());
  EXPECT_EQ(p.law, NormalLaw::seed_cubic);
  // Tangent 121 MPa/m at zero closure (f'(v0) = 121.9 MPa/m), at most 4456 MPa/m (the
  // inflection, v = 0.596 mm).
  EXPECT_NEAR(p.kn_zero, 121.9e6, 0.5e6);
  EXPECT_NEAR(p.kn_max, 4456e6, 1e6);
}

TEST(JointLaw, SeedCubicIsTheCurveFromItsZeroCrossing) {
  const JointParams p = joint_params(seed_def());
  const double v0 = seed_v0_mm() * kMm;
  EXPECT_NEAR(seed_v0_mm(), 0.0161, 0.0001);
  EXPECT_NEAR(seed_cubic_raw(v0), 0.0, 1e-9);
  EXPECT_EQ(normal_stress(p, 0.0), 0.0);
  for (double c : {0.01 * kMm, 0.1 * kMm, 0.5 * kMm, 1.0 * kMm})
    EXPECT_NEAR(normal_stress(p, c), seed_cubic_raw(c + v0), 1e-9 * seed_cubic_raw(c + v0)) << c;
}

TEST(JointLaw, SeedCubicIsStraightAt1880MPaPerMetrePastItsDescendingPoint) {
  const JointParams p = joint_params(seed_def());
  const double v0 = seed_v0_mm() * kMm, v1 = seed_v1_mm() * kMm;
  // The header: reached at v = 1.042 mm, sn = 3.35 MPa.
  EXPECT_NEAR(seed_v1_mm(), 1.042, 0.001);
  EXPECT_NEAR(seed_cubic_raw(v1), 3.35e6, 0.01e6);
  EXPECT_NEAR(normal_stress(p, v1 - v0), seed_cubic_raw(v1), 1e-6 * seed_cubic_raw(v1));
  for (double c : {1.1 * kMm, 2.0 * kMm, 3.0 * kMm, 10.0 * kMm}) {
    const double straight = seed_cubic_raw(v1) + 1880e6 * (c + v0 - v1);
    EXPECT_NEAR(normal_stress(p, c), straight, 1e-9 * straight) << c;
  }
  // There the raw curve would have gone soft: the clamp is stiffer.
  EXPECT_GT(normal_stress(p, 2.0 * kMm), seed_cubic_raw(2.0 * kMm + v0));
}

// The closure the overlap watchdog allows on top of its rounding: the curve's, from its zero
// crossing to where it goes straight, times the closure scale; none for laws given whole.
TEST(JointLaw, CurveClosureIsTheSeedCurvesScaledAndZeroForOtherLaws) {
  EXPECT_NEAR(joint_params(seed_def()).curve_closure, (seed_v1_mm() - seed_v0_mm()) * kMm, 1e-15);
  JointMaterialDef prototype = seed_def();
  prototype.law_stress_scale = 17.86;
  prototype.law_closure_scale = 400.0;
  EXPECT_NEAR(joint_params(prototype).curve_closure, 0.4105, 1e-4);
  EXPECT_EQ(joint_params(linear_def()).curve_closure, 0.0);
  EXPECT_EQ(joint_params(table_def()).curve_closure, 0.0);
}

TEST(JointLaw, SeedCubicOnFineClosuresIsPositiveIncreasingAndNeverStifferThanKnMax) {
  const JointParams p = joint_params(seed_def());
  const int n = 30001;
  const double top = 3.0 * kMm, h = top / (n - 1);
  const double straight_from = 1.03 * kMm;  // beyond v1 - v0 = 1.026 mm
  double previous = normal_stress(p, 0.0), max_tangent = 0.0;
  int failures = 0;
  for (int i = 1; i < n && failures < 5; ++i) {
    const double c = h * i, s = normal_stress(p, c);
    const double tangent = (s - previous) / h;
    if (!(s >= 0.0 && s > previous && tangent > 0.0 && tangent <= p.kn_max * (1.0 + 1e-6))) {
      ADD_FAILURE() << "closure " << c << ": stress " << s << " after " << previous << ", tangent "
                    << tangent << " (kn_max " << p.kn_max << ")";
      ++failures;
    }
    if (c - h >= straight_from && std::abs(tangent - 1880e6) > 1e-6 * 1880e6) {
      ADD_FAILURE() << "closure " << c << ": tangent " << tangent << ", expected 1880e6";
      ++failures;
    }
    max_tangent = std::max(max_tangent, tangent);
    previous = s;
  }
  // The secants come within a hair of the inflection's tangent.
  EXPECT_NEAR(max_tangent, p.kn_max, 1e-6 * p.kn_max);
}

TEST(JointLaw, SeedCubicClosureAtInvertsStress) {
  const JointParams p = joint_params(seed_def());
  for (double s : {1.0, 1e3, 1e5, 1e6, 3.35e6, 6e6, 2e7}) {
    const double c = closure_at(p, s);
    EXPECT_GT(c, 0.0) << s;
    EXPECT_NEAR(normal_stress(p, c), s, 1e-12 * s) << s;
  }
  for (double c : {0.001 * kMm, 0.3 * kMm, 1.0 * kMm, 2.5 * kMm})
    EXPECT_NEAR(closure_at(p, normal_stress(p, c)), c, 1e-12 * c) << c;
  EXPECT_DOUBLE_EQ(closure_at(p, -1e4), -1e4 / p.kn_zero);
}

TEST(JointLaw, SeedCubicLoadAndUnloadRetraceTheCurve) {
  const JointParams p = joint_params(seed_def());
  const double top = closure_at(p, 6e6);
  const int steps = 2000;
  std::vector<double> loading;
  double previous = -1.0;
  for (int i = 0; i <= steps; ++i) {
    const double s = normal_stress(p, top * i / steps);
    EXPECT_GT(s, previous) << "loading step " << i;
    loading.push_back(s);
    previous = s;
  }
  EXPECT_NEAR(loading.back(), 6e6, 1e-9 * 6e6);
  for (int i = steps; i >= 0; --i) {
    const double s = normal_stress(p, top * i / steps);
    if (i < steps) {
      EXPECT_LT(s, previous) << "unloading step " << i;
    }
    EXPECT_EQ(s, loading[static_cast<size_t>(i)]) << "unloading step " << i;  // elastic
    previous = s;
  }
  EXPECT_EQ(previous, 0.0);
}

TEST(JointLaw, StrengthAndResidualDefaults) {
  const JointParams p = joint_params(linear_def());
  EXPECT_DOUBLE_EQ(p.tan_friction, std::tan(30.0 * std::numbers::pi / 180.0));
  EXPECT_DOUBLE_EQ(p.tan_dilation, std::tan(5.0 * std::numbers::pi / 180.0));
  EXPECT_EQ(p.ks, 5e9);
  EXPECT_EQ(p.cohesion, 1e5);
  EXPECT_EQ(p.tension, 5e4);
  // Unset residual friction: the friction; residual cohesion: 0 whatever the cohesion.
  EXPECT_EQ(p.tan_residual_friction, p.tan_friction);
  EXPECT_EQ(p.residual_cohesion, 0.0);

  JointMaterialDef def = linear_def();
  def.residual_friction = 20.0;
  def.residual_cohesion = 1e5;  // = cohesion: allowed
  const JointParams q = joint_params(def);
  EXPECT_DOUBLE_EQ(q.tan_residual_friction, std::tan(20.0 * std::numbers::pi / 180.0));
  EXPECT_EQ(q.residual_cohesion, 1e5);
}

TEST(JointLaw, RejectsBadShearStiffness) {
  JointMaterialDef def = linear_def();
  def.ks = 0.0;
  expect_rejected(def, {"ks", "got 0"});
  def.ks = -2.0;
  expect_rejected(def, {"ks", "got -2"});
  def.ks = kUnset;
  expect_rejected(def, {"ks", "got nan"});
}

TEST(JointLaw, RejectsFriction90) {
  JointMaterialDef def = linear_def();
  def.friction = 90.0;
  def.dilation = 0.0;
  expect_rejected(def, {"friction", "got 90"});
}

TEST(JointLaw, RejectsDilationAboveFriction) {
  JointMaterialDef def = linear_def();
  def.dilation = 31.0;
  expect_rejected(def, {"dilation", "friction = 30", "got 31"});
}

TEST(JointLaw, RejectsNegativeCohesionAndTension) {
  JointMaterialDef def = linear_def();
  def.cohesion = -1.0;
  expect_rejected(def, {"cohesion", "got -1"});
  def = linear_def();
  def.tension = -2.0;
  expect_rejected(def, {"tension", "got -2"});
  def = linear_def();
  def.residual_cohesion = -3.0;
  expect_rejected(def, {"residual_cohesion", "got -3"});
}

TEST(JointLaw, RejectsResidualCohesionAboveCohesion) {
  JointMaterialDef def = linear_def();
  def.residual_cohesion = 2e5;
  expect_rejected(def, {"residual_cohesion", "cohesion = 100000", "got 200000"});
}

TEST(JointLaw, RejectsResidualFriction95) {
  JointMaterialDef def = linear_def();
  def.residual_friction = 95.0;
  expect_rejected(def, {"residual_friction", "got 95"});
}

TEST(JointLaw, RejectsTwoNormalLaws) {
  JointMaterialDef def = table_def();
  def.kn = 1e9;
  expect_rejected(def, {"kn", "kn_table", "not both"});
  def = seed_def();
  def.kn = 1e9;
  expect_rejected(def, {"kn", "kn_law", "not both"});
}

TEST(JointLaw, RejectsLinearWithoutKn) {
  JointMaterialDef def = linear_def();
  def.kn = kUnset;
  expect_rejected(def, {"kn is missing"});
  def.kn = 0.0;
  expect_rejected(def, {"kn", "got 0"});
}

TEST(JointLaw, RejectsTableNotStartingAtZero) {
  JointMaterialDef def = table_def();
  def.kn_table[0][0] = 1e-5;
  expect_rejected(def, {"kn_table", "closure 0", "got 1e-05"});
  def.kn_table.clear();
  expect_rejected(def, {"kn_table", "at least one stage"});
}

TEST(JointLaw, RejectsTableClosuresNotIncreasing) {
  JointMaterialDef def = table_def();
  def.kn_table[2][0] = 1e-4;  // equal to stage 2's
  expect_rejected(def, {"kn_table stage 3", "closures must increase", "got 0.0001 after 0.0001"});
  def.kn_table[2][0] = 0.5e-4;
  expect_rejected(def, {"kn_table stage 3", "got 5e-05 after 0.0001"});
}

TEST(JointLaw, RejectsTableKnNotPositive) {
  JointMaterialDef def = table_def();
  def.kn_table[1][1] = 0.0;
  expect_rejected(def, {"kn_table stage 2", "kn", "got 0"});
  def = table_def();
  def.kn_table[0][1] = -2.0;
  expect_rejected(def, {"kn_table stage 1", "kn", "got -2"});
}
// The seed's prototype (stresses x 17.86, closures x 400): the lab curve read at another scale,
// its three stages' 260 / 940 / 1880 MPa/m becoming 11.6 / 42.0 / 83.9 MPa/m.
JointMaterialDef prototype_def() {
  JointMaterialDef def = seed_def();
  def.law_stress_scale = 17.86;
  def.law_closure_scale = 400.0;
  return def;
}

TEST(JointLaw, ScaledSeedCubicIsTheLabCurveAtPrototypeScale) {
  const JointParams lab = joint_params(seed_def()), p = joint_params(prototype_def());
  for (double c : {0.001 * kMm, 0.1 * kMm, 0.5 * kMm, 1.0 * kMm, 2.5 * kMm}) {
    const double expected = 17.86 * normal_stress(lab, c);
    EXPECT_NEAR(normal_stress(p, 400.0 * c), expected, 1e-12 * expected) << c;
    const double energy = 17.86 * 400.0 * normal_energy(lab, c);
    EXPECT_NEAR(normal_energy(p, 400.0 * c), energy, 1e-12 * energy) << c;
  }
  EXPECT_NEAR(p.kn_zero, lab.kn_zero * 17.86 / 400.0, 1e-9 * p.kn_zero);
  EXPECT_NEAR(p.kn_max, lab.kn_max * 17.86 / 400.0, 1e-9 * p.kn_max);
  // Past its descending point the straight part is the third stage scaled: 83.9 MPa/m.
  const double h = 1e-6, c = 2.0 * kMm * 400.0;
  EXPECT_NEAR((normal_stress(p, c + h) - normal_stress(p, c)) / h, 1880e6 * 17.86 / 400.0, 1e-3 * 83.9e6);
  // The in-situ stress of the seed's cavern, 2.5 to 4.2 MPa, closes it by 5 to 8 cm.
  EXPECT_GT(closure_at(p, 2.5e6), 0.05);
  EXPECT_LT(closure_at(p, 4.2e6), 0.08);
  // (1 Pa is 0.056 Pa on the lab curve, where its terms cancel to about 1e-11 of it.)
  for (double s : {1.0, 1e4, 1e6, 4.2e6, 6e7, 1e8}) {
    const double closure = closure_at(p, s);
    EXPECT_NEAR(normal_stress(p, closure), s, 1e-10 * s) << s;
  }
}

TEST(JointLaw, RejectsScalesWithoutALawOrNotPositive) {
  JointMaterialDef linear = linear_def();
  linear.law_stress_scale = 17.86;
  expect_rejected(linear, {"stress_scale", "kn_law"});
  JointMaterialDef zero = prototype_def();
  zero.law_closure_scale = 0.0;
  expect_rejected(zero, {"closure_scale", "got 0"});
  JointMaterialDef negative = prototype_def();
  negative.law_stress_scale = -1.0;
  expect_rejected(negative, {"stress_scale", "got -1"});
}


// normal_energy is the integral of normal_stress from zero closure (Simpson's rule on a fine
// grid, through the stages and the seed curve's straight part), on both sides of zero.
TEST(JointLaw, NormalEnergyIsTheIntegralOfTheStressForEveryLaw) {
  for (const JointMaterialDef& def : {linear_def(), table_def(), seed_def(), prototype_def()}) {
    const JointParams p = joint_params(def);
    for (const double closure : {-2e-5, 5e-5, 2e-4, 4e-4, 1.5 * kMm, 3.0 * kMm}) {
      constexpr int kIntervals = 20000;
      const double h = closure / kIntervals;
      double sum = 0.0;
      for (int i = 0; i <= kIntervals; ++i)
        sum += (i == 0 || i == kIntervals ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0)) * normal_stress(p, i * h);
      const double integral = sum * h / 3.0;
      EXPECT_NEAR(normal_energy(p, closure), integral, 1e-6 * std::fabs(integral)) << def.kn << " " << closure;
    }
  }
}

TEST(JointLaw, RejectsEmptyName) {
  JointMaterialDef def = linear_def();
  def.name.clear();
  expect_rejected(def, {"name"});
}

}  // namespace
}  // namespace edem
