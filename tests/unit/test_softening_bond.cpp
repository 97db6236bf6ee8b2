// A softening bond (joint_law.hpp, JointParams::softens) on one contact, driven by hand: the work
// it takes to break it in opening is its fracture energy times its length, and in slip its shear
// fracture energy times its length; it unloads towards zero opening; and without fracture
// energies a bond drops at once, as it always did.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/contact_force.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

constexpr double kLength = 0.1;                    // the contact's length [m]
constexpr double kKn = 1e9, kKs = 1e8;             // [Pa/m]
constexpr double kTension = 1e5, kCohesion = 2e5;  // [Pa]

JointMaterialDef bonded(double fracture_energy, double shear_fracture_energy) {
  JointMaterialDef def;
  def.name = "bond";
  def.kn = kKn;
  def.ks = kKs;
  def.friction = 30.0;
  def.tension = kTension;
  def.cohesion = kCohesion;
  def.fracture_energy = fracture_energy;
  def.shear_fracture_energy = shear_fracture_energy;
  return def;
}

// Gridpoint 2 on the face of the block below y = 0, whose top edge runs from (1, 0) to (0, 0).
struct Face {
  std::vector<double> origin{1, 0, 0, 0, 0.5, 0};
  std::vector<double> u = std::vector<double>(6, 0.0), v = std::vector<double>(6, 0.0);
  std::vector<ContactEdge> edges = std::vector<ContactEdge>(1);
  JointParams joint;
  Contact contact;
  ContactLoss lost;  // what it dissipated, all steps

  explicit Face(const JointMaterialDef& def) : joint(joint_params(def)) {
    edges[0].a = 0;
    edges[0].b = 1;
    edges[0].prev = edges[0].next = 0;
    contact.node = 2;
    contact.edge = 0;
    contact.length = kLength;
    contact.limit = 0.05;
    contact.intact = true;
  }
  // The gridpoint moved by (dx, dy) over one step of 1 s; returns the work done on it [J/m].
  double move(double dx, double dy) {
    const double fx0 = contact.fx, fy0 = contact.fy;
    v[4] = dx, v[5] = dy;
    u[4] += dx, u[5] += dy;
    contact_force(contact, edges.data(), joint, origin.data(), u.data(), v.data(), 1.0, lost);
    return -0.5 * ((fx0 + contact.fx) * dx + (fy0 + contact.fy) * dy);  // against its force
  }
};

TEST(SofteningBond, OpeningTakesTheFractureEnergyTimesTheLength) {
  const double energy = 50.0;  // opening at loss 2 G / T = 1 mm, the peak at 0.1 mm
  Face f(bonded(energy, 0.0));
  double work = 0.0, peak = 0.0;
  for (int i = 0; i < 12000; ++i) {
    work += f.move(0.0, 1e-7);
    peak = std::max(peak, -f.contact.fy);
  }
  EXPECT_NEAR(peak, kTension * kLength, 1e-6 * kTension * kLength);
  EXPECT_NEAR(work, energy * kLength, 1e-3 * energy * kLength);
  EXPECT_FALSE(f.contact.intact);
  EXPECT_EQ(f.contact.fy, 0.0);
  EXPECT_EQ(f.contact.state, ContactState::open);
}

// The work done on the contact is what it stores (its energy as it stands) plus what it
// dissipated, at every step of opening to half its strength, closing half-way and opening again.
TEST(SofteningBond, TheWorkDoneOnItIsWhatItStoresPlusWhatItDissipated) {
  Face f(bonded(50.0, 0.0));
  double work = 0.0;
  const auto balance = [&] {
    const ContactEnergy e = contact_energy(f.contact, f.joint);
    return work - (e.normal + e.shear + f.lost.slip + f.lost.bond);
  };
  for (int i = 0; i < 5500; ++i) work += f.move(0.0, 1e-7);
  EXPECT_NEAR(balance(), 0.0, 1e-4 * 50.0 * kLength);
  EXPECT_GT(f.lost.bond, 0.0);
  for (int i = 0; i < 2750; ++i) work += f.move(0.0, -1e-7);
  EXPECT_NEAR(balance(), 0.0, 1e-4 * 50.0 * kLength);
  for (int i = 0; i < 8000; ++i) work += f.move(0.0, 1e-7);  // on past the loss: all dissipated
  EXPECT_NEAR(balance(), 0.0, 1e-4 * 50.0 * kLength);
  EXPECT_NEAR(f.lost.bond, 50.0 * kLength, 1e-3 * 50.0 * kLength);
}

TEST(SofteningBond, HalfWayItUnloadsTowardsZeroOpeningAndReloadsAlongTheSameLine) {
  Face f(bonded(50.0, 0.0));
  for (int i = 0; i < 5500; ++i) f.move(0.0, 1e-7);  // 0.55 mm: half the strength left
  const double at_largest = f.contact.sn;
  EXPECT_NEAR(at_largest, -0.5 * kTension, 1e-6 * kTension);
  for (int i = 0; i < 2750; ++i) f.move(0.0, -1e-7);  // back to half that opening
  EXPECT_NEAR(f.contact.sn, 0.5 * at_largest, 1e-6 * kTension);
  EXPECT_TRUE(f.contact.intact);
  for (int i = 0; i < 2750; ++i) f.move(0.0, 1e-7);
  EXPECT_NEAR(f.contact.sn, at_largest, 1e-6 * kTension);
}

