// The bolt/cable law (engine/bolt): its parameters, the segment and grout laws one at a time, a
// set's geometry, equilibrium and time step, and the pull-out of a fully grouted bolt from rigid
// ground (the shear-lag closed form, as tests/verification/bolt_pullout.lua), relaxed to
// equilibrium by a small damped explicit loop here in the test:
//   * elastic F(x) and head stiffness against the closed form (and the exact answer of the
//     discrete chain of 40 segments, solved directly);
//   * displacement control at the head, driven at a slow constant speed and read without stopping
//     (as Itasca's pull-out example does): the F0-u0 curve, the peak and the plateau, for bond
//     failure (s_b L < F_y) and for bolt yield (F_y < s_b L), and the bolt breaking.
// The pulled bolt has a free (ungrouted) tail of one segment out of the hole, where the "jack"
// holds it: the load is that segment's force, and the grouted length starts at the collar x = 0.
// (Pulling the first grouted node itself would add its half-segment of grout to the load: F_y +
// s_b dx / 2, 8% above F_y with 40 segments on 5 m.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

#include "bolt/bolt_law.hpp"
#include "core/error.hpp"
#include "error_of.hpp"

namespace edem {
namespace {

// The bolt of the seed paper (Jiang et al., §4.2: E = 190 GPa, A = 446 mm^2) in a reference
// grout, k_b = 50 MN/m/m, s_b = 0.2 MN/m; spacing 1.
constexpr double kYoung = 190e9, kArea = 446e-6, kBondStiffness = 50e6, kBondStrength = 0.2e6;
constexpr double kEA = kYoung * kArea;  // 84.74 MN
// The seed's "yield strength 1.55 MPa" is almost certainly a force, 1.55e5 N: 446 mm^2 x ~350 MPa.
constexpr double kSeedYield = 0.156e6;
constexpr double kSeedFailureStrain = 0.035;
constexpr int kSegments = 40;

double lambda() {
  return std::sqrt(kBondStiffness / kEA);
}

BoltParams seed_params(double yield = kSeedYield, double failure_strain = kSeedFailureStrain) {
  BoltParams p;
  p.young = kYoung;
  p.area = kArea;
  p.density = 7850.0;
  p.yield_tension = yield;
  p.yield_compression = yield;
  p.failure_strain = failure_strain;
  p.bond_stiffness = kBondStiffness;
  p.bond_strength = kBondStrength;
  p.spacing = 1.0;
  return p;
}

// ---------------------------------------------------------------------------------------------
// Parameters

std::string rejection(const BoltParams& p) { return error_of([&] { bolt_law(p); }); }

TEST(BoltParams, SeedValuesAreAccepted) {
  EXPECT_EQ(rejection(seed_params()), "");
}

TEST(BoltParams, EveryNonPositiveOrNonFiniteValueIsNamed) {
  struct Field {
    const char* key;
    double BoltParams::*member;
  };
  const Field fields[] = {
      {"young", &BoltParams::young},
      {"area", &BoltParams::area},
      {"density", &BoltParams::density},
      {"yield_tension", &BoltParams::yield_tension},
      {"yield_compression", &BoltParams::yield_compression},
      {"failure_strain", &BoltParams::failure_strain},
      {"bond_stiffness", &BoltParams::bond_stiffness},
      {"bond_strength", &BoltParams::bond_strength},
      {"spacing", &BoltParams::spacing},
  };
  for (const Field& f : fields) {
    for (double bad : {0.0, -2.5, std::nan(""), HUGE_VAL}) {
      BoltParams p = seed_params();
      p.*f.member = bad;
      const std::string message = rejection(p);
      ASSERT_FALSE(message.empty()) << f.key << " = " << bad << " accepted";
      EXPECT_EQ(message.rfind(std::string(f.key) + " must be a finite number > 0", 0), 0u)
          << message;
      EXPECT_NE(message.find(fmt::format("got {}", bad)), std::string::npos) << message;
      EXPECT_THROW(check_bolt_params(p), Error) << f.key;
    }
  }
}

TEST(BoltParams, LawIsPerMetreOfThickness) {
  BoltParams p = seed_params();
  p.spacing = 1.5;
  const BoltLaw law = bolt_law(p);
  EXPECT_DOUBLE_EQ(law.ea, kEA / 1.5);
  EXPECT_DOUBLE_EQ(law.yield_tension, kSeedYield / 1.5);
  EXPECT_DOUBLE_EQ(law.yield_compression, kSeedYield / 1.5);
  EXPECT_DOUBLE_EQ(law.bond_stiffness, kBondStiffness / 1.5);
  EXPECT_DOUBLE_EQ(law.bond_strength, kBondStrength / 1.5);
  EXPECT_DOUBLE_EQ(law.line_mass, 7850.0 * kArea / 1.5);
  EXPECT_EQ(law.failure_strain, kSeedFailureStrain);  // a strain is a strain
}

// ---------------------------------------------------------------------------------------------
// The segment law

TEST(BoltSegmentLaw, ElasticIncrementsAddEaOverL) {
  const BoltLaw law = bolt_law(seed_params());
  const double rest = 0.5, k = kEA / rest;
  SegmentUpdate s = segment_law(law, rest, 0.0, SegmentState::elastic, 0.0, 1e-4);
  EXPECT_DOUBLE_EQ(s.force, k * 1e-4);
  EXPECT_EQ(s.state, SegmentState::elastic);
  s = segment_law(law, rest, s.force, s.state, 1e-4, 0.4e-4);  // shortened by 0.6e-4
  EXPECT_NEAR(s.force, k * 0.4e-4, 1e-9 * k * 1e-4);
  s = segment_law(law, rest, s.force, s.state, 0.4e-4, -0.2e-4);  // into compression
  EXPECT_NEAR(s.force, -k * 0.2e-4, 1e-9 * k * 1e-4);
  EXPECT_EQ(s.state, SegmentState::elastic);
}

TEST(BoltSegmentLaw, YieldIsPerfectlyPlasticBothWaysAndUnloadsElastically) {
  BoltParams p = seed_params();
  p.yield_compression = 0.1e6;
  const BoltLaw law = bolt_law(p);
  const double rest = 0.5, k = kEA / rest;
  const double e_yield = kSeedYield / k;  // 0.92 mm
  SegmentUpdate s = segment_law(law, rest, 0.0, SegmentState::elastic, 0.0, 3.0 * e_yield);
  EXPECT_EQ(s.force, kSeedYield);
  EXPECT_EQ(s.state, SegmentState::yielded);
  s = segment_law(law, rest, s.force, s.state, 3.0 * e_yield, 4.0 * e_yield);  // further: held
  EXPECT_EQ(s.force, kSeedYield);
  // Unloading by 1 mm from the yield force: elastic, and the state remembers it yielded.
  s = segment_law(law, rest, s.force, s.state, 4.0 * e_yield, 4.0 * e_yield - 1e-4);
  EXPECT_NEAR(s.force, kSeedYield - k * 1e-4, 1e-6);
  EXPECT_EQ(s.state, SegmentState::yielded);
  // Far into compression: held at -yield_compression.
  s = segment_law(law, rest, s.force, s.state, 4.0 * e_yield - 1e-4, -0.01);
  EXPECT_EQ(s.force, -0.1e6);
  EXPECT_EQ(s.state, SegmentState::yielded);
}

TEST(BoltSegmentLaw, BreaksPastTheFailureStrainAndCarriesNothingAfter) {
  const BoltLaw law = bolt_law(seed_params());
  const double rest = 0.5, at_failure = kSeedFailureStrain * rest;
  SegmentUpdate s = segment_law(law, rest, 0.0, SegmentState::elastic, 0.0, at_failure);
  EXPECT_EQ(s.state, SegmentState::yielded);  // exactly at the failure strain: not yet
  EXPECT_EQ(s.force, kSeedYield);
  s = segment_law(law, rest, s.force, s.state, at_failure, at_failure * (1.0 + 1e-9));
  EXPECT_EQ(s.state, SegmentState::broken);
  EXPECT_EQ(s.force, 0.0);
  // Nothing brings it back: shortened, compressed, stretched again.
  for (double e : {0.5 * at_failure, 0.0, -0.01, 2.0 * at_failure}) {
    s = segment_law(law, rest, s.force, s.state, at_failure, e);
    EXPECT_EQ(s.state, SegmentState::broken) << e;
    EXPECT_EQ(s.force, 0.0) << e;
  }
  // Compression never breaks it.
  s = segment_law(law, rest, 0.0, SegmentState::elastic, 0.0, -2.0 * at_failure);
  EXPECT_EQ(s.state, SegmentState::yielded);
  EXPECT_EQ(s.force, -kSeedYield);
}

// ---------------------------------------------------------------------------------------------
// The grout law

TEST(BoltGroutLaw, SpringSliderWithPlasticSlip) {
  const double k = 50e6 * 0.125, strength = 0.2e6 * 0.125;  // one interior node of 0.125 m
  GroutUpdate g = grout_law(k, strength, 0.0, 0.0, 1e-3);   // elastic: 6.25 kN < 25 kN
  EXPECT_DOUBLE_EQ(g.force, k * 1e-3);
  EXPECT_FALSE(g.slipping);
  EXPECT_EQ(g.slip, 0.0);
  g = grout_law(k, strength, g.force, g.slip, 5e-3);  // to 6 mm: past the 4 mm at strength
  EXPECT_EQ(g.force, strength);
  EXPECT_TRUE(g.slipping);
  EXPECT_NEAR(g.slip, 6e-3 - strength / k, 1e-15);     // 2 mm
  g = grout_law(k, strength, g.force, g.slip, -1e-3);  // back 1 mm: elastic unloading
  EXPECT_NEAR(g.force, strength - k * 1e-3, 1e-6);
  EXPECT_FALSE(g.slipping);
  EXPECT_NEAR(g.slip, 2e-3, 1e-15);
  g = grout_law(k, strength, g.force, g.slip, -10e-3);  // reversed, slips the other way
  EXPECT_EQ(g.force, -strength);
  EXPECT_TRUE(g.slipping);
  // Net motion 6 - 1 - 10 = -5 mm, elastic part -4 mm: plastic slip -1 mm.
  EXPECT_NEAR(g.slip, -1e-3, 1e-15);
}

TEST(BoltGroutLaw, UngroutedNodeCarriesNothing) {
  const GroutUpdate g = grout_law(0.0, 0.0, 0.0, 0.0, 1.0);
  EXPECT_EQ(g.force, 0.0);
  EXPECT_EQ(g.slip, 0.0);
  EXPECT_FALSE(g.slipping);
}

// ---------------------------------------------------------------------------------------------
// A set of bolts

TEST(BoltSet, AddBoltLaysNodesLengthsAndMasses) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params()));
  const double line_mass = set.laws[0].line_mass;
  // An inclined 4.2 m bolt: a 0.2 m free tail, then 8 grouted segments of 0.5 m.
  const Vec2 head{1.0, 2.0}, end{1.0 + 4.2 * 0.6, 2.0 - 4.2 * 0.8};
  EXPECT_EQ(add_bolt(set, {head, end, 8, 0.2, 0}), 0);
  const BoltNodes& n = set.nodes;
  ASSERT_EQ(n.size(), 10u);
  ASSERT_EQ(set.segments.size(), 9u);
  EXPECT_EQ(set.bolts(), 1);
  EXPECT_EQ(set.bolt_first_node, (std::vector<int>{0, 10}));
  EXPECT_EQ(set.bolt_first_segment, (std::vector<int>{0, 9}));
  EXPECT_EQ(n.x.front(), head);
  EXPECT_EQ(n.x.back(), end);
  EXPECT_NEAR(set.segments.rest[0], 0.2, 1e-12);
  for (size_t s = 1; s < 9; ++s) EXPECT_NEAR(set.segments.rest[s], 0.5, 1e-12) << s;
  const std::vector<double> bond = {0.0, 0.25, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.25};
  const std::vector<double> tributary = {0.1, 0.35, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.25};
  double mass = 0.0;
  for (size_t i = 0; i < 10; ++i) {
    EXPECT_NEAR(n.bond_length[i], bond[i], 1e-12) << i;
    EXPECT_NEAR(n.tributary[i], tributary[i], 1e-12) << i;
    EXPECT_NEAR(n.grout_stiffness[i], kBondStiffness * bond[i], 1e-6) << i;
    EXPECT_NEAR(n.grout_strength[i], kBondStrength * bond[i], 1e-6) << i;
    EXPECT_NEAR(n.axis[i].x, 0.6, 1e-12);
    EXPECT_NEAR(n.axis[i].y, -0.8, 1e-12);
    mass += n.mass[i];
  }
  EXPECT_NEAR(mass, line_mass * 4.2, 1e-9);
  // A second bolt follows on, with its own indices.
  EXPECT_EQ(add_bolt(set, {{0, 0}, {3, 0}, 6, 0.0, 0}), 1);
  EXPECT_EQ(set.bolt_first_node, (std::vector<int>{0, 10, 17}));
  EXPECT_EQ(set.segments.a[9], 10);
  EXPECT_NEAR(set.nodes.bond_length[10], 0.25, 1e-12);  // no free tail: grouted from the head
}

