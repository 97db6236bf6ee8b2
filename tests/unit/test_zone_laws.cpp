// The zone-law registry: ids are positions, names are unique, and the flags the engine asks
// (is_void, has_strength, an update for every law but the inlined elastic one) say what the
// models are. And the strain-softening law's kernel and table checks.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "constitutive/material.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/zone_law.hpp"
#include "error_of.hpp"

namespace edem {
namespace {

TEST(ZoneLaws, TheEnumeratorsNameTheFirstLaws) {
  EXPECT_EQ(zone_law(MaterialModel::elastic).name, "elastic");
  EXPECT_EQ(zone_law(MaterialModel::mohr).name, "mohr");
  EXPECT_EQ(zone_law(MaterialModel::null).name, "null");
}

TEST(ZoneLaws, NamesAreUniqueAndFindTheirIds) {
  std::set<std::string> names;
  for (size_t i = 0; i < zone_laws().size(); ++i) {
    const ZoneLaw& law = *zone_laws()[i];
    EXPECT_TRUE(names.insert(std::string(law.name)).second) << law.name;
    MaterialModel id{};
    ASSERT_TRUE(find_zone_law(law.name, id));
    EXPECT_EQ(static_cast<size_t>(id), i);
  }
  MaterialModel id{};
  EXPECT_FALSE(find_zone_law("mohr_coulomb", id));
  EXPECT_EQ(zone_law_names().size(), zone_laws().size());
}

TEST(ZoneLaws, FlagsSayWhatTheEngineAsks) {
  EXPECT_EQ(zone_law(MaterialModel::elastic).update, nullptr);  // the cycle's inlined path
  EXPECT_TRUE(zone_law(MaterialModel::null).is_void);
  EXPECT_TRUE(zone_law(MaterialModel::mohr).has_strength);
  EXPECT_FALSE(zone_law(MaterialModel::elastic).has_strength);
  for (const ZoneLaw* law : zone_laws()) {
    if (!law->is_void && law->name != "elastic") {
      EXPECT_NE(law->update, nullptr) << law->name;
    }
  }
}

TEST(ZoneLaws, KeysSayWhichLawsTakeThem) {
  EXPECT_EQ(laws_taking("cohesion").substr(0, 6), "\"mohr\"");
  EXPECT_EQ(laws_taking("young"), "");  // the elastic constants are every law's
}

}  // namespace
}  // namespace edem

