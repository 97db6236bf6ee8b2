// One contact's force near a convex corner of the edge's block: a gridpoint on the corner (in or
// out by round-off) keeps its contact; one that has gone beside the block, past the corner, is not
// pressed in by the far extension of the edge's line (the seed cavern's wall gridpoint beside a
// heaved floor's corner once took 1 GPa from that), nor, within the edge, by the line of a thin
// tip's far face; a tip pressed into a face carries over a length that grows with its depth.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "contact/contact_force.hpp"

namespace edem {
namespace {

// The block below y = 0, x >= 0: its top edge runs from a = (1, 0) to b = (0, 0) (block on the
// left), and its boundary turns down at b to (0, -1), a convex corner. Node 3 is the gridpoint.
struct Corner {
  std::vector<double> origin{1, 0, 0, 0, 0, -1, 0, 0};
  std::vector<double> u = std::vector<double>(8, 0.0), v = std::vector<double>(8, 0.0);
  // The top edge, and the next one down from its corner b (the previous is not used here).
  std::vector<ContactEdge> edges = std::vector<ContactEdge>(2);
  JointParams joint;
  Contact contact;

  Corner() {
    ContactEdge& edge = edges[0];
    edge.a = 0;
    edge.b = 1;
    edge.prev = edge.next = 1;
    edge.corner_b = true;
    edges[1].a = 1;
    edges[1].b = 2;
    for (ContactEdge& e : edges) e.touchable = true;  // a free outline, nothing glued
    joint.kn = 1e9;
    joint.ks = 1e8;
    joint.kn_zero = joint.kn_max = joint.kn;
    contact.node = 3;
    contact.edge = 0;
    contact.length = 0.1;
  }
  double force_at(double x, double y) {
    origin[6] = x;
    origin[7] = y;
    ContactLoss lost;
    contact_force(contact, edges.data(), joint, origin.data(), u.data(), v.data(), 1e-4, lost);
    return contact.fy;
  }
  // The gridpoint moved along `steps` + 1 points (point(i) gives x, y): the largest change of the
  // force between neighbouring points, and the largest force [N/m].
  struct Steps {
    double jump = 0.0, largest = 0.0;
  };
  template <class Point>
  Steps force_steps(int steps, Point point) {
    Steps r;
    double fx = 0.0, fy = 0.0;
    for (int i = 0; i <= steps; ++i) {
      const std::array<double, 2> at = point(i);
      force_at(at[0], at[1]);
      if (i > 0) r.jump = std::max(r.jump, std::hypot(contact.fx - fx, contact.fy - fy));
      fx = contact.fx;
      fy = contact.fy;
      r.largest = std::max(r.largest, std::hypot(fx, fy));
    }
    return r;
  }
};

TEST(ContactForce, OnTheFaceItPushesOutByTheClosure) {
  Corner c;
  EXPECT_DOUBLE_EQ(c.force_at(0.5, -1e-3), 1e9 * 1e-3 * 0.1);
}

TEST(ContactForce, OnTheCornerInOrOutByRoundOffItKeepsItsForce) {
  Corner c;
  const double inside = c.force_at(1e-12, -1e-3), outside = c.force_at(-1e-12, -1e-3);
  EXPECT_NEAR(inside, 1e9 * 1e-3 * 0.1, 1e-6);
  EXPECT_NEAR(outside, inside, 1e-6);
}

TEST(ContactForce, JustPastTheCornerTheForceFadesWithTheShare) {
  Corner c;
  const double f = c.force_at(-0.05, -1e-3);  // past by half its length, a quarter of the span
  EXPECT_NEAR(f, 1e9 * 1e-3 * 0.1 * (1.0 - 0.25 * 0.25 * (3.0 - 2.0 * 0.25)), 1e-6);
  EXPECT_NEAR(c.force_at(-0.1, -1e-3), 1e9 * 1e-3 * 0.1 * 0.5, 1e-6);  // halfway
}

// A face pressed in and slid off the corner: the energy its fade takes (its springs' share) comes
// back as work on the gridpoint, a push along the face away from the corner, so sliding off loses
// nothing. Without it the energy of every face that slides off a corner under load would vanish.
TEST(ContactForce, SlidOffTheCornerTheFadeGivesItsEnergyBackAsWork) {
  Corner c;
  c.force_at(0.02, -1e-3);
  const double start = stored_in(c.contact, c.joint);  // kn d^2 length / 2 = 50 J/m
  ASSERT_NEAR(start, 50.0, 1e-9);
  constexpr int kSteps = 4000;
  double work = 0.0, x = 0.02, before = c.contact.fx;
  for (int i = 1; i <= kSteps; ++i) {  // to 0.25 m past the corner: gone at 0.2 m
    const double next = 0.02 - 0.27 * i / kSteps;
    c.force_at(next, -1e-3);
    work += 0.5 * (before + c.contact.fx) * (next - x);
    before = c.contact.fx;
    x = next;
  }
  EXPECT_EQ(stored_in(c.contact, c.joint), 0.0);
  EXPECT_NEAR(work, start, 1e-3 * start);
  // Halfway the share falls fastest, by 1.5 over the span (0.2 m): the push is the energy per
  // share times that, away from the corner. On the corner, in or out by round-off, none.
  c.force_at(-0.1, -1e-3);
  EXPECT_NEAR(c.contact.fx, -50.0 * 1.5 / 0.2, 1e-9);
  EXPECT_NEAR(c.contact.fy, 0.5 * 1e9 * 1e-3 * 0.1, 1e-6);
  c.force_at(-1e-12, -1e-3);
  EXPECT_NEAR(c.contact.fx, 0.0, 1e-6);
}

TEST(ContactForce, BesideTheBlockPastItsCornerNoDeepLinePressesItIn) {
  Corner c;
  c.origin[4] = 1.0;  // the boundary turns down at 45 deg at b, to (1, -1): an acute corner
  // 0.05 m past the corner along the edge (a quarter of the span) but 0.5 m below its line: by
  // that line 0.5 m deep, yet 0.39 m outside the block's other face, more than the fade span
  // (0.2 m).
  EXPECT_EQ(c.force_at(-0.05, -0.5), 0.0);
  EXPECT_EQ(c.contact.sn, 0.0);
  // 0.2 m below the line, 0.177 m outside the other face: deep by at most 0.2 - 0.177 m.
  c.force_at(-0.05, -0.2);
  EXPECT_NEAR(c.contact.closure, 0.2 - 0.25 / std::sqrt(2.0), 1e-12);
}

TEST(ContactForce, ATipPressedInCarriesOverALengthGrowingWithItsDepth) {
  Corner c;
  c.contact.length = 0.001;  // its half-edges' projection: almost nothing
  c.contact.wedge = 0.25;    // half the chord its edges cut on the face, per unit depth
  c.contact.limit = 0.1;
  EXPECT_NEAR(c.force_at(0.5, -1e-3), 1e9 * 1e-3 * 0.001, 1e-6);  // its own length still larger
  EXPECT_NEAR(c.force_at(0.5, -0.04), 1e9 * 0.04 * (0.25 * 0.04), 1e-3);
  EXPECT_NEAR(c.force_at(0.5, -0.2), 1e9 * 0.2 * (0.25 * 0.1), 1e-3);  // no longer than at the limit
  c.contact.length = 0.0;  // a tip and nothing more: carries nothing until pressed in
  EXPECT_EQ(c.force_at(0.5, 1e-3), 0.0);
  EXPECT_EQ(c.contact.state, ContactState::open);
}

// A tip pressed in less than the round-off of its closure (a prestressed joint holds centimetres
// of it): the overlap its last cycle left reads back as 0, so its length then reads as its own,
// almost nothing, and scaling its shear force by length now / length then would give it a shear
// stress of ~1e19 Pa, all of it "dissipated" by slip (in the seed cavern's Case 1, mirrored,
// 7.5e16 J/m). It carries nothing worth keeping: its shear spring starts afresh.
TEST(ContactForce, ATipPressedInBelowTheRoundOffOfItsClosureMakesNoEnergy) {
  Corner c;
  c.joint.tan_friction = c.joint.tan_residual_friction = 0.6;
  c.contact.length = 1e-31;  // an edge all but square to the face
  c.contact.wedge = 1.35;
  c.contact.limit = 0.1;
  c.contact.closure0 = 0.05;  // the in-situ closure: 50 MPa at this kn
  c.v[6] = 1e-3;              // sliding along the face
  ContactLoss lost;
  for (int i = 0; i < 10; ++i) {
    c.origin[6] = 0.5 + 1e-7 * i;
    c.origin[7] = -5e-19 * (1 + i % 3);
    contact_force(c.contact, c.edges.data(), c.joint, c.origin.data(), c.u.data(), c.v.data(), 1e-4, lost);
    const double length = c.contact.wedge * -c.origin[7];
    EXPECT_LE(std::fabs(c.contact.fs), 0.6 * c.contact.sn * length * (1 + 1e-12)) << i;
  }
  EXPECT_LT(std::fabs(lost.slip), 1e-9);
  EXPECT_LT(contact_energy(c.contact, c.joint).shear, 1e-9);
}

// A tip whose edges lead out past the sharp corner b (Contact::leads_past_b), pressed 0.04 m in:
// its tip carries over wedge x depth = 0.01 m, its overlap a chord of 0.02 m from its apex towards
// the corner. Beyond the corner it is beside the block and carries nothing, whatever sliver of
// length its half-edges give it; short of the corner its own length carries in full and only the
// tip's part beyond it is cut, by a smooth step of the part of the chord short of the corner.
TEST(ContactForce, PastASharpCornerItsEdgesLeadPastATipCarriesNothing) {
  Corner c;
  c.contact.wedge = 0.25;
  c.contact.limit = 0.1;
  c.contact.leads_past_b = true;
  for (const double own : {0.0, 1e-6, 0.005}) {
    c.contact.length = own;
    EXPECT_EQ(c.force_at(-0.05, -0.04), 0.0) << "own length " << own;
    EXPECT_EQ(c.contact.state, ContactState::open);
  }
}

TEST(ContactForce, ShortOfASharpCornerATipKeepsItsOwnLengthAndLosesOnlyTheTipsPartPastIt) {
  Corner c;
  c.contact.wedge = 0.25;
  c.contact.limit = 0.1;
  c.contact.leads_past_b = true;
  const double stress = 1e9 * 0.04, tip = 0.25 * 0.04;
  // The force its normal stress gives over the length it carries (the share's slope adds a push
  // of its own, ATipShortOfASharpCornerDoesNoWorkRoundAClosedPath).
  const auto carried = [&](double x, double y) {
    c.force_at(x, y);
    return c.contact.sn * last_carrying_length(c.contact);
  };
  // 0.01 m short of the corner: half the chord lies short of it, a share of 0.5 by the smooth step
  // q^2 (3 - 2 q) of that part q.
  const double tip_share = 0.5 * 0.5 * (3.0 - 2.0 * 0.5);
  c.contact.length = 0.0;
  EXPECT_NEAR(carried(0.01, -0.04), stress * tip * tip_share, 1e-6);
  c.contact.length = 0.009;  // less than the tip's, more than its part short of the corner
  EXPECT_NEAR(carried(0.01, -0.04), stress * 0.009, 1e-6);
  c.contact.length = 0.02;  // more than the tip's: its own, with no slope to push by
  EXPECT_NEAR(carried(0.01, -0.04), stress * 0.02, 1e-6);
  EXPECT_NEAR(c.force_at(0.01, -0.04), stress * 0.02, 1e-6);
  c.contact.length = 0.0;  // far enough from the corner, the whole tip, and nothing more
  EXPECT_NEAR(c.force_at(0.5, -0.04), stress * tip, 1e-6);
}

// A tip short of a sharp corner carries a share of its length that hangs on its distance from the
// corner and on its depth: its force is the slope of the energy it stores, so that taken round a
// closed path it does no net work. Two corners pressed into each other at a slipped joint crossing
// rock round such paths; a force only along the normal, share x the whole tip's, made about 6e4 J/m
// a swing in the seed cavern's Case 3 at 262 m. The path crosses where the tip's chord reaches the
// corner (share below 1 on one side, 1 on the other), for a tip alone and for one with a length of
// its own that the tip outgrows, by the corner at either end of the edge. And from one point to
// another the work is the energy's fall.
TEST(ContactForce, ATipShortOfASharpCornerDoesNoWorkRoundAClosedPath) {
  for (const bool at_b : {true, false}) {
    for (const double own : {0.0, 0.009}) {
      Corner c;
      c.contact.wedge = 0.25;
      c.contact.limit = 0.1;
      (at_b ? c.contact.leads_past_b : c.contact.leads_past_a) = true;
      c.contact.length = own;
      const double x0 = at_b ? 0.0 : 1.0, sign = at_b ? 1.0 : -1.0;  // the corner, and away from it
      const std::array<std::array<double, 2>, 5> corners{{{x0 + sign * 0.004, -0.02}, {x0 + sign * 0.03, -0.02},
                                                          {x0 + sign * 0.03, -0.06}, {x0 + sign * 0.004, -0.06},
                                                          {x0 + sign * 0.004, -0.02}}};
      c.force_at(corners[0][0], corners[0][1]);
      const double start = contact_energy(c.contact, c.joint).normal;
      double fx = c.contact.fx, fy = c.contact.fy, work = 0.0, largest = 0.0;
      constexpr int kSteps = 16000;  // the share's slope jumps where its rule changes: O(1 / kSteps)
      for (size_t side = 0; side + 1 < corners.size(); ++side) {
        const double dx = (corners[side + 1][0] - corners[side][0]) / kSteps;
        const double dy = (corners[side + 1][1] - corners[side][1]) / kSteps;
        for (int i = 1; i <= kSteps; ++i) {
          c.force_at(corners[side][0] + i * dx, corners[side][1] + i * dy);
          work += 0.5 * (fx + c.contact.fx) * dx + 0.5 * (fy + c.contact.fy) * dy;
          fx = c.contact.fx;
          fy = c.contact.fy;
          largest = std::max(largest, contact_energy(c.contact, c.joint).normal);
        }
        if (side == 1) {  // from the first point to the far one: the work is the energy's fall
          EXPECT_NEAR(work, start - contact_energy(c.contact, c.joint).normal, 1e-4 * largest) << "own " << own
                                                                                                << " at b " << at_b;
        }
      }
      EXPECT_NEAR(work, 0.0, 1e-4 * largest) << "own length " << own << " at b " << at_b << ", largest energy "
                                             << largest;
    }
  }
}

// Where a tip short of a sharp corner goes from carrying its own length to carrying its cut tip's,
// its force must not jump: a gridpoint rocking across that switch would be pushed by a step that
// one sample a cycle integrates wrongly, and in the seed cavern's Case 3 at 262 m one chattered
// there, 787 switches in 3,000 cycles, 50 J/m made a cycle. Here the tip carries 0.01 m at 0.04 m
// deep, its own length 0.005 m: the two shares meet 0.01 m from the corner.
TEST(ContactForce, WhereATipsOwnLengthGivesWayToItsCutTipItsForceDoesNotJump) {
  Corner c;
  c.contact.wedge = 0.25;
  c.contact.limit = 0.1;
  c.contact.leads_past_b = true;
  c.contact.length = 0.005;
  constexpr double kStep = 1e-6;
  const auto [jump, largest] = c.force_steps(10000, [&](int i) {  // from 0.005 to 0.015 m from the corner
    return std::array<double, 2>{0.005 + i * kStep, -0.04};
  });
  // A force with a bounded slope moves by at most slope x step; a jump would be a sizeable part of
  // the force.
  EXPECT_LT(jump, 1e-3 * largest) << "largest force " << largest;
}

// A tip short of a sharp corner pressed across its reach (Contact::limit), where its length stops
// growing: its force must not jump there either. Its share hangs on the tip's length, and the
// share's slope with depth, times what its springs store, is part of its normal force; a length
// whose growth stopped sharply would drop that part at once. In the seed cavern's Case 3 at
// 212 m a gridpoint of a tip pressed to its reach rocked across it, 1.3e6 J/m made in 60,000
// cycles. Here the tip is 0.12 m from the corner (beyond its reach, so no corner caps its depth),
// its chord at the reach 0.2 m: a share of 0.65.
TEST(ContactForce, AcrossItsReachATipShortOfASharpCornerHasAForceThatDoesNotJump) {
  Corner c;
  c.contact.wedge = 1.0;
  c.contact.limit = 0.1;
  c.contact.leads_past_b = true;
  c.contact.length = 0.0;
  constexpr double kStep = 1e-6;
  const auto [jump, largest] = c.force_steps(40000, [&](int i) {  // from 0.08 to 0.12 m deep
    return std::array<double, 2>{0.12, -(0.08 + i * kStep)};
  });
  EXPECT_NEAR(c.contact.share, 0.648, 0.01);
  EXPECT_LT(jump, 1e-3 * largest) << "largest force " << largest;
}

// A tip's energy is the work of pressing it in slowly (its force growing as its depth squared
// past its own length, and only linearly again past the limit); with a prestress (closure at
// zero gap) the work starts from the prestress's energy.
TEST(ContactForce, ATipStoresTheWorkOfPressingItIn) {
  for (const double prestress : {0.0, 2e-3}) {
    Corner c;
    c.contact.length = 0.001;
    c.contact.wedge = 0.25;
    c.contact.limit = 0.1;
    c.contact.closure0 = prestress;
    double work = 0.0, before = c.force_at(0.5, 0.0);
    const double start = contact_energy(c.contact, c.joint).normal;
    constexpr int kSteps = 40000;
    for (int i = 1; i <= kSteps; ++i) {  // to 0.15 m deep, past the limit
      const double now = c.force_at(0.5, -0.15 * i / kSteps);
      work += 0.5 * (before + now) * 0.15 / kSteps;
      before = now;
    }
    EXPECT_NEAR(contact_energy(c.contact, c.joint).normal - start, work, 1e-4 * work) << prestress;
  }
}

// A tip that carries a shear force keeps its shear spring's energy as its length grows with its
// depth (contact_force): pressed in without a shear move, the work of its force is the change of
// both its springs' energy, and its shear spring's does not change with a tip alone or with one
// that outgrows its own length on the way (0.01 m, at 0.04 m deep). Short of a sharp corner its
// share falls as it sinks, which takes its stress's share of the shear energy away, paid by the
// share's push.
TEST(ContactForce, ATipCarryingAShearForceStoresTheWorkOfPressingItIn) {
  for (const int kind : {0, 1, 2}) {
    Corner c;
    c.contact.length = kind == 1 ? 0.01 : 0.0;
    c.contact.wedge = 0.25;
    c.contact.limit = 0.1;
    c.joint.ks = 1e9;
    c.joint.tan_friction = c.joint.tan_residual_friction = 10.0;
    const double x = kind == 2 ? 0.03 : 0.5;
    if (kind == 2) c.contact.leads_past_b = true;
    c.force_at(x, -0.02);
    c.contact.fs = 2e5;
    double fy = c.force_at(x, -0.02), fx = c.contact.fx;
    const ContactEnergy start = contact_energy(c.contact, c.joint);
    double work = 0.0;
    constexpr int kSteps = 40000;
    for (int i = 1; i <= kSteps; ++i) {  // from 0.02 to 0.08 m deep
      const double y = -0.02 - 0.06 * i / kSteps;
      const double now = c.force_at(x, y);
      work += 0.5 * (fy + now) * 0.06 / kSteps;
      fy = now;
      fx = c.contact.fx;
    }
    const ContactEnergy end = contact_energy(c.contact, c.joint);
    const double change = end.normal + end.shear - start.normal - start.shear;
    if (kind < 2) {
      EXPECT_NEAR(end.shear, start.shear, 1e-9 * start.shear) << kind;
    }
    EXPECT_NEAR(change, work, 1e-4 * work) << "kind " << kind << ", shear energy " << start.shear << " to "
                                           << end.shear << ", fx " << fx;
  }
}

// A tip whose own length is 0.37 mm, carrying a shear stress of 4.4 MPa on a soft joint (ks 3.6
// MPa/m), pressed across the band where its tip's length takes over from its own: its normal
// force grows no faster than its springs make it, the normal stress's slope over its length and
// the stress over the length's growth. A force that paid for a shear stress kept as the length
// grows rose by tau^2 wedge / (2 ks), 2.7e6 N/m, across the band's 74 micrometres, a stiffness of
// 3.6e10 N/m/m that no gridpoint's mass was scaled for: a tip of Case 3 at 212 m chattered on it.
TEST(ContactForce, AcrossItsBandATinyTipsNormalForceIsNoStifferThanItsSprings) {
  Corner c;
  c.contact.length = 3.7e-4;
  c.contact.wedge = 1.0;
  c.contact.limit = 0.5;
  c.joint.kn = c.joint.kn_zero = c.joint.kn_max = 8.4e7;
  c.joint.ks = 3.6e6;
  c.joint.tan_friction = c.joint.tan_residual_friction = 1e4;  // its stress stays as set
  const double from = 0.2e-3, to = 0.6e-3;  // the band: 0.333 to 0.407 mm deep
  c.force_at(0.5, -from);
  c.contact.fs = 4.4e6 * last_carrying_length(c.contact);
  double fy = c.force_at(0.5, -from), steepest = 0.0;
  constexpr int kSteps = 4000;
  for (int i = 1; i <= kSteps; ++i) {
    const double now = c.force_at(0.5, -(from + (to - from) * i / kSteps));
    steepest = std::max(steepest, (now - fy) / ((to - from) / kSteps));
    fy = now;
  }
  const double springs = c.joint.kn_max * to * c.contact.wedge + c.joint.kn_max * to;  // kn L + sn wedge
  EXPECT_NEAR(c.contact.fs / last_carrying_length(c.contact), 4.4e6, 0.5 * 4.4e6);
  EXPECT_LT(steepest, 2.0 * springs) << "fs " << c.contact.fs;
}

TEST(ContactForce, BesideAThinTipWithinTheEdgeNoDeepLinePressesItIn) {
  Corner c;
  c.origin[4] = 1.0;  // the boundary turns down at 45 deg at b, to (1, -1): a 45 deg tip
  c.contact.limit = 0.1;
  // 0.05 m from the tip along the edge, so within it, and 0.5 m below its line: by that line
  // 0.5 m deep, yet 0.32 m outside the tip's other face, more than the fade span (0.2 m).
  EXPECT_EQ(c.force_at(0.05, -0.5), 0.0);
  EXPECT_EQ(c.contact.sn, 0.0);
  // 0.2 m below the line, 0.106 m outside the other face: deep by at most 0.2 - 0.106 m.
  c.force_at(0.05, -0.2);
  EXPECT_NEAR(c.contact.closure, 0.2 - 0.15 / std::sqrt(2.0), 1e-12);
  // Farther along the edge than its reach from the corner, the same: 0.035 m outside the other
  // face, deep by at most 0.2 - 0.035 m.
  c.force_at(0.15, -0.2);
  EXPECT_NEAR(c.contact.closure, 0.2 - 0.05 / std::sqrt(2.0), 1e-12);
}

// The same 45 deg tip, a gridpoint 0.2 m below the edge's line sliding along it from 0.05 to
// 0.15 m from the tip, across its reach (0.1 m): the force changes with its place, never at once.
// Capped within the reach alone, the depth jumped there from 0.13 to 0.2 m, and a gridpoint
// rocking across the reach made energy at every crossing.
TEST(ContactForce, BesideAThinTipAcrossItsReachTheForceDoesNotJump) {
  Corner c;
  c.origin[4] = 1.0;
  c.contact.limit = 0.1;
  const auto [jump, largest] = c.force_steps(10000, [&](int i) {
    return std::array<double, 2>{0.05 + 1e-5 * i, -0.2};
  });
  EXPECT_GT(largest, 1e7);
  EXPECT_LT(jump, 1e-3 * largest);
}

// A face shorter than twice the reach, with convex corners at both ends: the block below it is a
// triangle, its top edge from a = (0.6, 0) to b = (0, 0), its third corner at (0.1, -0.6), so the
// tip at a (50 deg) is thinner than the one at b (80 deg). Node 3 is the gridpoint.
struct ShortFace {
  std::vector<double> origin{0.6, 0, 0, 0, 0.1, -0.6, 0, 0};
  std::vector<double> u = std::vector<double>(8, 0.0), v = std::vector<double>(8, 0.0);
  std::vector<ContactEdge> edges = std::vector<ContactEdge>(3);
  JointParams joint;
  Contact contact;

