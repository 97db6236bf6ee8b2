// The registry of zone laws: one line per law, in id order (an id is saved in checkpoints, so a
// new law goes at the end). Each law's entry lives in its own file.
#include <string>

#include "constitutive/zone_law.hpp"

namespace edem {

extern const ZoneLaw elastic_law;       // constitutive/elastic.cpp
extern const ZoneLaw mohr_coulomb_law;  // constitutive/mohr_coulomb.cpp
extern const ZoneLaw null_law;          // constitutive/null_law.cpp
extern const ZoneLaw strain_softening_law;  // constitutive/strain_softening.cpp

extern const ZoneLaw* const kZoneLaws[] = {
    &elastic_law,       // MaterialModel::elastic
    &mohr_coulomb_law,  // MaterialModel::mohr
    &null_law,          // MaterialModel::null
    &strain_softening_law,
};

const ZoneTable& law_table(const MaterialDef& def, std::string_view key) {
  static const ZoneTable none;
  for (const ZoneLawTable& table : def.tables)
    if (table.key == key) return table.points;
  return none;
}

// The table's length, here where its definition is seen.
constexpr size_t kLawCount = sizeof(kZoneLaws) / sizeof(kZoneLaws[0]);

std::span<const ZoneLaw* const> zone_laws() { return {kZoneLaws, kLawCount}; }

bool find_zone_law(std::string_view name, MaterialModel& id) {
  for (size_t i = 0; i < kLawCount; ++i)
    if (kZoneLaws[i]->name == name) {
      id = static_cast<MaterialModel>(i);
      return true;
    }
  return false;
}

const std::vector<std::string>& zone_law_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const ZoneLaw* law : kZoneLaws) all.emplace_back(law->name);
    return all;
  }();
  return names;
}

std::string laws_taking(std::string_view key) {
  std::string names;
  for (const ZoneLaw* law : kZoneLaws)
    for (const ZoneLawParam& param : law->params)
      if (param.key == key) names += (names.empty() ? "\"" : " or \"") + std::string(law->name) + "\"";
  return names;
}

}  // namespace edem
