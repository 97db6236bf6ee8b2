// Materials of the zones: material{} defines one (its models and their keys come from the zone-law
// registry, constitutive/zone_laws.cpp), assign{} gives it to zones.
#include <string>
#include <utility>
#include <vector>

#include <lua.hpp>

#include <fmt/format.h>

#include "commands.hpp"
#include "constitutive/zone_law.hpp"
#include "context.hpp"

namespace edem {
namespace {

// The keys as given, unset where not: the engine checks them (material_params).
void optional_number(const Args& args, const char* key, double& into) {
  if (args.has(key)) into = args.number(key);
}

// Each law's own keys (constitutive/zone_laws.cpp), each key once, in registry order.
std::vector<const ZoneLawParam*> law_params() {
  std::vector<const ZoneLawParam*> params;
  for (const ZoneLaw* law : zone_laws())
    for (const ZoneLawParam& param : law->params) {
      bool seen = false;
      for (const ZoneLawParam* p : params) seen = seen || p->key == param.key;
      if (!seen) params.push_back(&param);
    }
  return params;
}

int run_material(lua_State*, Context& context, const Args& args) {
  MaterialDef def;
  def.name = args.string("name");
  find_zone_law(args.string("model"), def.model);  // the schema allows only the registry's names
  def.density = args.number("density");
  for (const auto& [key, into] : {std::pair{"young", &def.young}, std::pair{"poisson", &def.poisson},
                                  std::pair{"bulk", &def.bulk}, std::pair{"shear", &def.shear}})
    optional_number(args, key, *into);
  for (const ZoneLawParam* param : law_params()) {
    if (!args.has(param->key)) continue;
    if (param->number)
      def.*param->number = args.number(param->key);
    else
      def.tables.push_back({std::string(param->key), args.get<ZoneTable>(param->key)});
  }
  context.model().add_material(def);
  return 0;
}

// The command's help: the laws and what they are.
std::string material_help() {
  std::string laws;
  for (const ZoneLaw* law : zone_laws())
    laws += fmt::format("{}`{}` ({})", laws.empty() ? "" : "; ", law->name, law->description);
  return "Defines a zone material by its model: " + laws +
         ". Give the elastic constants as young and poisson or as bulk and shear. Defining a name "
         "again replaces that material, in the zones that have it too.";
}

// The schema's key for a law's parameter: "cohesion (mohr only)".
Key law_key(const ZoneLawParam& param, const std::string& help) {
  const bool table = param.number == nullptr;
  return {param.key,
          table ? Type::pairs : Type::number,
          param.unit,
          table ? any_value : Range{param.lo, param.hi, param.lo_open, param.hi_open},
          kOptional,
          help,
          param.absent};
}

// The help lines of the laws' keys and, last, the command's own: kept for the schema's string views.
const std::vector<std::string>& law_key_helps() {
  static const std::vector<std::string> helps = [] {
    std::vector<std::string> all;
    for (const ZoneLawParam* param : law_params()) {
      std::string takers;
      for (const ZoneLaw* law : zone_laws())
        for (const ZoneLawParam& own : law->params)
          if (own.key == param->key) takers += (takers.empty() ? "" : ", ") + std::string(law->name);
      all.push_back(fmt::format("{} ({} only){}", param->help, takers, param->note));
    }
    all.push_back(material_help());
    return all;
  }();
  return helps;
}

std::vector<Key> material_keys() {
  std::vector<Key> keys = {
      {"model", Type::string, "", any_value, R"("elastic")", "the constitutive model", {}, zone_law_names},
      {"density", Type::number, "kg/m^3", ge(0), "0", "mass density"},
      {"young", Type::number, "Pa", gt(0), kOptional, "Young's modulus (with poisson)", "bulk and shear"},
      {"poisson", Type::number, "-", above_below(-1, 0.5), kOptional, "Poisson's ratio (with young)",
       "bulk and shear"},
      {"bulk", Type::number, "Pa", gt(0), kOptional, "bulk modulus (with shear)", "young and poisson"},
      {"shear", Type::number, "Pa", gt(0), kOptional, "shear modulus (with bulk)", "young and poisson"},
  };
  const std::vector<const ZoneLawParam*> params = law_params();
  for (size_t i = 0; i < params.size(); ++i) keys.push_back(law_key(*params[i], law_key_helps()[i]));
  return keys;
}

int run_assign(lua_State*, Context& context, const Args& args) {
  AssignDef def;
  def.material = args.string("material");
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  context.model().assign(def);
  return 0;
}

}  // namespace

const Command& material_command() {
  static const Command command{
      .name = "material",
      .help = law_key_helps().back(),
      .positional =
          {
              {"name", Type::string, "", any_value, kRequired, "the material's name"},
          },
      .keys = material_keys(),
      .run = run_material,
      .usage =
          "material{ \"rock\", model = \"mohr\", density = 2650, young = 7.4e9, poisson = 0.136, "
          "cohesion = 2.55e6, friction = 34, tension = 0.975e6 }\n"
          "material{ \"fill\", density = 1800, bulk = 5e8, shear = 2e8 }",
  };
  return command;
}

const Command& assign_command() {
  static const Command command{
      .name = "assign",
      .help =
          "Gives a material to all zones, or to those of a region: the zones of the blocks "
          "inside a named region, or the zones whose centroid is inside a polygon. Needs "
          "zones: use it after `zone{}`.",
      .keys =
          {
              {"material", Type::string, "", any_value, kRequired, "a material's name"},
              {"region", Type::region, "", any_value, kOptional,
               "only zones inside this region (a name or a polygon)", "all zones"},
          },
      .run = run_assign,
      .usage = "assign{ material = \"rock\" }\nassign{ material = \"fill\", region = \"stage1\" }",
  };
  return command;
}

}  // namespace edem