TEST(BoltSet, AddBoltRejectsBadLines) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params()));
  auto message = [&](const BoltLine& line) {
    try {
      add_bolt(set, line);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_NE(message({{0, 0}, {1, 0}, 0, 0.0, 0}).find("at least 1 grouted segment"),
            std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}, 4, 0.0, 1}).find("bolt material 1 does not exist"),
            std::string::npos);
  EXPECT_NE(message({{2, 3}, {2, 3}, 4, 0.0, 0}).find("two distinct ends"), std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}, 4, 1.0, 0}).find("free_length must be in [0, 1)"),
            std::string::npos);
  EXPECT_NE(message({{0, 0}, {1, 0}, 4, -0.1, 0}).find("free_length"), std::string::npos);
  EXPECT_EQ(set.nodes.size(), 0u);
}

// Rotating the whole bolt and the rock with it stresses nothing; stretching an inclined bolt gives
// the same axial force as stretching it along x.
TEST(BoltSet, RigidRotationStressesNothing) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params()));
  add_bolt(set, {{0.0, 0.0}, {0.8, 0.6}, 4, 0.0, 0});
  const double angle = 0.3;  // [rad]
  std::vector<Vec2> host(set.nodes.size());
  for (int step = 1; step <= 10; ++step) {  // in steps, as a solver would
    const double a = angle * step / 10.0, c = std::cos(a), s = std::sin(a);
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      const Vec2 x = set.nodes.x[i];
      set.nodes.u[i] = Vec2{c * x.x - s * x.y, s * x.x + c * x.y} - x;
      host[i] = set.nodes.u[i];
    }
    bolt_forces(set, host);
  }
  for (size_t s = 0; s < set.segments.size(); ++s) EXPECT_NEAR(set.segments.force[s], 0.0, 1e-3);
  for (size_t i = 0; i < set.nodes.size(); ++i) {
    EXPECT_NEAR(set.nodes.grout_force[i], 0.0, 1e-3);
    EXPECT_NEAR(norm(set.nodes.force[i]), 0.0, 1e-3);
    // The axis turned with the bolt.
    EXPECT_NEAR(set.nodes.axis[i].x, std::cos(angle + std::atan2(0.6, 0.8)), 1e-12);
  }
  // Now stretch it uniformly by 1e-4 along its axis, the rock staying put.
  const Vec2 t = set.nodes.axis[0];
  for (size_t i = 0; i < set.nodes.size(); ++i) {
    const double along = dot(set.nodes.x[i] + set.nodes.u[i], t);
    set.nodes.u[i] = set.nodes.u[i] + (1e-4 * along) * t;
  }
  bolt_forces(set, host);
  for (size_t s = 0; s < set.segments.size(); ++s)
    EXPECT_NEAR(set.segments.force[s], kEA * 1e-4, 1e-6 * kEA * 1e-4) << s;
}