namespace edem {
namespace {

MaterialDef softening_rock() {
  MaterialDef def;
  def.name = "rock";
  MaterialModel id{};
  EXPECT_TRUE(find_zone_law("ss", id));
  def.model = id;
  def.young = 1e9;
  def.poisson = 0.25;
  def.cohesion = 1e6;
  def.friction = 30;
  def.tables.push_back({"cohesion_table", {{0.0, 1e6}, {0.01, 0.2e6}}});
  return def;
}

MaterialDef mohr_rock() {
  MaterialDef def;
  def.name = "rock";
  def.model = MaterialModel::mohr;
  def.young = 1e9;
  def.poisson = 0.25;
  def.cohesion = 1e6;
  def.friction = 30;
  def.dilation = 10;
  def.tension = 0.5e6;
  return def;
}

// The work a law reports for a yielding step is the general definition's (plastic_work): the
// mid-step stress on C^-1 (trial - returned), for steps that fail in shear and in tension, with
// the out-of-plane stress least, middle and most compressive, and rotating principal axes.
TEST(ZoneLaws, PlasticWorkIsTheMidStepStressOnThePlasticStrain) {
  for (const MaterialDef& def : {mohr_rock(), softening_rock()}) {
    const MaterialParams p = material_params(def);
    const ZoneLaw& law = zone_law(p.model);
    int shear = 0, tension = 0, positions[3] = {0, 0, 0};
    for (double szz : {-8e6, -2e6, 0.4e6})
      for (double angle = 0.0; angle < 3.2; angle += 0.4)
        for (double size : {1e-4, 3e-3}) {
          const Stress before{-3e6, -1e6, 0.3e6, szz};
          const double dxx = size * std::cos(angle), dyy = -size * std::sin(angle), dxy = 0.7 * size;
          Stress trial = before;
          elastic_update(p, trial, dxx, dyy, dxy);
          Stress s = before;
          double history = 0.0, work = -1.0;
          const std::uint8_t now = law.update(p, s, dxx, dyy, dxy, 0.0, history, &work);
          if (now == 0) {
            EXPECT_EQ(work, -1.0);  // left alone
            continue;
          }
          shear += (now & kShearNow) != 0, tension += (now & kTensionNow) != 0;
          const Principal in_plane = in_plane_principal(trial);
          positions[trial.zz <= in_plane.s1 ? 0 : trial.zz <= in_plane.s3 ? 1 : 2] += 1;
          const double expected = plastic_work(p, before, trial, s);
          EXPECT_NEAR(work, expected, 1e-9 * std::abs(expected) + 1e-12) << def.name << " szz " << szz << " angle " << angle;
        }
    EXPECT_GT(shear, 0) << def.name;
    EXPECT_GT(tension, 0) << def.name;
    for (int count : positions) EXPECT_GT(count, 0) << def.name;
  }
}

// One zone pressed in yy past the peak at a held sxx: each shear step adds |lambda| to e_ps
// (psi = 0), and the next step's strength is the table's at the new e_ps.
TEST(StrainSoftening, ShearStepsAdvanceEpsAndSoften) {
  const MaterialParams p = material_params(softening_rock());
  const ZoneLaw& law = zone_law(p.model);
  ASSERT_NE(law.update, nullptr);
  EXPECT_EQ(law.history, "e_ps");
  EXPECT_TRUE(law.has_strength);
  EXPECT_TRUE(law.unsymmetric(p));  // dilation 0, friction 30
  Stress s{-1e6, -1e6, 0.0, -1e6};
  double eps = 0.0, first_plastic = 0.0;
  int steps = 0;
  while (eps < 0.011 && steps < 100000) {
    s.xx = -1e6;  // the confining stress held
    const double before = eps;
    // Axial strain, and the lateral strain that keeps sxx near -1e6 elastically.
    const double de = -1e-6, dx = -(p.e2 / p.e1) * de;
    if (law.update(p, s, dx, de, 0.0, 0.0, eps, nullptr) & kShearNow && first_plastic == 0.0) first_plastic = eps - before;
    ++steps;
  }
  EXPECT_GT(first_plastic, 0.0);
  // Past e_r the step's strength is the residual one: the returned in-plane pair (syy most
  // compressive, sxx least) is on that surface.
  const double nphi = 3.0;
  EXPECT_NEAR(s.yy - nphi * s.xx + 2.0 * 0.2e6 * std::sqrt(nphi), 0.0, 1e-3);
}

TEST(StrainSoftening, TablesAreChecked) {
  MaterialDef def = softening_rock();
  def.tables[0].points = {{0.0, 1e6}, {0.02, 0.5e6}, {0.01, 0.2e6}};
  EXPECT_EQ(error_of([&] { material_params(def); }),
            "cohesion_table point 3: e_ps must increase, got 0.01 after 0.02");
  def.tables[0].points = {{0.001, 1e6}};
  EXPECT_EQ(error_of([&] { material_params(def); }), "cohesion_table must start at e_ps = 0, got 0.001");
  def.tables[0].points = {{0.0, 1e6}, {0.01, -1.0}};
  EXPECT_EQ(error_of([&] { material_params(def); }), "cohesion_table point 2: cohesion must be >= 0, got -1");
  def = softening_rock();
  def.tables.push_back({"dilation_table", {{0.0, 0.0}, {0.01, 40.0}}});
  EXPECT_EQ(error_of([&] { material_params(def); }),
            "dilation must be <= friction at every e_ps: at e_ps = 0.01, 40 > 30");
}

}  // namespace
}  // namespace edem
