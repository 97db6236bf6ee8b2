// Potential-crack commands: crackseed{}, judge{}, cracks(), sections().
#include <lua.hpp>

#include "callbacks.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "errors.hpp"
#include "iterator.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

std::string_view mode_name(CrackMode mode) {
  switch (mode) {
    case CrackMode::shear: return "shear";
    case CrackMode::tension: return "tension";
    case CrackMode::none: break;
  }
  return "none";
}

int run_crackseed(lua_State*, Context& context, const Args& args) {
  CrackSeedDef def;
  const bool one = args.has("angle"), two = args.has("angles");
  if (one == two) fail("give angle = a or angles = {{a1, a2}} (one of them)");
  def.angles = one ? std::vector<double>{args.number("angle")} : args.get<std::vector<double>>("angles");
  def.spacing = args.number("spacing");
  def.origin = args.point("origin");
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  if (args.has("material")) def.material = args.string("material");
  if (args.has("after")) def.after = args.string("after");
  context.model().add_crackseed(def);
  return 0;
}

int run_judge(lua_State* L, Context& context, const Args& args) {
  JudgeDef def;
  def.every = static_cast<long>(args.integer("every"));
  if (args.has("criterion")) def.criterion = lua_criterion(L, args.get<FunctionArg>("criterion").index);
  context.model().judge(def);
  return 0;
}

void push_crack(lua_State* L, const Model& model, size_t index) {
  const CrackView& c = model.crack(static_cast<int>(index));
  lua_createtable(L, 0, 12);
  set_field(L, "id", static_cast<long long>(index) + 1);
  push_point(L, c.position);
  lua_setfield(L, -2, "position");
  set_field(L, "x", c.position.x);
  set_field(L, "y", c.position.y);
  set_field(L, "angle", c.angle);
  set_field(L, "length", c.length);
  set_field(L, "mode", mode_name(c.mode));
  set_field(L, "cycle", static_cast<long long>(c.cycle));
  set_field(L, "stage", c.stage);
  set_field(L, "section", c.section + 1);
  set_field(L, "sxx", c.sxx);
  set_field(L, "syy", c.syy);
  set_field(L, "sxy", c.sxy);
}

int next_crack(lua_State* L) {
  return iterator_step(
      L, "cracks", [](const Model& m) { return static_cast<size_t>(m.crack_count()); }, push_crack);
}

int next_section(lua_State* L) {
  return iterator_step(
      L, "sections", [](const Model& m) { return static_cast<size_t>(m.section_count()); },
      [](lua_State* T, const Model& m, size_t i) { push_section(T, m.section(static_cast<int>(i))); });
}

int run_cracks(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_crack, 1);
  return 1;
}

int run_sections(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_section, 1);
  return 1;
}

int refuse_write(lua_State* L) {
  return luaL_error(L, "a section is read-only (field '%s')", luaL_tolstring(L, 2, nullptr));
}

}  // namespace

void set_section_fields(lua_State* L, const SectionView& s) {
  set_field(L, "id", s.id + 1);
  set_field(L, "x", s.position.x);
  set_field(L, "y", s.position.y);
  set_field(L, "angle", s.angle);
  set_field(L, "length", s.length);
  set_field(L, "sxx", s.sxx);
  set_field(L, "syy", s.syy);
  set_field(L, "sxy", s.sxy);
  set_field(L, "s1", s.s1);
  set_field(L, "s3", s.s3);
  set_field(L, "sn", s.sn);
  set_field(L, "tau", s.tau);
  set_field(L, "cohesion", s.strength.cohesion);
  set_field(L, "friction", s.strength.friction);
  set_field(L, "tension", s.strength.tension);
}

void push_section(lua_State* L, const SectionView& s) {
  lua_createtable(L, 0, 0);   // the proxy the script sees
  lua_createtable(L, 0, 3);   // its metatable
  lua_createtable(L, 0, 16);  // the fields
  set_section_fields(L, s);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, refuse_write);
  lua_setfield(L, -2, "__newindex");
  lua_pushboolean(L, 0);
  lua_setfield(L, -2, "__metatable");  // getmetatable() cannot reach the fields either
  lua_setmetatable(L, -2);
}