// A segment removed with its rock keeps its direction, and the nodes of the rest take their axes
// from the segments still in the rock: the rock left, and the node with it, may move past where
// the cut node stays, which would turn or zero a mean with the cut segment in it.
TEST(BoltSet, RemovedSegmentsKeepTheirDirectionAndLeaveTheAxesToTheRest) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params()));
  add_bolt(set, {{0.0, 0.0}, {2.0, 0.0}, 2, 0.0, 0});  // nodes at x = 0, 1, 2
  std::vector<Vec2> host(set.nodes.size());
  bolt_forces(set, host);
  set.segments.state[0] = SegmentState::removed;  // node 0's rock is gone; it stays at x = 0
  set.segments.force[0] = 0.0;
  for (const double shift : {-0.5, -1.0, -1.5}) {  // nodes 1 and 2 move left, past node 0
    for (size_t i : {size_t{1}, size_t{2}}) host[i] = set.nodes.u[i] = Vec2{shift, 0.0};
    bolt_forces(set, host);
    EXPECT_EQ(set.segments.direction[0], (Vec2{1.0, 0.0})) << shift;
    EXPECT_EQ(set.segments.force[0], 0.0) << shift;
    EXPECT_EQ(set.segments.state[0], SegmentState::removed) << shift;
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_NEAR(set.nodes.axis[i].x, 1.0, 1e-12) << shift << " node " << i;
      EXPECT_NEAR(norm(set.nodes.force[i]), 0.0, 1e-9) << shift << " node " << i;
    }
  }
}

