// Geometry commands: block{}, jset{}, crack{}, region{}, zone{}. Each fills one engine def
// and calls one Model function, which checks the geometry and changes nothing on failure.
#include <fmt/format.h>

#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

// x = {x0, x1}, y = {y0, y1} as a counter-clockwise rectangle.
Polygon rectangle(const Args& args) {
  if (!args.has("x") || !args.has("y"))
    fail("a rectangle needs both x = {{x0, x1}} and y = {{y0, y1}}");
  const auto x = args.get<std::array<double, 2>>("x");
  const auto y = args.get<std::array<double, 2>>("y");
  if (!(x[0] < x[1])) fail("x must be {{x0, x1}} with x0 < x1, got {{{}, {}}}", x[0], x[1]);
  if (!(y[0] < y[1])) fail("y must be {{y0, y1}} with y0 < y1, got {{{}, {}}}", y[0], y[1]);
  return {{x[0], y[0]}, {x[1], y[0]}, {x[1], y[1]}, {x[0], y[1]}};
}

int run_block(lua_State*, Context& context, const Args& args) {
  const bool corners = args.has("outline");
  const bool box = args.has("x") || args.has("y");
  if (corners && box) fail("give corner points or x = {{x0, x1}}, y = {{y0, y1}}, not both");
  if (!corners && !box)
    fail(
        "no outline: give corner points, block{{ {{x, y}}, {{x, y}}, {{x, y}}, ... }}, or a "
        "rectangle, block{{ x = {{x0, x1}}, y = {{y0, y1}} }}");
  BlockDef def;
  def.polygon = corners ? args.get<Polygon>("outline") : rectangle(args);
  context.model().add_block(def);
  return 0;
}

int run_jset(lua_State* L, Context& context, const Args& args) {
  JointSetDef def;
  def.angle = args.number("angle");
  def.spacing = args.get<std::vector<double>>("spacing");
  def.origin = args.point("origin");
  if (args.has("trace")) def.trace = args.number("trace");
  def.gap = args.number("gap");
  def.angle_dev = args.number("angle_dev");
  def.spacing_dev = args.number("spacing_dev");
  def.trace_dev = args.number("trace_dev");
  def.gap_dev = args.number("gap_dev");
  def.seed = static_cast<std::uint64_t>(args.integer("seed"));
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  const int set = context.model().add_joint_set(def);
  lua_pushinteger(L, set + 1);
  return 1;
}

int run_crack(lua_State*, Context& context, const Args& args) {
  CrackDef def;
  def.from = args.point("from");
  def.to = args.point("to");
  context.model().add_crack(def);
  return 0;
}

int run_region(lua_State*, Context& context, const Args& args) {
  RegionDef def;
  def.name = args.string("name");
  if (def.name.empty()) fail("name must not be empty");
  def.polygon = args.get<Polygon>("polygon");
  def.glued = args.boolean("glued");
  context.model().add_region(def);
  return 0;
}

int run_zone(lua_State*, Context& context, const Args& args) {
  ZoneDef def;
  def.edge = args.number("edge");
  def.far = args.has("far") ? args.number("far") : def.edge;
  if (def.far < def.edge) fail("far must be >= edge ({}), got {}", def.edge, def.far);
  def.growth = args.number("growth");
  if (args.has("near")) def.near = args.get<std::vector<RegionRef>>("near");
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  def.sliver = args.number("sliver");
  def.max_zones = args.number("max_zones");
  context.model().zone(def);
  return 0;
}

}  // namespace

const Command& block_command() {
  static const Command command{
      .name = "block",
      .help =
          "Adds a block of intact rock, given by its corners or as a rectangle. Blocks must "
          "not overlap; joints, cracks and regions cut them.",
      .positional =
          {
              {"outline", Type::polygon, "m", any_value, kOptional,
               "the corners, in either direction", "or x and y", nullptr, true},
          },
      .keys =
          {
              {"x", Type::pair, "m", any_value, kOptional, "x0 < x1: left and right sides",
               "or corners"},
              {"y", Type::pair, "m", any_value, kOptional, "y0 < y1: bottom and top sides",
               "or corners"},
          },
      .run = run_block,
      .usage = "block{ x = {-100, 100}, y = {-90, 90} }\nblock{ {0, 0}, {10, 0}, {5, 8} }",
  };
  return command;
}

