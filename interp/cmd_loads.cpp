// Loads and initial state: gravity{}, insitu{}, boundary{}.
#include <fmt/format.h>

#include <cmath>
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

// The keys of `names` that the call gave, in the schema's order.
std::vector<std::string> given(const Args& args, std::initializer_list<const char*> names) {
  std::vector<std::string> keys;
  for (const char* name : names)
    if (args.has(name)) keys.emplace_back(name);
  return keys;
}

int run_gravity(lua_State*, Context& context, const Args& args) {
  const bool items = args.has("gx") || args.has("gy");
  const bool keys = args.has("x") || args.has("y");
  if (items && keys) fail("give gravity{{ gx, gy }} or gravity{{ x = , y = }}, not both");
  Vec2 g;
  if (items) {
    if (!args.has("gy")) fail("missing item #2 (gy): give both components, gravity{{ 0, -9.81 }}");
    g = {args.number("gx"), args.number("gy")};
  } else if (keys) {
    g = {args.has("x") ? args.number("x") : 0.0, args.has("y") ? args.number("y") : 0.0};
  } else {
    fail("no acceleration given: gravity{{ 0, -9.81 }} or gravity{{ y = -9.81 }}");
  }
  context.model().set_gravity(g);
  return 0;
}

int run_insitu(lua_State*, Context& context, const Args& args) {
  InsituDef def;
  def.from_surface = args.has("surface");
  const auto field = given(args, {"sxx", "syy", "sxy", "szz", "ygrad"});
  const auto surface = given(args, {"density", "k0", "surcharge"});
  if (def.from_surface && !field.empty())
    fail("{} belong{} to the stress form; with surface = give density, k0 and surcharge",
         fmt::join(field, ", "), field.size() == 1 ? "s" : "");
  if (!def.from_surface && !surface.empty())
    fail("{} need{} surface = (the y of the ground surface), or give sxx, syy, ... instead",
         fmt::join(surface, ", "), surface.size() == 1 ? "s" : "");
  if (def.from_surface) {
    if (!args.has("density")) fail("the surface form needs density, the overburden's density");
    def.surface = args.number("surface");
    def.density = args.number("density");
    if (args.has("k0")) def.k0 = args.number("k0");
    if (args.has("surcharge")) def.surcharge = args.number("surcharge");
  } else {
    if (args.has("sxx")) def.sxx = args.number("sxx");
    if (args.has("syy")) def.syy = args.number("syy");
    if (args.has("sxy")) def.sxy = args.number("sxy");
    if (args.has("szz")) def.szz = args.number("szz");
    if (args.has("ygrad")) {
      const auto& ygrad = args.get<std::vector<double>>("ygrad");
      if (ygrad.size() != 3 && ygrad.size() != 4)
        fail("ygrad must be {{dsxx, dsyy, dsxy}} or {{dsxx, dsyy, dsxy, dszz}}, got {} number{}",
             ygrad.size(), ygrad.size() == 1 ? "" : "s");
      std::copy(ygrad.begin(), ygrad.end(), def.ygrad.begin());
      // Without szz, szz is sxx, gradient included; a dszz of its own starts from sxx.
      if (ygrad.size() == 4 && std::isnan(def.szz)) def.szz = def.sxx;
    }
  }
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  context.model().insitu(def);
  return 0;
}

const std::vector<std::string>& sides() {
  static const std::vector<std::string> names = {"left", "right", "top", "bottom"};
  return names;
}

const std::vector<std::string>& components() {
  static const std::vector<std::string> names = {"x", "y", "xy"};
  return names;
}

const std::vector<std::string>& stress_names() {
  static const std::vector<std::string> names = {"insitu"};
  return names;
}

int run_boundary(lua_State*, Context& context, const Args& args) {
  BoundaryDef def;
  const bool side = args.has("side"), polygon = args.has("polygon");
  if (side && polygon) fail("give side or polygon, not both");
  if (!side && !polygon)
    fail("which gridpoints? give side = \"left\", \"right\", \"top\" or \"bottom\", or a polygon");
  if (side) def.side = args.string("side");
  if (polygon) def.polygon = args.get<Polygon>("polygon");
  if (const auto* name = args.find<std::string>("stress")) {
    def.stress_insitu = *name == "insitu";
  } else if (const auto* stress = args.find<std::vector<double>>("stress")) {
    if (stress->size() != 3)
      fail("stress must be {{sxx, syy, sxy}} or \"insitu\", got {} number{}", stress->size(),
           stress->size() == 1 ? "" : "s");
    def.stress = std::array<double, 3>{(*stress)[0], (*stress)[1], (*stress)[2]};
  }
  if (args.has("fix")) def.fix = args.string("fix");
  if (args.has("free")) def.free = args.string("free");
  if (args.has("xvel")) def.xvel = args.number("xvel");
  if (args.has("yvel")) def.yvel = args.number("yvel");
  if (!args.has("stress") && def.fix.empty() && def.free.empty() && !args.has("xvel") &&
      !args.has("yvel"))
    fail("nothing to apply: give stress, fix, free, xvel or yvel");
  for (const char axis : {'x', 'y'}) {
    const bool freed = def.free.find(axis) != std::string::npos;
    if (freed && def.fix.find(axis) != std::string::npos) fail("fix and free both name {}", axis);
    if (freed && args.has(fmt::format("{}vel", axis)))
      fail("free = \"{}\" releases the velocity that {}vel holds: give one of them", def.free,
           axis);
  }
  context.model().boundary(def);
  return 0;
}

}  // namespace