// Whatever the state, the forces on the bolt nodes and the grout's reactions on the rock add up to
// zero (the bolt makes no force out of nothing), and the reaction lies along the axis.
TEST(BoltSet, ForcesOnBoltAndRockBalance) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params(0.05e6, 0.01)));
  add_bolt(set, {{0.0, 0.0}, {3.0, 1.0}, 12, 0.3, 0});
  std::vector<Vec2> host(set.nodes.size());
  for (int step = 1; step <= 20; ++step) {
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      const double s = static_cast<double>(i);
      set.nodes.u[i] = Vec2{-2e-4 * step * std::cos(s), 1e-4 * step * std::sin(2.0 * s)};
      host[i] = Vec2{1e-4 * step * std::sin(s), -0.5e-4 * step};
    }
    bolt_forces(set, host);
    Vec2 sum{};
    double scale = 0.0;
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      const Vec2 reaction = grout_on_host(set, i);
      sum = sum + set.nodes.force[i] + reaction;
      scale = std::max(scale, norm(set.nodes.force[i]) + norm(reaction));
      EXPECT_NEAR(cross(reaction, set.nodes.axis[i]), 0.0, 1e-9 * (1.0 + norm(reaction)));
    }
    EXPECT_NEAR(sum.x, 0.0, 1e-9 * scale) << step;
    EXPECT_NEAR(sum.y, 0.0, 1e-9 * scale) << step;
  }
  // The states this went through: something yielded, something slipped.
  EXPECT_NE(std::count(set.nodes.slipping.begin(), set.nodes.slipping.end(), 1), 0);
  EXPECT_NE(std::count(set.segments.state.begin(), set.segments.state.end(), SegmentState::elastic),
            static_cast<long>(set.segments.size()));
}

// ---------------------------------------------------------------------------------------------
// Time step

TEST(BoltTimeStep, NodeStiffnessAndMass) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params()));
  add_bolt(set, {{0.0, 0.0}, {2.0, 0.0}, 4, 0.0, 0});  // 4 segments of 0.5 m
  const std::vector<double> k = bolt_node_stiffness(set);
  const double seg = kEA / 0.5, grout = kBondStiffness * 0.5;
  EXPECT_DOUBLE_EQ(k[0], 2.0 * seg + 2.0 * 0.5 * grout);
  EXPECT_DOUBLE_EQ(k[2], 4.0 * seg + 2.0 * grout);
  EXPECT_DOUBLE_EQ(set.nodes.mass[2], 7850.0 * kArea * 0.5);
  EXPECT_DOUBLE_EQ(set.nodes.mass[0], 7850.0 * kArea * 0.25);
  // A broken segment no longer counts.
  set.segments.state[1] = SegmentState::broken;
  const std::vector<double> after = bolt_node_stiffness(set);
  EXPECT_DOUBLE_EQ(after[1], 2.0 * seg + 2.0 * grout);
  EXPECT_DOUBLE_EQ(after[2], 2.0 * seg + 2.0 * grout);
}

// A 0.5 m segment of the seed bolt, density 6083 kg/m^3 (the seed paper's §4.2): m = 1.357 kg,
// k = EA/L = 1.695e8 N/m. A single mass on that spring is stable up to 2 sqrt(m/k) = 1.79e-4 s;
// a chain of such segments, with the segment's mass lumped on each interior node, is
// stable only up to sqrt(m/k) = 8.95e-5 s, half of it.
TEST(BoltTimeStep, SeedBoltChainStepIsHalfTheSingleSpringValue) {
  BoltParams p = seed_params();
  p.density = 6083.0;
  BoltSet set;
  set.laws.push_back(bolt_law(p));
  add_bolt(set, {{0.0, 0.0}, {5.0, 0.0}, 10, 0.0, 0});
  const double m = 6083.0 * kArea * 0.5, k = kEA / 0.5;
  EXPECT_NEAR(m, 1.357, 0.001);
  EXPECT_NEAR(k, 1.695e8, 0.001e8);
  const double step = bolt_critical_step(set);
  std::printf(
      "seed bolt, 0.5 m segments: critical step %.4g s; sqrt(m/k) = %.4g s; "
      "2 sqrt(m/k) = %.4g s (the single-spring value, 1.79e-4 s)\n",
      step, std::sqrt(m / k), 2.0 * std::sqrt(m / k));
  EXPECT_LT(step, std::sqrt(m / k));
  EXPECT_GT(step, 0.9 * std::sqrt(m / k));  // the grout (2 k_b dx against 4 EA/dx) lowers it 4%
}

