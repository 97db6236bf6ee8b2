// profile{}: a quantity sampled along a line (the seed's Figure 12: settlement above the roof),
// returned to the script and, with file =, drawn as a line chart against the distance.
#include <fmt/format.h>

#include <cmath>
#include <lua.hpp>
#include <vector>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "io/chart.hpp"
#include "lua_util.hpp"
#include "schema.hpp"

namespace edem {
namespace {

const std::vector<std::string>& profile_quantities() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;  // the point quantities of history{} but the joints'
    for (const std::string& q : Model::history_point_quantities())
      if (!q.starts_with("joint_")) all.push_back(q);
    return all;
  }();
  return names;
}

void push_list(lua_State* L, const char* key, const std::vector<double>& values) {
  lua_createtable(L, static_cast<int>(values.size()), 0);
  for (size_t i = 0; i < values.size(); ++i) {
    lua_pushnumber(L, values[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, key);
}

int run_profile(lua_State* L, Context& context, const Args& args) {
  const Vec2 from = args.point("from"), to = args.point("to");
  const std::string& quantity = args.string("quantity");
  const auto points = static_cast<int>(args.integer("points"));
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  if (!(length > 0.0)) fail("from and to are the same point ({}, {}): a profile needs a line", from.x, from.y);
  const Model& model = context.model();
  std::vector<double> distance, xs, ys, values;
  for (int i = 0; i < points; ++i) {
    const double t = static_cast<double>(i) / (points - 1);
    const Vec2 p{from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)};
    // As history{} measures it: the nearest gridpoint (of rock in place), or the zone containing it.
    values.push_back(model.history_sampler(quantity, p)());
    distance.push_back(t * length);
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  if (args.has("file")) {
    ChartDef def;
    def.file = context.output_path(args.string("file"));
    if (args.has("title")) def.title = args.string("title");
    def.x_label = fmt::format("distance from ({}, {}) [m]", show_number(from.x), show_number(from.y));
    def.y_label = fmt::format("{} [{}]", quantity, Model::history_unit(quantity));
    def.series = {{fmt::format("{} along ({}, {}) to ({}, {})", quantity, show_number(from.x), show_number(from.y),
                               show_number(to.x), show_number(to.y)),
                   distance, values}};
    chart(def);
  }
  lua_createtable(L, 0, 4);
  push_list(L, "distance", distance);
  push_list(L, "x", xs);
  push_list(L, "y", ys);
  push_list(L, "value", values);
  return 1;
}

}  // namespace

const Command& profile_command() {
  static const Command command{
      .name = "profile",
      .help =
          "Samples a quantity at evenly spaced points along a line, as history{} measures it at a "
          "point (displacements and velocities at the nearest gridpoint of rock in place, stresses "
          "in the zone containing the point), and returns them; with file = it also draws them "
          "against the distance along the line (the seed's Figure 12: settlement above the roof).",
      .keys =
          {
              {"from", Type::point, "m", any_value, kRequired, "the line's start"},
              {"to", Type::point, "m", any_value, kRequired, "the line's end"},
              {"quantity", Type::string, "", any_value, kRequired,
               "ux, uy, vx, vy (nearest gridpoint), sxx, syy, sxy, szz, s1, s3 (zone containing the point)",
               {}, profile_quantities},
              {"points", Type::integer, "", between(2, 100000), "50", "how many points, both ends included"},
              {"file", Type::string, "", any_value, kOptional,
               "a picture (.png, .svg or .pdf) of the profile against the distance", "none"},
              {"title", Type::string, "", any_value, kOptional, "the picture's title", "none"},
          },
      .run = run_profile,
      .usage =
          R"(local p = profile{ from = {-40, 30}, to = {40, 30}, quantity = "uy", file = "settlement.png" } -- p.distance, p.x, p.y, p.value)",
  };
  return command;
}

}  // namespace edem