  ShortFace() {
    edges[0].a = 0, edges[0].b = 1, edges[0].prev = 2, edges[0].next = 1;
    edges[0].corner_a = edges[0].corner_b = true;
    edges[1].a = 1, edges[1].b = 2;  // b down to the third corner
    edges[2].a = 2, edges[2].b = 0;  // and up to a
    for (ContactEdge& e : edges) e.touchable = true;
    joint.kn = joint.kn_zero = joint.kn_max = 1e9;
    joint.ks = 1e8;
    contact.node = 3;
    contact.edge = 0;
    contact.length = 0.05;
    contact.limit = 0.47;
  }
  void place(double x, double y) { origin[6] = x, origin[7] = y; }
  double closure_at(double x, double y) {
    place(x, y);
    ContactLoss lost;
    contact_force(contact, edges.data(), joint, origin.data(), u.data(), v.data(), 1e-4, lost);
    return contact.closure;
  }
  // The gridpoint's depth behind the line from the third corner up to a.
  double behind_a() const {
    const double dx = 0.6 - 0.1, dy = 0.0 - -0.6;
    return ((origin[7] - -0.6) * dx - (origin[6] - 0.1) * dy) / std::hypot(dx, dy);
  }
};

// A gridpoint 0.35 m under the middle of the edge is within the reach of both corners and is
// inside by at most its depth inside either neighbouring line plus the span: the lesser of the
// two, whichever half of the edge it is over. Taken from the nearer corner alone, its depth jumped
// from one line's to the other's as it crossed the middle, and a gridpoint rocking there made
// energy at every crossing.
TEST(ContactForce, UnderAShortFaceBetweenTwoCornersTheDepthDoesNotJumpAtItsMiddle) {
  ShortFace f;
  const double over_b_half = f.closure_at(0.3 - 1e-9, -0.35), over_a_half = f.closure_at(0.3 + 1e-9, -0.35);
  const double expected = f.behind_a() + 2.0 * f.contact.length;
  EXPECT_NEAR(over_a_half, expected, 1e-8);
  EXPECT_NEAR(over_b_half, expected, 1e-8);
}

// A tip over the edge near its acute corner a, 0.3 m behind the edge's line yet outside the line
// of the face beside a: the force takes the edge's line's overlap there (the cap adds the span its
// force fades over, twice wedge x limit), but the gridpoint is beside the block, not in it, and
// the overlap watchdog asks how deep it is in the block.
TEST(ContactForce, BesideAnAcuteCornerAGridpointDeepBehindTheEdgesLineIsNotInTheBlock) {
  ShortFace f;
  f.contact.length = 0.0;
  f.contact.wedge = 1.0;
  EXPECT_NEAR(f.closure_at(0.57, -0.3), 0.3, 1e-12);
  EXPECT_LT(f.behind_a(), -0.1);
  EXPECT_NEAR(depth_in_block(f.contact, f.edges.data(), f.origin.data(), f.u.data()), f.behind_a(), 1e-12);
  // Under the middle, deep in it: the least of its depths behind the three lines.
  f.place(0.3, -0.2);
  EXPECT_GT(f.behind_a(), 0.0);
  EXPECT_NEAR(depth_in_block(f.contact, f.edges.data(), f.origin.data(), f.u.data()),
              std::min(0.2, f.behind_a()), 1e-12);
}

// The same 45 deg tip, its other edge glued (ContactEdge::glued_tip_b: the block glued there goes
// on past it): a gridpoint over the edge is inside by at most its depth inside the glued edge's
// line, so its force goes to nothing as it reaches that line, with no span added, and stays
// nothing beyond; away from the tip the edge's line decides.
TEST(ContactForce, PastAGluedTipTheForceGoesToNothingAtTheGluedLine) {
  Corner c;
  c.origin[4] = 1.0;
  c.edges[0].glued_tip_b = true;
  c.edges[1].touchable = false;  // the glued edge
  c.edges[0].glued_line_b = 1;
  c.contact.limit = 0.1;
  c.force_at(0.05, -0.03);  // 0.03 m below the line, 0.014 m inside the glued one
  EXPECT_NEAR(c.contact.closure, 0.02 / std::sqrt(2.0), 1e-12);
  double last = c.force_at(0.05, -0.04);
  for (const double depth : {0.045, 0.049, 0.0499, 0.05}) {
    const double now = c.force_at(0.05, -depth);
    EXPECT_LE(now, last) << depth;  // falling to nothing, not dropped from a height
    EXPECT_LT(now, 1e9 * (0.05 - depth) * 0.1 + 1e-9) << depth;
    last = now;
  }
  EXPECT_EQ(c.force_at(0.05, -0.2), 0.0);
  EXPECT_EQ(c.contact.sn, 0.0);
  c.force_at(0.6, -0.2);  // far from the tip
  EXPECT_NEAR(c.contact.closure, 0.2, 1e-12);
}

// A blunt glued tip at b: the boundary turns down-left at 135 deg to (-1, -1), glued there. A
// gridpoint sliding along the face at a constant depth across the end of the edge is inside by its
// depth inside the glued edge's line on both sides of the end, so its closure changes with the
// slide, never by a jump: a force that jumps as a gridpoint crosses the end and back makes energy
// at every crossing (such a jump keeps a step of the seed's cavern on Set M from settling in
// 40,000 cycles, +1.7e7 J/m).
TEST(ContactForce, AcrossTheEndOfAGluedTipTheClosureDoesNotJump) {
  Corner c;
  c.origin[4] = -1.0;
  c.edges[0].glued_tip_b = true;
  c.edges[1].touchable = false;  // the glued edge
  c.edges[0].glued_line_b = 1;
  c.contact.limit = 0.1;
  double last = NAN;
  for (int i = 0; i <= 16; ++i) {
    const double x = 0.004 - 0.0005 * i;  // from over the edge to past its end b at x = 0
    c.force_at(x, -0.005);
    // By the glued edge's line, y = x, it is inside by (x - y) / sqrt 2 below 0.005 m.
    EXPECT_NEAR(c.contact.closure, std::min(0.005, (x + 0.005) / std::sqrt(2.0)), 1e-12) << x;
    if (!std::isnan(last)) {
      EXPECT_LT(std::fabs(c.contact.closure - last), 0.0005 / std::sqrt(2.0) + 1e-12) << x;
    }
    last = c.contact.closure;
  }
}

// A straight run of two edges, (2, 0) to (1, 0) and on to (0, 0), ends at the 45 deg glued tip
// of PastAGluedTipTheForceGoesToNothingAtTheGluedLine. A gridpoint at the run's inner vertex, found
// on either edge, is inside by the same depth: its depth inside the glued edge's line where that
// is less than its depth below the face. Taken only on the tip's own edge, the depth jumped there
// from out of the block to the depth below the face's line: in the seed cavern's Case 3 at 158 m a
// gridpoint 0.93 m out of a glued line, found on the next edge of the run, was 1.3 m in, and its
// contact made 1.6e7 J/m in one cycle.
TEST(ContactForce, AlongAStraightRunToAGluedTipEitherEdgeGivesTheSameDepth) {
  for (const double y : {-0.1, -0.6, -1.3}) {
    double closure[2] = {0.0, 0.0};
    for (const int on : {0, 1}) {
      Corner c;
      // Nodes: 0 (1, 0), 1 (0, 0), 2 (1, -1), 3 the gridpoint, 4 (2, 0); edges 0: 0 -> 1 (the tip's,
      // glued on at 1), 1: 1 -> 2 (glued), 2: 4 -> 0 (the run before it).
      c.origin = {1, 0, 0, 0, 1, -1, 0, 0, 2, 0};
      c.u.assign(10, 0.0);
      c.v.assign(10, 0.0);
      c.edges.resize(3);
      c.edges[0].prev = 2;
      c.edges[0].glued_tip_b = true;
      c.edges[0].glued_line_b = 1;
      c.edges[1].touchable = false;
      c.edges[2].touchable = true;
      c.edges[2].a = 4;
      c.edges[2].b = 0;
      c.edges[2].prev = c.edges[2].next = 0;
      // The run's end towards the tip leads there (mark_glued_tips).
      c.edges[2].glued_line_b = 1;
      c.contact.limit = 0.1;
      c.contact.edge = on == 0 ? 0 : 2;
      c.force_at(on == 0 ? 0.9999 : 1.0001, y);
      closure[on] = c.contact.closure;
    }
    // By the glued line y = -x: inside by (x + y) / sqrt 2, at most the depth below the face.
    const double expected = std::min(-y, (1.0 + y) / std::sqrt(2.0));
    EXPECT_NEAR(closure[0], expected, 1e-4) << y;
    EXPECT_NEAR(closure[1], expected, 1e-4) << y;
  }
}

// The corner at b with its edge down glued, the rock glued beside (x < 0) going on along the
// face's line (a crack's mouth on a floor, no glued tip): a gridpoint 0.5 m below the face, 0.05 m
// from the glued line, is in the rock 0.5 m deep and pushed out of the face, not across the glued
// line by its 0.05 m from it (the apex of a block falling on the seed cavern's floor at 262 m went
// down a crack's line 1.1 m so). Sliding across the glued line the force fades with its share and
// never jumps: the glued block's own contact takes over there.
TEST(ContactForce, AtACornerGluedToRockThatGoesOnTheFaceAloneSetsTheDepth) {
  Corner c;
  c.edges[1].touchable = false;
  c.contact.limit = 1.1;
  c.force_at(0.05, -0.5);
  EXPECT_NEAR(c.contact.closure, 0.5, 1e-12);
  EXPECT_GT(c.contact.fy, 0.0);
  EXPECT_NEAR(c.contact.fx, 0.0, 1e-9 * c.contact.fy);
  EXPECT_NEAR(depth_in_block(c.contact, c.edges.data(), c.origin.data(), c.u.data()), 0.5, 1e-12);
  const Corner::Steps slide =
      c.force_steps(400, [](int i) { return std::array<double, 2>{0.05 - 0.001 * i, -0.5}; });
  EXPECT_LT(slide.jump, 0.02 * slide.largest);
  // Free there, the same corner caps the depth at the gridpoint's depth behind the edge down, plus
  // the span its force fades over.
  c.edges[1].touchable = true;
  c.force_at(0.05, -0.5);
  EXPECT_NEAR(c.contact.closure, 0.05 + 2.0 * c.contact.length, 1e-12);
}

// A tip pressed in beside a corner of the face's block takes as its overlap its depth inside the
// corner's other face (plus the fade span), less than its depth below the face's line, which is
// the distance a detection finds. Found again and again at rest, it keeps its shear force: its
// length is scaled at the overlap its force takes, whatever the detection measured.
TEST(ContactForce, ATipFoundAgainAtRestBesideACornerKeepsItsShearForce) {
  Corner c;
  c.origin[4] = 1.0;  // a 45 deg tip at b, as above
  c.joint.tan_friction = c.joint.tan_residual_friction = 1.0;
  c.contact.length = 0.001;
  c.contact.wedge = 0.25;
  c.contact.limit = 0.1;
  // 0.09 m from the tip along the edge and 0.12 m below its line, 0.021 m outside the tip's other
  // face: pressed in by 0.05 - 0.021 m (the fade span twice its largest length, 0.025 m).
  c.force_at(0.09, -0.12);
  const double overlap = 0.05 - 0.03 / std::sqrt(2.0);
  ASSERT_NEAR(c.contact.closure, overlap, 1e-12);
  c.contact.fs = 1e4;  // within Coulomb's limit, 1e9 x 0.029 x (0.25 x 0.029) = 2.1e5 N/m
  for (int detection = 0; detection < 10; ++detection) {
    Contact found;
    found.node = c.contact.node;
    found.edge = c.contact.edge;
    found.length = c.contact.length;
    found.wedge = c.contact.wedge;
    found.limit = c.contact.limit;
    keep_state(found, c.contact, c.joint);
    c.contact = found;
    c.force_at(0.09, -0.12);
    EXPECT_NEAR(c.contact.fs, 1e4, 1e-6) << "detection " << detection;
  }
  // Found with a longer length of its own than the tip's, it keeps its shear stress.
  Contact longer = c.contact;
  longer.length = 0.05;
  keep_state(longer, c.contact, c.joint);
  EXPECT_NEAR(longer.fs, 1e4 * 0.05 / (0.25 * overlap), 1e-6);
}

// The block is the plane but the quarter x > 0, y > 0 (a notch): its boundary runs from a = (1, 0)
// to the re-entrant corner b = (0, 0) (edge 0), then up to (0, 1) (edge 1). Node 3 is the gridpoint.
struct Notch {
  std::vector<double> origin{1, 0, 0, 0, 0, 1, 0, 0};
  std::vector<double> u = std::vector<double>(8, 0.0), v = std::vector<double>(8, 0.0);
  std::vector<ContactEdge> edges = std::vector<ContactEdge>(2);
  JointParams joint;