// Undamped central differences on a grouted bolt in rigid ground, from its highest (alternating)
// mode: bounded at 0.99 of bolt_critical_step, blown up at 1.1 of it (the bound is tight).
double amplitude_after(double step_factor, int steps) {
  BoltSet set;
  set.laws.push_back(bolt_law(seed_params(1e9, 1.0)));  // elastic throughout
  set.laws[0].bond_strength = 1e12;                     // elastic grout too
  add_bolt(set, {{0.0, 0.0}, {5.0, 0.0}, 20, 0.0, 0});
  for (size_t i = 0; i < set.nodes.size(); ++i) {
    set.nodes.u[i].x = (i % 2 ? 1e-6 : -1e-6);
  }
  const double dt = step_factor * bolt_critical_step(set);
  const std::vector<Vec2> host(set.nodes.size());
  double largest = 0.0;
  for (int n = 0; n < steps; ++n) {
    bolt_forces(set, host);
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      set.nodes.v[i] = set.nodes.v[i] + (dt / set.nodes.mass[i]) * set.nodes.force[i];
      set.nodes.u[i] = set.nodes.u[i] + dt * set.nodes.v[i];
      largest = std::max(largest, std::fabs(set.nodes.u[i].x));
    }
    if (!(largest < 1.0)) break;
  }
  return largest;
}

TEST(BoltTimeStep, CriticalStepIsSafeAndTight) {
  EXPECT_LT(amplitude_after(0.99, 20000), 1e-5);
  EXPECT_GT(amplitude_after(1.1, 2000), 1e-3);
}

// ---------------------------------------------------------------------------------------------
// Pull-out in rigid ground

// The closed form, F0 at the head of a grouted length L, elastic bond.
double closed_ratio(double L, double x) {
  return std::sinh(lambda() * (L - x)) / std::sinh(lambda() * L);
}
double closed_head_stiffness(double L) {
  return kEA * lambda() * std::tanh(lambda() * L);
}
double closed_slip_onset(double L) {
  return kBondStrength / lambda() * std::tanh(lambda() * L);
}

// The closed-form pull-out load at head (collar) displacement u0, through debonding to s_b L.
double closed_load(double L, double u0) {
  const double s_b = kBondStrength, lam = lambda();
  if (u0 <= s_b / kBondStiffness) return closed_head_stiffness(L) * u0;
  auto f0 = [&](double l) { return s_b * (l + std::tanh(lam * (L - l)) / lam); };
  auto u_at = [&](double l) {
    return s_b / kBondStiffness + (f0(l) * l - s_b * l * l / 2.0) / kEA;
  };
  if (u0 >= u_at(L)) return s_b * L;
  double lo = 0.0, hi = L;
  for (int i = 0; i < 200; ++i) (u_at(0.5 * (lo + hi)) < u0 ? lo : hi) = 0.5 * (lo + hi);
  return f0(0.5 * (lo + hi));
}

// The exact static answer of the discrete chain the test builds (collar node 0 with half a
// segment of grout, n segments of EA/dx, end node with half), load P at the collar: node
// displacements by the tridiagonal (Thomas) solve.
std::vector<double> chain_displacements(double L, int n, double P) {
  const double dx = L / n, k = kEA / dx;
  const size_t m = static_cast<size_t>(n) + 1;
  std::vector<double> diag(m), rhs(m, 0.0), c(m), d(m), u(m);
  for (size_t i = 0; i < m; ++i) {
    const bool end = i == 0 || i + 1 == m;
    diag[i] = (end ? k : 2.0 * k) + kBondStiffness * dx * (end ? 0.5 : 1.0);
  }
  rhs[0] = P;
  c[0] = -k / diag[0];
  d[0] = rhs[0] / diag[0];
  for (size_t i = 1; i < m; ++i) {
    const double pivot = diag[i] + k * c[i - 1];
    c[i] = -k / pivot;
    d[i] = (rhs[i] + k * d[i - 1]) / pivot;
  }
  u[m - 1] = d[m - 1];
  for (size_t i = m - 1; i-- > 0;) u[i] = d[i] - c[i] * u[i + 1];
  return u;
}

// A pulled bolt along +x: the head (jack) at x = -dx, a free tail of one segment to the collar at
// x = 0, 40 grouted segments to x = L. Pulling the head towards -x puts it in tension.
struct Pullout {
  BoltSet set;
  std::vector<Vec2> host;    // the rock: rigid, fixed
  std::vector<double> mass;  // density-scaled, as the solver does for static runs
  double L = 0.0, dx = 0.0;
  static constexpr size_t head = 0, collar = 1;

  Pullout(double length, const BoltParams& p) : L(length), dx(length / kSegments) {
    set.laws.push_back(bolt_law(p));
    add_bolt(set, {{-dx, 0.0}, {L, 0.0}, kSegments, dx, 0});
    host.assign(set.nodes.size(), Vec2{});
    rescale_masses();
  }
  // m = (1 + alpha) k / (4 f^2) for a step of 1 (engine/solver/prepare.cpp's rule).
  void rescale_masses() {
    const std::vector<double> k = bolt_node_stiffness(set);
    mass.resize(k.size());
    for (size_t i = 0; i < k.size(); ++i)
      mass[i] = (1.0 + kAlpha) * k[i] / (4.0 * kFraction * kFraction);
  }
  double load() const { return set.nodes.force[head].x; }  // what holds the head, tension +
  double collar_pull() const { return -set.nodes.u[collar].x; }
  // The axial force at node i from the segments either side (their mean; the collar: the tail's).
  double node_force(size_t i) const {
    return i == collar ? set.segments.force[0]
                       : 0.5 * (set.segments.force[i - 1] + set.segments.force[i]);
  }

