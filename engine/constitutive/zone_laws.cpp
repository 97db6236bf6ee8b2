// The registry of zone laws: one line per law, in id order (an id is saved in checkpoints, so a
// new law goes at the end). Each law's entry lives in its own file.
#include <string>

#include "constitutive/zone_law.hpp"

namespace edem {

extern const ZoneLaw elastic_law;       // constitutive/elastic.cpp
extern const ZoneLaw mohr_coulomb_law;  // constitutive/mohr_coulomb.cpp
extern const ZoneLaw null_law;          // constitutive/null_law.cpp
extern const ZoneLaw strain_softening_law;  // constitutive/strain_softening.cpp

namespace {

constexpr const ZoneLaw* kLaws[] = {
    &elastic_law,       // MaterialModel::elastic
    &mohr_coulomb_law,  // MaterialModel::mohr
    &null_law,          // MaterialModel::null
    &strain_softening_law,
};

}  // namespace

const ZoneTable& law_table(const MaterialDef& def, std::string_view key) {
  static const ZoneTable none;
  for (const ZoneLawTable& table : def.tables)
    if (table.key == key) return table.points;
  return none;
}

std::span<const ZoneLaw* const> zone_laws() { return kLaws; }

const ZoneLaw& zone_law(MaterialModel id) { return *kLaws[static_cast<size_t>(id)]; }

bool find_zone_law(std::string_view name, MaterialModel& id) {
  for (size_t i = 0; i < std::size(kLaws); ++i)
    if (kLaws[i]->name == name) {
      id = static_cast<MaterialModel>(i);
      return true;
    }
  return false;
}

const std::vector<std::string>& zone_law_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const ZoneLaw* law : kLaws) all.emplace_back(law->name);
    return all;
  }();
  return names;
}

std::string laws_taking(std::string_view key) {
  std::string names;
  for (const ZoneLaw* law : kLaws)
    for (const ZoneLawParam& param : law->params)
      if (param.key == key) names += (names.empty() ? "\"" : " or \"") + std::string(law->name) + "\"";
  return names;
}

}  // namespace edem
