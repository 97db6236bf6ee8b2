// The zone-law registry: ids are positions, names are unique, and the flags the engine asks
// (is_void, has_strength, an update for every law but the inlined elastic one) say what the
// models are.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "constitutive/zone_law.hpp"

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