  // One cycle's forces; the largest unbalanced force on a free node [N/m]. The head is either
  // loaded by `head_force` towards -x or moved by the caller.
  double forces(bool hold_head, double head_force) {
    bolt_forces(set, host);
    double unbalanced = 0.0;
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      if (i == head && hold_head) continue;
      const Vec2 f = unbalanced_force(i, head_force);
      unbalanced = std::max(unbalanced, std::max(std::fabs(f.x), std::fabs(f.y)));
    }
    return unbalanced;
  }
  // Local damping (the solver's), step 1; and `viscous` damping of the nodes' velocities about
  // their mass-weighted mean, which leaves the bolt's motion as a whole alone.
  void move(bool hold_head, double head_force) {
    Vec2 mean{};
    if (viscous > 0.0) {
      double total = 0.0;
      for (size_t i = 0; i < set.nodes.size(); ++i) {
        if (i == head && hold_head) continue;
        mean = mean + mass[i] * set.nodes.v[i];
        total += mass[i];
      }
      mean = (1.0 / total) * mean;
    }
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      if (i == head && hold_head) continue;
      const Vec2 f = unbalanced_force(i, head_force);
      Vec2& v = set.nodes.v[i];
      v = v - viscous * (v - mean);
      v.x += (f.x - kAlpha * std::fabs(f.x) * sign(v.x)) / mass[i];
      v.y += (f.y - kAlpha * std::fabs(f.y) * sign(v.y)) / mass[i];
      set.nodes.u[i] = set.nodes.u[i] + v;
    }
  }
  Vec2 unbalanced_force(size_t i, double head_force) const {
    return set.nodes.force[i] + Vec2{i == head ? -head_force : 0.0, 0.0};
  }

  // Damped explicit cycles until the largest unbalanced force on a free node is below
  // `tolerance` [N/m]. Returns the cycles taken; the state is that of the converged forces.
  long relax(double tolerance, bool hold_head, double head_force = 0.0) {
    for (long cycle = 0; cycle < kMaxCycles; ++cycle) {
      if (forces(hold_head, head_force) <= tolerance) return cycle;
      move(hold_head, head_force);
    }
    ADD_FAILURE() << "no equilibrium in " << kMaxCycles << " cycles";
    return kMaxCycles;
  }

  // Kinetic energy of the free nodes (scaled masses, step 1) over the elastic energy stored in the
  // segments and the grout [-].
  double energy_ratio() const {
    double kinetic = 0.0, strain = 0.0;
    for (size_t i = 0; i < set.nodes.size(); ++i) {
      if (i != head) kinetic += 0.5 * mass[i] * dot(set.nodes.v[i], set.nodes.v[i]);
      if (set.nodes.grout_stiffness[i] > 0.0)
        strain += 0.5 * set.nodes.grout_force[i] * set.nodes.grout_force[i] /
                  set.nodes.grout_stiffness[i];
    }
    for (size_t s = 0; s < set.segments.size(); ++s)
      strain += 0.5 * set.segments.force[s] * set.segments.force[s] * set.segments.rest[s] / kEA;
    return kinetic / strain;
  }

  static double sign(double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; }
  static constexpr double kAlpha = 0.8, kFraction = 0.9;
  double viscous = 0.0;  // of the velocity about the mean, lost per cycle [-]
  static constexpr long kMaxCycles = 2'000'000;
};

// Elastic stage at half the slip-onset load: F(x)/F0, the head stiffness, against the closed form
// (and `table`, values of it worked by hand, to their rounding) and the discrete chain.
void check_elastic(double L, const double (&x)[3], const double (&table)[3],
                   double table_stiffness) {
  Pullout bolt(L, seed_params(1e9, 1.0));
  const double F0 = 0.5 * closed_slip_onset(L);
  const long cycles = bolt.relax(1e-9 * F0, false, F0);
  EXPECT_NEAR(bolt.load(), F0, 1e-8 * F0);
  for (size_t i = 0; i < bolt.set.nodes.size(); ++i) EXPECT_FALSE(bolt.set.nodes.slipping[i]);
  const std::vector<double> chain = chain_displacements(L, kSegments, F0);
  // The relaxed state is the discrete chain's static answer.
  for (size_t i = 0; i < chain.size(); ++i)
    EXPECT_NEAR(-bolt.set.nodes.u[Pullout::collar + i].x, chain[i], 1e-6 * chain[0]) << i;

  const double measured_k = F0 / bolt.collar_pull(), chain_k = F0 / chain[0];
  const double closed_k = closed_head_stiffness(L);
  std::printf(
      "L = %g m: %ld cycles; head stiffness %.5f MN/m, discrete chain %.5f MN/m, closed form "
      "%.5f MN/m (table %.2f): measured/closed - 1 = %+.3e, measured/chain - 1 = %+.1e\n",
      L, cycles, measured_k / 1e6, chain_k / 1e6, closed_k / 1e6, table_stiffness,
      measured_k / closed_k - 1.0, measured_k / chain_k - 1.0);
  EXPECT_NEAR(measured_k, closed_k, 0.01 * closed_k);
  EXPECT_NEAR(measured_k, chain_k, 1e-6 * chain_k);
  EXPECT_NEAR(closed_k / 1e6, table_stiffness, 0.005);  // the table's rounding

  for (int j = 0; j < 3; ++j) {
    const size_t node = Pullout::collar + static_cast<size_t>(std::lround(x[j] / bolt.dx));
    EXPECT_NEAR(bolt.set.nodes.x[node].x, x[j], 1e-12);
    const double measured = bolt.node_force(node) / F0, closed = closed_ratio(L, x[j]);
    std::printf("  F(%.4g)/F0: measured %.5f, closed form %.5f, table %.4f: error %+.2e of F0\n",
                x[j], measured, closed, table[j], measured - closed);
    EXPECT_NEAR(measured, closed, 0.02);
    EXPECT_NEAR(measured, closed, 0.005);   // and within the tighter 0.5 % of F0
    EXPECT_NEAR(closed, table[j], 0.0006);  // the table's values, to their rounding
  }
}