const Command& crackseed_command() {
  static const Command command{
      .name = "crackseed",
      .help =
          "Places potential cracks: sets of parallel cuts through intact rock, tied shut "
          "(their faces share gridpoints: no stiffness to choose, the model deforms exactly as "
          "without them) until a section of one fails in shear "
          "or tension (judge{}); the section then becomes a crack with a joint material. "
          "Each zone edge along a cut is a section, judged on its own.",
      .keys =
          {
              {"angle", Type::number, "deg", between(-360, 360), kOptional,
               "direction of one set of cuts, counter-clockwise from +x", "or angles"},
              {"angles", Type::numbers, "deg", between(-360, 360), kOptional,
               "one set of cuts per direction, e.g. {45 + phi/2, 135 - phi/2}", "or angle"},
              {"spacing", Type::number, "m", gt(0), kRequired,
               "normal distance between the cuts of a set"},
              {"origin", Type::point, "m", any_value, "{0, 0}", "a point on one cut of each set"},
              {"region", Type::region, "", any_value, kOptional,
               "only inside this region (a name or a polygon; a region{} keeps every piece, a "
               "polygon drops the pieces that end inside a block)",
               "everywhere"},
              {"material", Type::string, "", any_value, kOptional,
               "a mohr_coulomb material whose cohesion, friction and tension judge the sections",
               "the zones' own"},
              {"after", Type::string, "", any_value, kOptional,
               "the joint material of its cracks", "the one jassign{} gives joints there"},
          },
      .run = run_crackseed,
      .usage = "crackseed{ region = \"arch\", angles = {62, 118}, spacing = 4.8, after = \"joint\" }",
  };
  return command;
}

const Command& judge_command() {
  static const Command command{
      .name = "judge",
      .help =
          "How potential-crack sections are judged: every n cycles, each intact section's "
          "stress is fitted from the zones around it (four each side, an equilibrium linear "
          "field) and the section breaks in tension when s3 > tension, else in shear when "
          "(1 - sin phi) s1 - (1 + sin phi) s3 + 2 c cos phi < 0; or by your criterion.",
      .keys =
          {
              {"every", Type::integer, "", ge(1), "10", "cycles between judgments"},
              {"criterion", Type::function, "", any_value, kOptional,
               "fn(section) returning nil, \"shear\" or \"tension\"; the section is read-only: "
               "id, x, y, angle, length, sxx, syy, sxy, s1, s3, sn, tau, cohesion, friction, "
               "tension",
               "the built-in criteria"},
          },
      .run = run_judge,
      .usage = "judge{ every = 10, criterion = function(s) if s.s3 > s.tension then return "
               "\"tension\" end end }",
  };
  return command;
}

const Command& cracks_command() {
  static const Command command{
      .name = "cracks",
      .help = "Iterates over the cracks made so far, in the order they broke.",
      .form = Form::call,
      .run = run_cracks,
      .returns =
          "an iterator; each crack is a table: id, position {x =, y =}, x, y (its section's "
          "midpoint [m]), angle [deg], length [m], mode (\"shear\" or \"tension\"), cycle, "
          "stage, section, sxx, syy, sxy (the fitted stress that broke it [Pa])",
      .usage = "for c in cracks() do if c.mode == \"tension\" then n = n + 1 end end",
  };
  return command;
}

const Command& sections_command() {
  static const Command command{
      .name = "sections",
      .help = "Iterates over the potential-crack sections with their fitted stress of now.",
      .form = Form::call,
      .run = run_sections,
      .returns = "an iterator; each section is a read-only table as judge{ criterion } gets it",
      .usage = "for s in sections() do worst = math.max(worst, s.s3) end",
  };
  return command;
}

}  // namespace edem