const Command& gravity_command() {
  static const Command command{
      .name = "gravity",
      .help =
          "Sets the acceleration of gravity, which loads every zone with its weight (and "
          "sets g for `insitu{ surface = ... }`).",
      .positional =
          {
              {"gx", Type::number, "m/s^2", any_value, kOptional, "x component", "or x ="},
              {"gy", Type::number, "m/s^2", any_value, kOptional, "y component", "or y ="},
          },
      .keys =
          {
              {"x", Type::number, "m/s^2", any_value, kOptional, "x component, by name", "0"},
              {"y", Type::number, "m/s^2", any_value, kOptional, "y component, by name", "0"},
          },
      .run = run_gravity,
      .usage = "gravity{ 0, -9.81 }\ngravity{ y = -9.81 }",
  };
  return command;
}

const Command& insitu_command() {
  static const Command command{
      .name = "insitu",
      .help =
          "Sets the initial stresses of the zones, in one of two forms. The stress form gives "
          "s(y) = s + ygrad * y for each component (compression negative). The surface form "
          "(selected by `surface`) gives the lithostatic state sv = -(surcharge + density * g "
          "* (surface - y)), sh = szz = k0 * sv, with g the magnitude of the `gravity{}` given "
          "before (9.81 if none). The keys of the two forms do not mix. Zones of a null "
          "material are left at zero.",
      .keys =
          {
              {"sxx", Type::number, "Pa", any_value, kOptional, "horizontal stress at y = 0", "0"},
              {"syy", Type::number, "Pa", any_value, kOptional, "vertical stress at y = 0", "0"},
              {"sxy", Type::number, "Pa", any_value, kOptional, "shear stress at y = 0", "0"},
              {"szz", Type::number, "Pa", any_value, kOptional, "out-of-plane stress at y = 0",
               "sxx"},
              {"ygrad", Type::numbers, "Pa/m", any_value, kOptional,
               "{dsxx, dsyy, dsxy} or {dsxx, dsyy, dsxy, dszz}: increase of each component "
               "per metre of y (szz follows sxx unless szz or dszz is given)",
               "0"},
              {"surface", Type::number, "m", any_value, kOptional,
               "y of the ground surface: selects the surface form", "stress form"},
              {"density", Type::number, "kg/m^3", ge(0), kOptional,
               "density of the overburden (surface form, required)"},
              {"k0", Type::number, "-", ge(0), kOptional,
               "horizontal over vertical stress (surface form)", "1"},
              {"surcharge", Type::number, "Pa", ge(0), kOptional,
               "load on the surface, positive (surface form)", "0"},
              {"region", Type::region, "", any_value, kOptional,
               "only zones inside this region (a name or a polygon)", "all zones"},
          },
      .run = run_insitu,
      .usage =
          "insitu{ surface = 182, density = 2650, k0 = 0.6 }\n"
          "insitu{ sxx = -10e6, syy = -20e6 }\n"
          "insitu{ sxx = -1.2e6, syy = -2e6, ygrad = {15.6e3, 26e3, 0} }",
  };
  return command;
}

const Command& boundary_command() {
  static const Command command{
      .name = "boundary",
      .help =
          "Applies conditions to the gridpoints of the model's outer boundary on one side of "
          "its bounding box, or to the boundary gridpoints inside a polygon: a traction from "
          "a stress (or from the in-situ stresses), fixed velocity components, or their "
          "release.",
      .keys =
          {
              {"side", Type::string, "", any_value, kOptional, "which side of the model",
               "or polygon", sides},
              {"polygon", Type::polygon, "m", any_value, kOptional,
               "the boundary gridpoints inside it", "or side"},
              {"stress", Type::numbers_or_name, "Pa", any_value, kOptional,
               "{sxx, syy, sxy} applied as a traction, or \"insitu\": the in-situ stresses",
               "no traction", stress_names},
              {"fix", Type::string, "", any_value, kOptional,
               "hold these velocity components (at zero, or at xvel / yvel)", "", components},
              {"free", Type::string, "", any_value, kOptional,
               "release these components (and their applied velocity)", "", components},
              {"xvel", Type::number, "m/s", any_value, kOptional, "held x velocity (fixes x)"},
              {"yvel", Type::number, "m/s", any_value, kOptional, "held y velocity (fixes y)"},
          },
      .run = run_boundary,
      .usage =
          "boundary{ side = \"bottom\", fix = \"y\" }\n"
          "boundary{ side = \"top\", stress = \"insitu\" }\n"
          "boundary{ side = \"right\", stress = {-10e6, 0, 0} }",
  };
  return command;
}

}  // namespace edem