TEST(BoltPullout, Elastic5m) {
  check_elastic(5.0, {1.25, 2.5, 3.75}, {0.3818, 0.1435, 0.0479}, 65.03);
}

TEST(BoltPullout, Elastic05m) {
  check_elastic(0.5, {0.125, 0.25, 0.375}, {0.742, 0.491, 0.244}, 23.84);
}

// Head speeds [m per cycle] slow enough for kinetic energy below 1e-4 of the strain energy.
constexpr double kRate5 = 1e-7, kRate05 = 2e-8;
// Local damping alone leaves the bolt ringing while it slides as a whole (every node's velocity
// keeps its sign, so the damping never opposes the ringing), and the ringing drags like friction:
// the plateau came out 0.13% (5 m) and 1.3% (0.5 m) above s_b L. Damping the velocities about
// their mean stops the ringing and leaves the sliding alone (plain mass-proportional damping
// would drag too: viscous x mass x speed / (1 - alpha) per node).
constexpr double kViscous = 0.01;

struct Curve {
  std::vector<double> head, collar, load;  // [m], [m], [N/m]
  std::vector<double> energy_ratio;        // kinetic / strain energy [-]
  double peak() const { return *std::max_element(load.begin(), load.end()); }
  // The largest kinetic / strain energy once the load is past a tenth of its peak (before, the
  // strain energy is next to nothing).
  double largest_energy_ratio() const {
    double largest = 0.0;
    for (size_t i = 0; i < load.size(); ++i)
      if (load[i] > 0.1 * peak()) largest = std::max(largest, energy_ratio[i]);
    return largest;
  }
};

// The head driven towards -x at `rate` [m per cycle] to `distance` [m], the rest cycling as in
// relax() (the velocity-driven head of Itasca's pull-out example: recording without stopping, as
// a hold lets the bolt behind a yielding segment catch up and unload it). Records every
// `distance / records`.
Curve drive(Pullout& bolt, double rate, double distance, int records) {
  Curve c;
  bolt.viscous = kViscous;
  const long cycles = std::lround(distance / rate), every = cycles / records;
  for (long n = 1; n <= cycles; ++n) {
    bolt.set.nodes.u[Pullout::head].x = -rate * static_cast<double>(n);
    bolt.set.nodes.v[Pullout::head].x = -rate;
    bolt.forces(true, 0.0);
    if (n % every == 0) {
      c.head.push_back(-bolt.set.nodes.u[Pullout::head].x);
      c.collar.push_back(bolt.collar_pull());
      c.load.push_back(bolt.load());
      c.energy_ratio.push_back(bolt.energy_ratio());
    }
    bolt.move(true, 0.0);
  }
  return c;
}

// The largest difference between the curve and the closed-form F0-u0 curve [N/m], at loads up
// to `upto`, and the collar displacement where it is.
struct CurveError {
  double worst = 0.0, at = 0.0;
};
CurveError against_closed_form(const Curve& c, double L, double upto) {
  CurveError e;
  for (size_t i = 0; i < c.load.size() && c.load[i] < upto; ++i) {
    const double d = std::fabs(c.load[i] - closed_load(L, c.collar[i]));
    if (d > e.worst) e = {d, c.collar[i]};
  }
  return e;
}

// Peak within 1% of `capacity` (and within the tighter 0.1%), and the last `plateau`
// records at it.
void check_peak_and_plateau(const Curve& c, double capacity, size_t plateau, const char* what) {
  const double peak = c.peak();
  double spread = 0.0;
  ASSERT_GE(c.load.size(), plateau);
  for (size_t i = c.load.size() - plateau; i < c.load.size(); ++i)
    spread = std::max(spread, std::fabs(c.load[i] - capacity));
  std::printf(
      "%s: peak %.6f MN, expected %.6f MN, error %+.2e; plateau over the last %zu records "
      "(head %.1f to %.1f mm) within %.2e of it; kinetic/strain energy at most %.1e\n",
      what, peak / 1e6, capacity / 1e6, peak / capacity - 1.0, plateau,
      c.head[c.load.size() - plateau] * 1e3, c.head.back() * 1e3, spread / capacity,
      c.largest_energy_ratio());
  EXPECT_NEAR(peak, capacity, 0.01 * capacity);
  EXPECT_NEAR(peak, capacity, 0.001 * capacity);
  EXPECT_NEAR(spread, 0.0, 0.001 * capacity);
  EXPECT_LT(c.largest_energy_ratio(), 1e-4);  // slow enough: kinetic below 1e-4 of strain energy
}

// Bond failure: L = 5 m with a bolt strong enough (F_y = 1.5 MN > s_b L = 1 MN). The curve
// follows the closed-form debonding curve, the peak is s_b L, and it stays there.
TEST(BoltPullout, BondFailure5mPeaksAndHoldsAtBondCapacity) {
  Pullout bolt(5.0, seed_params(1.5e6, kSeedFailureStrain));
  const Curve c = drive(bolt, kRate5, 0.05, 200);  // to 50 mm; fully debonded at ~35 mm
  const double capacity = kBondStrength * 5.0;
  const CurveError e = against_closed_form(c, 5.0, capacity);
  std::printf(
      "L = 5 m, bond failure: F0-u0 curve within %.2e of s_b L of the closed form, worst at "
      "collar displacement %.2f mm\n",
      e.worst / capacity, e.at * 1e3);
  EXPECT_LT(e.worst, 0.02 * capacity);
  check_peak_and_plateau(c, capacity, 40, "L = 5 m, bond failure");
  for (size_t i = 0; i < bolt.set.nodes.size(); ++i)
    if (i != Pullout::head) {
      EXPECT_TRUE(bolt.set.nodes.slipping[i]) << i;
    }
  for (SegmentState s : bolt.set.segments.state) EXPECT_EQ(s, SegmentState::elastic);
}

