// Materials of the zones: material{} defines one, assign{} gives it to zones.
#include <fmt/format.h>

#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

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

// Exactly one pair of elastic constants, both of it (a null material needs none).
void elastic_constants(const Args& args, MaterialDef& def) {
  const bool young = args.has("young"), poisson = args.has("poisson");
  const bool bulk = args.has("bulk"), shear = args.has("shear");
  if ((young || poisson) && (bulk || shear))
    fail("give young and poisson, or bulk and shear, not both pairs");
  if (young != poisson)
    fail("{} needs {} too (or give bulk and shear)", young ? "young" : "poisson",
         young ? "poisson" : "young");
  if (bulk != shear)
    fail("{} needs {} too (or give young and poisson)", bulk ? "bulk" : "shear",
         bulk ? "shear" : "bulk");
  if (!young && !bulk) {
    if (def.model == MaterialModel::null) return;
    fail("missing elastic constants: give young and poisson, or bulk and shear");
  }
  if (young) {
    def.young = args.number("young");
    def.poisson = args.number("poisson");
  } else {
    def.bulk = args.number("bulk");
    def.shear = args.number("shear");
  }
}

// Strength belongs to the Mohr-Coulomb model: given to another, it would be silently unused.
void strength(const Args& args, const std::string& model, MaterialDef& def) {
  std::vector<std::string> given;
  for (const char* key : {"cohesion", "friction", "dilation", "tension"})
    if (args.has(key)) given.emplace_back(key);
  if (def.model != MaterialModel::mohr) {
    if (!given.empty())
      fail("{} need{} model = \"mohr\" (this material's model is \"{}\")", fmt::join(given, ", "),
           given.size() == 1 ? "s" : "", model);
    return;
  }
  if (args.has("cohesion")) def.cohesion = args.number("cohesion");
  if (args.has("friction")) def.friction = args.number("friction");
  if (args.has("dilation")) def.dilation = args.number("dilation");
  if (args.has("tension")) def.tension = args.number("tension");
  if (def.dilation > def.friction)
    fail("dilation must be <= friction ({}), got {}", def.friction, def.dilation);
}

int run_material(lua_State*, Context& context, const Args& args) {
  MaterialDef def;
  def.name = args.string("name");
  if (def.name.empty()) fail("name must not be empty");
  const std::string& model = args.string("model");
  def.model = model_of(model);
  def.density = args.number("density");
  elastic_constants(args, def);
  strength(args, model, def);
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
