// Materials of the zones: material{} defines one, assign{} gives it to zones.
#include <utility>

#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"

namespace edem {
namespace {

const std::vector<std::string>& material_models() {
  static const std::vector<std::string> names = {"elastic", "mohr", "null"};
  return names;
}

MaterialModel model_of(const std::string& name) {
  if (name == "mohr") return MaterialModel::mohr;
  if (name == "null") return MaterialModel::null;
  return MaterialModel::elastic;
}

// The keys as given, unset where not: the engine checks them (material_params).
void optional_number(const Args& args, const char* key, double& into) {
  if (args.has(key)) into = args.number(key);
}

int run_material(lua_State*, Context& context, const Args& args) {
  MaterialDef def;
  def.name = args.string("name");
  def.model = model_of(args.string("model"));
  def.density = args.number("density");
  for (const auto& [key, into] : {std::pair{"young", &def.young}, std::pair{"poisson", &def.poisson},
                                  std::pair{"bulk", &def.bulk}, std::pair{"shear", &def.shear},
                                  std::pair{"cohesion", &def.cohesion}, std::pair{"friction", &def.friction},
                                  std::pair{"dilation", &def.dilation}, std::pair{"tension", &def.tension}})
    optional_number(args, key, *into);
  context.model().add_material(def);
  return 0;
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
      .help =
          "Defines a zone material: elastic, Mohr-Coulomb (`mohr`: elastic until it fails in "
          "shear or tension) or `null` (an empty zone, as excavated). Give the elastic "
          "constants as young and poisson or as bulk and shear. Defining a name again replaces "
          "that material, in the zones that have it too.",
      .positional =
          {
              {"name", Type::string, "", any_value, kRequired, "the material's name"},
          },
      .keys =
          {
              {"model",
               Type::string,
               "",
               any_value,
               R"("elastic")",
               "the constitutive model",
               {},
               material_models},
              {"density", Type::number, "kg/m^3", ge(0), "0", "mass density"},
              {"young", Type::number, "Pa", gt(0), kOptional, "Young's modulus (with poisson)",
               "bulk and shear"},
              {"poisson", Type::number, "-", above_below(-1, 0.5), kOptional,
               "Poisson's ratio (with young)", "bulk and shear"},
              {"bulk", Type::number, "Pa", gt(0), kOptional, "bulk modulus (with shear)",
               "young and poisson"},
              {"shear", Type::number, "Pa", gt(0), kOptional, "shear modulus (with bulk)",
               "young and poisson"},
              {"cohesion", Type::number, "Pa", ge(0), kOptional, "cohesion (mohr only)", "0"},
              {"friction", Type::number, "deg", from_below(0, 90), kOptional,
               "friction angle (mohr only)", "0"},
              {"dilation", Type::number, "deg", ge(0), kOptional,
               "dilation angle, at most friction (mohr only)", "0"},
              {"tension", Type::number, "Pa", ge(0), kOptional,
               "tensile strength (mohr only); capped at cohesion / tan(friction)", "0"},
          },
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