TEST(BoltPullout, BondFailure05mPeaksAndHoldsAtBondCapacity) {
  Pullout bolt(0.5, seed_params());                 // s_b L = 100 kN < F_y = 156 kN
  const Curve c = drive(bolt, kRate05, 0.01, 100);  // to 10 mm; fully debonded at ~4.3 mm
  const double capacity = kBondStrength * 0.5;
  const CurveError e = against_closed_form(c, 0.5, capacity);
  std::printf(
      "L = 0.5 m, bond failure: F0-u0 curve within %.2e of s_b L of the closed form, worst "
      "at collar displacement %.2f mm\n",
      e.worst / capacity, e.at * 1e3);
  EXPECT_LT(e.worst, 0.02 * capacity);
  check_peak_and_plateau(c, capacity, 40, "L = 0.5 m, bond failure");
  for (SegmentState s : bolt.set.segments.state) EXPECT_EQ(s, SegmentState::elastic);
}

// Bolt yield: L = 5 m, F_y = 0.156 MN < s_b L = 1 MN (and below the slip onset, 0.26 MN): the
// free tail yields at F_y and the load holds there; no grout slips.
TEST(BoltPullout, BoltYield5mHoldsAtYieldForce) {
  Pullout bolt(5.0, seed_params(kSeedYield, 1.0));  // failure strain high: a long plateau
  const Curve c = drive(bolt, kRate5, 0.02, 80);    // to 20 mm; yields at ~2.6 mm
  check_peak_and_plateau(c, kSeedYield, 60, "L = 5 m, bolt yield");
  EXPECT_EQ(bolt.set.segments.state[0], SegmentState::yielded);
  for (size_t s = 1; s < bolt.set.segments.size(); ++s)
    EXPECT_EQ(bolt.set.segments.state[s], SegmentState::elastic) << s;
  for (std::uint8_t slipping : bolt.set.nodes.slipping) EXPECT_FALSE(slipping);
}

// Pulled on past the failure strain (3.5% of the 0.125 m tail: 4.4 mm beyond its length), the
// tail breaks: it carries exactly 0, the load drops to exactly 0, and stays there whether the
// head is pulled further or pushed back.
TEST(BoltPullout, BoltBreaksPastFailureStrainAndLoadDropsToZero) {
  Pullout bolt(5.0, seed_params());
  const BoltSegments& g = bolt.set.segments;
  const double rest = g.rest[0];
  double peak = 0.0, load_before = 0.0, strain_before = 0.0, strain_at = 0.0, head_at = 0.0;
  long broke = -1, loaded_after = 0;
  const long cycles = std::lround(0.01 / kRate5);  // to 10 mm
  for (long n = 1; n <= cycles; ++n) {
    bolt.set.nodes.u[Pullout::head].x = -kRate5 * static_cast<double>(n);
    bolt.set.nodes.v[Pullout::head].x = -kRate5;
    bolt.forces(true, 0.0);
    if (broke < 0 && g.state[0] == SegmentState::broken) {
      broke = n;
      strain_at = g.elongation[0] / rest;
      head_at = kRate5 * static_cast<double>(n);
    }
    if (broke < 0) {
      load_before = bolt.load();
      strain_before = g.elongation[0] / rest;
      peak = std::max(peak, load_before);
    } else if (bolt.load() != 0.0 || g.force[0] != 0.0) {
      ++loaded_after;
    }
    bolt.move(true, 0.0);
  }
  ASSERT_GT(broke, 0) << "never broke";
  // Where it should: the collar held where F_y puts it (the discrete chain's answer), the tail
  // stretched by 3.5%.
  const double expected_head =
      chain_displacements(5.0, kSegments, kSeedYield)[0] + kSeedFailureStrain * rest;
  std::printf(
      "L = 5 m, break: peak %.6f MN, load %.6f MN the cycle before, 0 from the cycle it "
      "broke, at head displacement %.4f mm (expected %.4f); tail strain - failure strain "
      "%+.1e the cycle before, %+.1e that cycle\n",
      peak / 1e6, load_before / 1e6, head_at * 1e3, expected_head * 1e3,
      strain_before - kSeedFailureStrain, strain_at - kSeedFailureStrain);
  EXPECT_NEAR(head_at, expected_head, 1e-5);
  EXPECT_NEAR(peak, kSeedYield, 1e-3 * kSeedYield);
  EXPECT_EQ(load_before, kSeedYield);  // yielding up to the last cycle
  EXPECT_LE(strain_before, kSeedFailureStrain);
  EXPECT_GT(strain_at, kSeedFailureStrain);
  EXPECT_EQ(loaded_after, 0);
  EXPECT_EQ(g.state[0], SegmentState::broken);
  // Push the head back in, past where it started: still nothing.
  bolt.set.nodes.u[Pullout::head].x = 5e-3;
  bolt.relax(1e-9 * kSeedYield, true);
  EXPECT_EQ(bolt.load(), 0.0);
  EXPECT_EQ(g.force[0], 0.0);
  // Behind the break the bolt is back in equilibrium, unloaded at the collar.
  EXPECT_NEAR(g.force[1], bolt.set.nodes.grout_force[Pullout::collar], 1e-3);
  // A broken segment drops out of the time step.
  EXPECT_EQ(bolt_node_stiffness(bolt.set)[Pullout::head], 0.0);
}

}  // namespace
}  // namespace edem