  Notch() {
    edges[0].a = 0;
    edges[0].b = 1;
    edges[1].a = 1;
    edges[1].b = 2;
    edges[0].prev = edges[0].next = 1;
    edges[1].prev = edges[1].next = 0;
    edges[0].bent_b = edges[1].bent_a = true;  // a re-entrant corner: no convex one, no straight run
    for (ContactEdge& e : edges) e.touchable = true;
    joint.kn = 1e9;
    joint.ks = 1e8;
    joint.kn_zero = joint.kn_max = joint.kn;
  }
  Contact on_edge(int edge, double x, double y) {
    origin[6] = x;
    origin[7] = y;
    Contact c;
    c.node = 3;
    c.edge = edge;
    c.length = 0.1;
    ContactLoss lost;
    contact_force(c, edges.data(), joint, origin.data(), u.data(), v.data(), 1e-4, lost);
    return c;
  }
};

// A corner pressed past the notch's corner is inside the block by its distance to it, and pushed
// out towards it, on either of the notch's faces: a detection that moves its contact from one
// face to the other changes nothing (by each face's own line it was 4 and 3 mm deep, and a
// contact switched at every detection took energy from each switch).
TEST(ContactForce, PastARe_entrantCornerEitherFaceGivesItsDistanceToTheCorner) {
  Notch notch;
  for (int edge : {0, 1}) {
    const Contact c = notch.on_edge(edge, -0.003, -0.004);
    EXPECT_NEAR(c.closure, 0.005, 1e-15) << "edge " << edge;
    EXPECT_NEAR(c.fx, 1e9 * 0.005 * 0.1 * 0.6, 1e-6) << "edge " << edge;
    EXPECT_NEAR(c.fy, 1e9 * 0.005 * 0.1 * 0.8, 1e-6) << "edge " << edge;
  }
}

// Where it leaves the face's span for the corner's, its depth and force go on smoothly.
TEST(ContactForce, AtTheEdgeOfARe_entrantCornersSpanTheForceIsContinuous) {
  Notch notch;
  const Contact over = notch.on_edge(0, 1e-12, -0.004), past = notch.on_edge(0, -1e-12, -0.004);
  EXPECT_NEAR(past.closure, over.closure, 1e-12);
  EXPECT_NEAR(past.fx, over.fx, 1e-3);
  EXPECT_NEAR(past.fy, over.fy, 1e-3);
}

// A gridpoint at an obtuse corner of its block (node 3; its edges' far ends nodes 4 and 5), pressed
// into the face of the Corner's block under a prestress and a shear stress, its length following
// its facing length (facing_length.hpp; unclipped, the length a detection finds). Moved by
// `place` through `steps` positions, its springs store what the forces on its nodes did (the
// face's block stays put), to the round-off of the midpoint rule.
struct Turning : Corner {
  const double d1[2] = {0.2, 0.0}, d2[2] = {0.1, 0.2};  // its edges: along the face, and rising
  double given_booked = 0.0;  // what its length changed of its given part (ContactLoss::given)
  Turning() {
    origin.resize(12, 0.0);
    u.assign(12, 0.0);
    v.assign(12, 0.0);
    contact.far_a = 4;
    contact.far_b = 5;
    contact.per_facing = 1.0;
    contact.closure0 = 2e-3;  // 3 mm closed at 1 mm in: 3 MPa
    contact.fs = 5e3;
    joint.tan_friction = joint.tan_residual_friction = 1.0;
  }
  // The gridpoint at (x, -1 mm), its edges turned by `angle`.
  void place(double x, double angle) {
    const double cs = std::cos(angle), sn = std::sin(angle), y = -1e-3;
    origin[6] = x;
    origin[7] = y;
    origin[8] = x - (cs * d1[0] - sn * d1[1]);
    origin[9] = y - (sn * d1[0] + cs * d1[1]);
    origin[10] = x + (cs * d2[0] - sn * d2[1]);
    origin[11] = y + (sn * d2[0] + cs * d2[1]);
  }
  // The forces on nodes 3, 4 and 5 at the current positions.
  std::array<double, 6> push() {
    ContactLoss lost;
    NodePush turn;
    contact_force(contact, edges.data(), joint, origin.data(), u.data(), v.data(), 1e-4, lost, &turn);
    given_booked += lost.given;
    return {contact.fx + turn.on[0], contact.fy + turn.on[1], turn.on[6], turn.on[7], turn.on[8], turn.on[9]};
  }
  // The work of those forces from (x0, angle0) to (x1, angle1), and the stored energy's change.
  std::pair<double, double> move(double x0, double angle0, double x1, double angle1, int steps) {
    place(x0, angle0);
    contact.length = 0.25 * (0.2 + 0.1 * 0.1 / std::hypot(0.1, 0.2));  // found here, unclipped
    std::array<double, 6> force = push();
    const double start = stored_in(contact, joint);
    double work = 0.0;
    for (int i = 1; i <= steps; ++i) {
      const std::vector<double> before(origin.begin() + 6, origin.end());
      const std::array<double, 6> was = force;
      place(x0 + (x1 - x0) * i / steps, angle0 + (angle1 - angle0) * i / steps);
      force = push();
      for (size_t k = 0; k < 6; ++k) work += 0.5 * (was[k] + force[k]) * (origin[6 + k] - before[k]);
    }
    return {work, stored_in(contact, joint) - start};
  }
};

// Turned by 0.3 rad where it stands, its facing length, and with it its length, falls to 0.77
// of what it was; the force its edges' far ends take pays for the energy that takes away.
TEST(ContactForce, AGridpointWhoseEdgesTurnStoresTheWorkOfTheTurningForce) {
  Turning c;
  const double length_start = 0.25 * (0.2 + 0.1 * 0.1 / std::hypot(0.1, 0.2));
  const auto [work, change] = c.move(0.5, 0.0, 0.5, 0.3, 3000);
  EXPECT_NEAR(c.contact.length / length_start, 0.770, 0.001);
  EXPECT_LT(change, -0.1 * (change - work));
  EXPECT_NEAR(work, -change, 1e-6 * std::fabs(change));
  EXPECT_NEAR(c.contact.fs / c.contact.length, 5e3 / length_start, 1e-6);  // the shear stress it had
}

// The same gridpoint as a tip pressed past its own length (its tip's length, 80 x the 1 mm
// overlap, above the 0.061 m its edges give): its energy still hangs on its own length, up to
// the overlap where the tip took over, and the push pays for what the turn changes of it.
TEST(ContactForce, ATipPressedPastItsOwnLengthStoresTheWorkOfTheTurningForce) {
  Turning c;
  c.contact.wedge = 80.0;
  c.contact.limit = 0.01;
  const auto [work, change] = c.move(0.5, 0.0, 0.5, 0.3, 3000);
  EXPECT_GT(c.contact.wedge * 1e-3, c.contact.length);  // the tip's length carries it throughout
  EXPECT_LT(change, 0.0);
  EXPECT_NEAR(work, -change, 1e-6 * std::fabs(change));
}

// The same gridpoint as a tip whose tip's length (54 x the 1 mm overlap) its own length (0.061 m)
// falls past as it turns, through the band where either carries: the push still pays for what the
// turn changes of both springs' energy, and turned back it has done no work.
TEST(ContactForce, ATipWhoseOwnLengthFallsPastItsTipsStoresTheWorkOfTheTurningForce) {
  Turning c;
  c.contact.wedge = 54.0;
  c.contact.limit = 0.01;
  const auto [work, change] = c.move(0.5, 0.0, 0.5, 0.3, 3000);
  EXPECT_LT(c.contact.length * (1.0 + kTipBand), c.contact.wedge * 1e-3);  // the tip's length carries it at the end
  EXPECT_LT(change, 0.0);
  EXPECT_NEAR(work, -change, 1e-6 * std::fabs(change));
  const double shear_stress = c.contact.fs / last_carrying_length(c.contact);
  double back = 0.0, start = stored_in(c.contact, c.joint);
  std::array<double, 6> force = c.push();
  for (int i = 1; i <= 3000; ++i) {
    const std::vector<double> before(c.origin.begin() + 6, c.origin.end());
    const std::array<double, 6> was = force;
    c.place(0.5, 0.3 * (1.0 - i / 3000.0));
    force = c.push();
    for (size_t k = 0; k < 6; ++k) back += 0.5 * (was[k] + force[k]) * (c.origin[6 + k] - before[k]);
  }
  EXPECT_NEAR(work + back, 0.0, 1e-6 * std::fabs(change));
  EXPECT_NEAR(back, start - stored_in(c.contact, c.joint), 1e-6 * std::fabs(change));
  EXPECT_NEAR(c.contact.fs / last_carrying_length(c.contact), shear_stress, 1e-6 * shear_stress);
}

// Where its tip's length takes over from its own, a shear stress kept as the length changes
// stores tau^2 / (2 ks) a metre, paid by the push on its edges' far ends while its own length
// carries and by the normal force once its tip's does: the forces on its nodes must go from the
// one to the other without a jump, or a gridpoint rocking across is pushed by a step that one
// sample a cycle integrates wrongly (a tip of Case 3 at 262 m made 5e4 J/m a cycle so).
TEST(ContactForce, WhereATipsLengthTakesOverFromItsOwnTheForcesDoNotJump) {
  Turning c;
  c.contact.wedge = 54.0;
  c.contact.limit = 0.01;
  c.contact.fs = 5e4;  // 0.8 MPa, its shear spring 3.4e3 J/m^2 against the normal's 4.5e3
  c.place(0.5, 0.0);
  c.contact.length = 0.25 * (0.2 + 0.1 * 0.1 / std::hypot(0.1, 0.2));
  std::array<double, 6> force = c.push();
  double jump = 0.0, largest = 0.0;
  for (int i = 1; i <= 30000; ++i) {  // turned by 0.3 rad: its own length falls past its tip's
    c.place(0.5, 0.3 * i / 30000.0);
    const std::array<double, 6> was = force;
    force = c.push();
    for (size_t k = 0; k < 6; ++k) {
      jump = std::max(jump, std::fabs(force[k] - was[k]));
      largest = std::max(largest, std::fabs(force[k]));
    }
  }
  EXPECT_LT(c.contact.length * (1.0 + kTipBand), c.contact.wedge * 1e-3);
  EXPECT_LT(jump, 1e-3 * largest) << "largest force " << largest;
}

// Slid from 0.1 m short of the block's corner (b, at x = 0) to 0.05 m past it: its half-edge
// along the face hangs past the corner, and its facing length shrinks with it (to a fifth at the
// corner), and past the corner its share fades over a span its length sets; the push along the
// face pays for the energy that takes away.
TEST(ContactForce, AGridpointSlidingPastACornerStoresTheWorkOfThePush) {
  Turning c;
  c.contact.fs = 0.0;  // no shear stress: its shear spring does not see a move made by placing
  const auto [work, change] = c.move(0.1, 0.0, -0.05, 0.0, 3000);
  EXPECT_LT(c.contact.length, 0.5 * 0.25 * (0.2 + 0.1 * 0.1 / std::hypot(0.1, 0.2)));
  EXPECT_LT(change, 0.0);
  // (The midpoint rule errs by a step's worth where a half-edge's end crosses the corner.)
  EXPECT_NEAR(work, -change, 1e-3 * std::fabs(change));
}

// Given half of what it stores a metre (a given stress), slid as above: the push pays for the
// rest, and what the length, and the span its share fades over, change of the given part is
// booked with the given stress.
TEST(ContactForce, SlidPastACornerTheGivenPartIsBookedAndTheRestIsWork) {
  Turning c;
  c.contact.fs = 0.0;
  c.place(0.1, 0.0);
  c.contact.length = 0.25 * (0.2 + 0.1 * 0.1 / std::hypot(0.1, 0.2));
  c.push();
  c.contact.given = 0.5 * stored_in(c.contact, c.joint) / c.contact.length;
  c.given_booked = 0.0;
  const auto [work, change] = c.move(0.1, 0.0, -0.05, 0.0, 3000);
  EXPECT_LT(c.given_booked, 0.25 * change);  // about half of it, a loss
  EXPECT_NEAR(work - c.given_booked, -change, 1e-3 * std::fabs(change));
}


// Both blocks turned together as one rigid body, the gridpoint pressed 5 cm into the face: the
// faces do not slide on each other, so its shear displacement and force stay as they were. Measured
// as the gridpoint's velocity against the edge point's under it, the turn would shear it by the
// overlap times the angle (5e-5 m a step here).
TEST(ContactForce, PressedFacesTurnedTogetherDoNotShear) {
  Corner c;
  c.joint.tan_residual_friction = 0.6;
  c.origin[6] = 0.5;
  c.origin[7] = -0.05;
  const double omega = 1e-3, dt = 1.0;  // about (0.5, 0)
  for (int step = 0; step < 5; ++step) {
    for (size_t i = 0; i < 4; ++i) {
      const double x = c.origin[2 * i] + c.u[2 * i], y = c.origin[2 * i + 1] + c.u[2 * i + 1];
      c.v[2 * i] = -omega * y;
      c.v[2 * i + 1] = omega * (x - 0.5);
    }
    ContactLoss lost;
    contact_force(c.contact, c.edges.data(), c.joint, c.origin.data(), c.u.data(), c.v.data(), dt,
                  lost);
    for (size_t k = 0; k < 8; ++k) c.u[k] += c.v[k] * dt;
  }
  EXPECT_NEAR(c.contact.us, 0.0, 1e-15);
  EXPECT_NEAR(c.contact.fs, 0.0, 1e-6);
}

// A gridpoint pressed 5 cm into the face and sheared: its shear force on it and the reaction on
// the edge's ends act 5 cm apart, a couple the edge's ends balance, so the contact's forces on its
// nodes add up to no force and no moment, as two bodies pressed together push each other.
TEST(ContactForce, TheForcesOnItsNodesHaveNoMoment) {
  Corner c;
  c.joint.tan_residual_friction = 0.6;
  c.origin[6] = 0.3;
  c.origin[7] = -0.05;
  c.v[6] = 100.0;  // along the face: 1 cm in the step
  ContactLoss lost;
  NodePush extra;
  contact_force(c.contact, c.edges.data(), c.joint, c.origin.data(), c.u.data(), c.v.data(), 1e-4, lost,
                &extra);
  ASSERT_GT(std::fabs(c.contact.fs), 1e4);
  double p[2 * kContactRoles];
  contact_push(c.contact, extra, p);
  const int nodes[3] = {3, 0, 1};  // by role: the gridpoint, the edge's ends a and b
  double fx = 0.0, fy = 0.0, moment = 0.0;
  for (int role = 0; role < 3; ++role) {
    const size_t n = static_cast<size_t>(nodes[role]);
    fx += p[2 * role];
    fy += p[2 * role + 1];
    moment += c.origin[2 * n] * p[2 * role + 1] - c.origin[2 * n + 1] * p[2 * role];
  }
  EXPECT_NEAR(fx, 0.0, 1e-9 * std::fabs(c.contact.fs));
  EXPECT_NEAR(fy, 0.0, 1e-9 * std::fabs(c.contact.fs));
  EXPECT_NEAR(moment, 0.0, 1e-9 * std::fabs(c.contact.fs));
}

}  // namespace
}  // namespace edem