const Command& jset_command() {
  static const Command command{
      .name = "jset",
      .help =
          "Cuts a set of parallel joints through the blocks (or only inside a region). "
          "Returns the set's number, 1, 2, ...",
      .keys =
          {
              {"angle", Type::number, "deg", between(-360, 360), kRequired,
               "direction of the traces, counter-clockwise from +x"},
              {"spacing", Type::numbers, "m", gt(0), kRequired,
               "normal distance between traces; a list is used in turn"},
              {"origin", Type::point, "m", any_value, "{0, 0}", "a point on one trace"},
              {"trace", Type::number, "m", gt(0), kOptional, "length of each trace", "infinite"},
              {"gap", Type::number, "m", ge(0), "0", "gap between traces along a joint"},
              {"angle_dev", Type::number, "deg", between(0, 90), "0",
               "random deviation of each trace's angle (uniform, +-)"},
              {"spacing_dev", Type::number, "m", ge(0), "0",
               "random deviation of each spacing (uniform, +-)"},
              {"trace_dev", Type::number, "m", ge(0), "0",
               "random deviation of each trace length (uniform, +-)"},
              {"gap_dev", Type::number, "m", ge(0), "0",
               "random deviation of each gap (uniform, +-)"},
              {"seed", Type::integer, "", ge(0), "1", "random stream of the deviations"},
              {"region", Type::region, "", any_value, kOptional,
               "cut only inside this region (a name or a polygon)", "everywhere"},
          },
      .run = run_jset,
      .returns = "the joint set's number",
      .usage = "jset{ angle = 60, spacing = {16, 12, 8} }",
  };
  return command;
}

const Command& crack_command() {
  static const Command command{
      .name = "crack",
      .help =
          "Cuts one straight crack from a point to another; parts that split no block are "
          "dropped.",
      .keys =
          {
              {"from", Type::point, "m", any_value, kRequired, "one end"},
              {"to", Type::point, "m", any_value, kRequired, "the other end"},
          },
      .run = run_crack,
      .usage = "crack{ from = {0, 0}, to = {5, 3} }",
  };
  return command;
}

const Command& region_command() {
  static const Command command{
      .name = "region",
      .help =
          "Names a region and cuts its outline into the blocks (an excavation stage, a zone "
          "of weak rock). Its name can then stand for its polygon.",
      .keys =
          {
              {"name", Type::string, "", any_value, kRequired, "a name not used by another region"},
              {"polygon", Type::polygon, "m", any_value, kRequired, "the outline"},
              {"glued", Type::boolean, "", any_value, "true", "outline edges never slide or open"},
          },
      .run = run_region,
      .usage = R"(region{ name = "stage1", polygon = {{-6, 0}, {6, 0}, {6, 8}, {-6, 8}} })",
  };
  return command;
}

const Command& zone_command() {
  static const Command command{
      .name = "zone",
      .help =
          "Meshes the blocks into triangular zones, finest near the given regions and "
          "coarser with distance from them.",
      .keys =
          {
              {"edge", Type::number, "m", gt(0), "1", "zone edge length near `near`"},
              {"far", Type::number, "m", gt(0), kOptional,
               "largest zone edge length, far away (>= edge)", "edge"},
              {"growth", Type::number, "-", ge(0), "0.2",
               "increase of edge length per metre of distance"},
              {"near", Type::regions, "", any_value, kOptional,
               "where zones are finest: region names or polygons", "uniform size"},
              {"region", Type::region, "", any_value, kOptional,
               "zone only the blocks in this region", "all blocks"},
              {"sliver", Type::number, "-", between(0, 0.5), "0.1",
               "no block edge shorter than this fraction of the zone edge there: cuts that would make one "
               "are bent together (info().snapped counts them, info().shortest_edge measures what is left); "
               "0: only model{ tolerance }"},
              {"max_zones", Type::number, "-", gt(0), "1e6",
               "refused before meshing if the finest edge would make about more zones than this (each block's area over "
               "a zone's, or a thin block's perimeter over twice its width)"},
          },
      .run = run_zone,
      .usage = R"(zone{ edge = 1.5, far = 10, near = "stage1" })",
  };
  return command;
}

}  // namespace edem