TEST(SofteningBond, SlipTakesTheShearFractureEnergyTimesTheLength) {
  // Plastic slip at loss 2 G / c = 5 mm, the peak at 2 mm: above c^2 / (2 ks) = 200 J/m^2, so
  // that the force falls more slowly than the contact unloads and the slip can follow it.
  const double energy = 500.0;
  Face f(bonded(0.0, energy));
  double work = 0.0;
  for (int i = 0; i < 8000; ++i) work += f.move(-1e-6, 0.0);
  EXPECT_NEAR(work, energy * kLength, 1e-3 * energy * kLength);
  EXPECT_FALSE(f.contact.intact);
  EXPECT_NEAR(f.contact.fs, 0.0, 1e-9);  // no normal stress, no residual cohesion
}

// Pressed and slipping, the shear spring's work less what it stores is the slip's dissipation.
TEST(SofteningBond, SlippingTheWorkDoneOnItIsWhatItStoresPlusWhatItDissipated) {
  Face f(bonded(0.0, 500.0));
  double work = f.move(0.0, -1e-4);  // pressed: 0.1 MPa
  for (int i = 0; i < 9000; ++i) work += f.move(-1e-6, 0.0);
  const ContactEnergy e = contact_energy(f.contact, f.joint);
  EXPECT_NEAR(work, e.normal + e.shear + f.lost.slip + f.lost.bond, 1e-4 * std::fabs(work));
  EXPECT_GT(f.lost.slip, 0.0);
}

TEST(SofteningBond, PressedItsFrictionHoldsAtThePeakWhileTheCohesionGoesThenTheResidual) {
  JointMaterialDef def = bonded(0.0, 500.0);
  def.residual_friction = 20.0;
  Face f(def);
  f.move(0.0, -1e-4);  // pressed: 0.1 MPa
  const double sn = kKn * 1e-4, peak_friction = std::tan(30.0 * M_PI / 180.0);
  double peak = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const double slip_before = f.contact.slip;  // the step's limit: explicit, from its start
    f.move(-1e-6, 0.0);
    peak = std::max(peak, std::fabs(f.contact.fs));
    if (i == 2999) {  // 3 mm, past the peak at 2.6 mm: its cohesion partly gone, its friction not
      const double left = 1.0 - slip_before / 5e-3;
      EXPECT_GT(f.contact.slip, 0.0);
      EXPECT_TRUE(f.contact.intact);
      EXPECT_NEAR(std::fabs(f.contact.fs), (left * kCohesion + peak_friction * sn) * kLength,
                  1e-9 * kCohesion);
    }
  }
  EXPECT_NEAR(peak, (kCohesion + peak_friction * sn) * kLength, 1e-6 * kCohesion * kLength);
  for (int i = 0; i < 6000; ++i) f.move(-1e-6, 0.0);
  EXPECT_FALSE(f.contact.intact);
  EXPECT_NEAR(std::fabs(f.contact.fs), std::tan(20.0 * M_PI / 180.0) * sn * kLength,
              1e-9 * sn * kLength);
}

TEST(SofteningBond, WithNoTensileStrengthARoundOffOpeningNeitherBreaksItNorGivesNaN) {
  JointMaterialDef def = bonded(0.0, 500.0);
  def.tension = 0.0;
  Face f(def);
  f.move(0.0, 1e-13);  // within round-off of closed (1e-9 of its reach)
  EXPECT_TRUE(f.contact.intact);
  EXPECT_EQ(f.contact.sn, 0.0);
  f.move(0.0, 1e-6);  // open: no tensile strength, gone
  EXPECT_FALSE(f.contact.intact);
  EXPECT_EQ(f.contact.fy, 0.0);
}

TEST(SofteningBond, WithoutFractureEnergiesTheBondDropsAtOnce) {
  Face f(bonded(0.0, 0.0));
  for (int i = 0; i < 1001; ++i) f.move(0.0, 1e-7);
  EXPECT_FALSE(f.contact.intact);
  EXPECT_EQ(f.contact.fy, 0.0);
}

TEST(SofteningBond, RejectsAFractureEnergyBelowTheElasticEnergyAtThePeak) {
  EXPECT_THROW(joint_params(bonded(kTension * kTension / (2.0 * kKn), 0.0)), Error);
  JointMaterialDef no_tension = bonded(10.0, 0.0);
  no_tension.tension = 0.0;
  EXPECT_THROW(joint_params(no_tension), Error);
  JointMaterialDef no_cohesion_left = bonded(0.0, 10.0);
  no_cohesion_left.residual_cohesion = kCohesion;
  EXPECT_THROW(joint_params(no_cohesion_left), Error);
}

}  // namespace
}  // namespace edem
