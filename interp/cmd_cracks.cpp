// Potential-crack commands: crackseed{}, judge{}, cracks(), sections().
#include <lua.hpp>

#include <cmath>

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

// A number field of the table on top of the stack, named for messages as `path`.
double number_field(lua_State* L, const char* key, const std::string& path) {
  lua_pushstring(L, key);
  lua_rawget(L, -2);
  if (lua_type(L, -1) != LUA_TNUMBER) {
    lua_pop(L, 1);
    fail("auto: {}.{} must be a number, as prepass{{}} gives it", path, key);
  }
  const double value = lua_tonumber(L, -1);
  lua_pop(L, 1);
  if (!std::isfinite(value)) fail("auto: {}.{} must be finite, got {}", path, key, value);
  return value;
}

// A string field of the table on top of the stack ("" when absent).
std::string string_field(lua_State* L, const char* key) {
  lua_pushstring(L, key);
  lua_rawget(L, -2);
  std::string value = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
  lua_pop(L, 1);
  return value;
}

// The zones of a prepass{} result (the table at `index`): id, x, y, state, states, angle.
std::vector<PrepassZone> read_prepass_zones(lua_State* L, int index) {
  lua_pushstring(L, "zones");
  lua_rawget(L, index);
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    fail("auto must be a prepass{{}} result: it has no zones list");
  }
  std::vector<PrepassZone> zones;
  const auto count = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer i = 1; i <= count; ++i) {
    lua_rawgeti(L, -1, i);
    const std::string path = fmt::format("zones[{}]", i);
    if (!lua_istable(L, -1)) {
      lua_pop(L, 2);
      fail("auto: {} must be a table, as prepass{{}} gives it", path);
    }
    try {
      PrepassZone z;
      const double id = number_field(L, "id", path);
      if (id < 1 || id > 2e9 || id != std::floor(id)) fail("auto: {}.id must be a zone number, got {}", path, id);
      z.zone = static_cast<int>(id) - 1;
      z.centroid = {number_field(L, "x", path), number_field(L, "y", path)};
      z.angle = number_field(L, "angle", path);
      const std::string state = string_field(L, "state");
      z.shear = state.find("shear") != std::string::npos;
      z.tension = state.find("tension") != std::string::npos;
      lua_pushstring(L, "states");
      lua_rawget(L, -2);
      if (lua_istable(L, -1)) {
        lua_rawgeti(L, -1, static_cast<lua_Integer>(lua_rawlen(L, -1)));
        z.excavated = lua_type(L, -1) == LUA_TSTRING && std::string_view(lua_tostring(L, -1)) == "excavated";
        lua_pop(L, 1);
      }
      lua_pop(L, 1);
      zones.push_back(z);
    } catch (...) {
      lua_pop(L, 2);
      throw;
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return zones;
}

// crackseed{ auto = prepass result }: the groups placed, as a list.
int run_auto_crackseed(lua_State* L, Context& context, const Args& args) {
  if (args.has("angle") || args.has("angles")) fail("auto places its own cuts: leave out angle and angles");
  AutoCrackSeedDef def;
  def.zones = read_prepass_zones(L, args.get<TableArg>("auto").index);
  if (args.has("spacing")) def.spacing = args.number("spacing");
  def.similar = args.number("similar");
  if (args.has("min_angle")) def.min_angle = args.number("min_angle");
  if (args.has("origin")) def.origin = args.point("origin");
  if (args.has("by_mode")) def.by_mode = args.boolean("by_mode");
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  if (args.has("material")) def.material = args.string("material");
  if (args.has("after")) def.after = args.string("after");
  const int first = context.model().info().crack_seeds;
  const std::vector<CrackRegion> regions = context.model().add_auto_crackseed(def);
  lua_createtable(L, static_cast<int>(regions.size()), 0);
  for (size_t i = 0; i < regions.size(); ++i) {
    const CrackRegion& r = regions[i];
    lua_createtable(L, 0, 9);
    set_field(L, "seed", first + static_cast<int>(i) + 1);
    set_field(L, "mode", std::string_view(r.tension ? "tension" : "shear"));
    set_field(L, "principal", r.principal);
    set_field(L, "friction", r.friction);
    lua_createtable(L, 2, 0);
    for (size_t k = 0; k < r.angles.size(); ++k) {
      lua_pushnumber(L, r.angles[k]);
      lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
    }
    lua_setfield(L, -2, "angles");
    lua_createtable(L, static_cast<int>(r.zones.size()), 0);
    for (size_t k = 0; k < r.zones.size(); ++k) {
      lua_pushinteger(L, r.zones[k] + 1);
      lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
    }
    lua_setfield(L, -2, "zones");
    push_point(L, r.origin);
    lua_setfield(L, -2, "origin");
    lua_createtable(L, static_cast<int>(r.cuts.size()), 0);
    for (size_t k = 0; k < r.cuts.size(); ++k) {
      lua_createtable(L, 2, 0);
      push_point(L, r.cuts[k][0]);
      lua_rawseti(L, -2, 1);
      push_point(L, r.cuts[k][1]);
      lua_rawseti(L, -2, 2);
      lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
    }
    lua_setfield(L, -2, "cuts");
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  if (!context.quiet) {
    size_t cuts = 0;
    for (const CrackRegion& r : regions) cuts += r.cuts.size();
    fmt::print("crackseed: auto: {} group(s) of yielded zones, {} cut(s)\n", regions.size(), cuts);
    std::fflush(stdout);
  }
  return 1;
}

int run_crackseed(lua_State* L, Context& context, const Args& args) {
  if (args.has("auto")) return run_auto_crackseed(L, context, args);
  CrackSeedDef def;
  const bool one = args.has("angle"), two = args.has("angles");
  if (one == two) fail("give angle = a or angles = {{a1, a2}} (one of them), or auto = a prepass{{}} result");
  if (args.has("min_angle"))
    fail("min_angle is for auto = a prepass{{}} result: cuts at angle or angles are laid as given");
  if (args.has("by_mode"))
    fail("by_mode is for auto = a prepass{{}} result: it says how its groups are formed");
  def.angles = one ? std::vector<double>{args.number("angle")} : args.get<std::vector<double>>("angles");
  if (!args.has("spacing")) fail("spacing is needed (the normal distance between the cuts of a set)");
  def.spacing = args.number("spacing");
  if (args.has("origin")) def.origin = args.point("origin");
  if (args.has("region")) def.region = args.get<RegionRef>("region");
  if (args.has("material")) def.material = args.string("material");
  if (args.has("after")) def.after = args.string("after");
  context.model().add_crackseed(def);
  return 0;
}

const std::vector<std::string>& judging_times() {
  static const std::vector<std::string> names = {"cycles", "equilibrium"};
  return names;
}

const std::vector<std::string>& neighbour_rules() {
  static const std::vector<std::string> names = {"wait", "break"};
  return names;
}

int run_judge(lua_State* L, Context& context, const Args& args) {
  JudgeDef def;
  def.at = args.string("at") == "equilibrium" ? JudgeAt::equilibrium : JudgeAt::cycles;
  if (def.at == JudgeAt::equilibrium && args.has("every"))
    fail("every is for at = \"cycles\" (a judgment every n cycles); at = \"equilibrium\" "
         "judges each state a solve{{}} brings to its ratio");
  if (args.has("every")) def.every = static_cast<long>(args.integer("every"));
  def.most = static_cast<long>(args.integer("most"));
  const std::string neighbours =
      args.has("neighbours") ? args.string("neighbours") : def.at == JudgeAt::equilibrium ? "wait" : "break";
  def.neighbours_wait = neighbours == "wait";
  def.radius = args.number("radius");
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
  set_field(L, "overstress", s.overstress);
  lua_pushboolean(L, s.gone);
  lua_setfield(L, -2, "gone");
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
          "Each zone edge along a cut is a section, judged on its own. With auto = a prepass{} "
          "result it places them itself, where that prepass found the rock yielding: the yielded "
          "zones grouped by principal direction, two sets in each group, at +-(45 + phi/2) from "
          "the major principal plane where shear governs, along and across it where tension "
          "does, in more than half the group's area (crack/auto_placement.hpp tells how).",
      .keys =
          {
              {"angle", Type::number, "deg", between(-360, 360), kOptional,
               "direction of one set of cuts, counter-clockwise from +x", "or angles"},
              {"angles", Type::numbers, "deg", between(-360, 360), kOptional,
               "one set of cuts per direction, e.g. {45 + phi/2, 135 - phi/2}", "or angle"},
              {"auto", Type::table, "", any_value, kOptional,
               "a prepass{} result: cuts only in the zones it found yielding, at the angles above, "
               "one crack seed per group (returns the groups)",
               "angle or angles"},
              {"spacing", Type::number, "m", gt(0), kOptional,
               "normal distance between the cuts of a set",
               "required; with auto a tenth of the height the prepass excavated"},
              {"similar", Type::number, "deg", above_upto(0, 90), "15",
               "auto: largest difference of principal direction within a group"},
              {"min_angle", Type::number, "deg", between(0, 60), kOptional,
               "auto: where a cut would meet a joint, a crack, an outline or another cut at a "
               "corner sharper than this, its stretch there is left out, back to the crossings "
               "either side (counted in info().cuts_cut_back): no thin wedge forms that could "
               "break loose and be driven tip first into its neighbours",
               "0: every cut laid"},
              {"origin", Type::point, "m", any_value, kOptional,
               "a point on one cut of each set (with auto: of every group's sets)",
               "{0, 0}; with auto each group's centroid (and a group no line through the point "
               "given crosses)"},
              {"by_mode", Type::boolean, "", any_value, kOptional,
               "auto: each group keeps to one failure mode (false: a group is the touching "
               "zones of one principal direction, a tension group where its tension zones cover "
               "more than half its area, as the seed's rule reads)",
               "false"},
              {"region", Type::region, "", any_value, kOptional,
               "only inside this region (a name or a polygon; a region{} keeps every piece, a "
               "polygon drops the pieces that end inside a block)",
               "everywhere"},
              {"material", Type::string, "", any_value, kOptional,
               "a material of model \"mohr\" whose cohesion, friction and tension judge the sections",
               "the zones' own"},
              {"after", Type::string, "", any_value, kOptional,
               "the joint material of its cracks", "the one jassign{} gives joints there"},
          },
      .run = run_crackseed,
      .returns = "with auto: the groups, each {seed, mode, principal, friction, angles, zones, origin, cuts}",
      .usage = "crackseed{ region = \"arch\", angles = {62, 118}, spacing = 4.8, after = \"joint\" }\n"
               "local groups = crackseed{ auto = prepass{ stages = {\"heading\", \"bench\"} }, spacing = 4.8 }",
  };
  return command;
}

const Command& judge_command() {
  static const Command command{
      .name = "judge",
      .help =
          "How and when potential-crack sections are judged. Each intact section's stress is "
          "fitted from the zones around it (four each side, an equilibrium linear field; with "
          "radius, also the rest of its two blocks' zones within it) and the section breaks in "
          "tension when s3 > tension, else in shear when "
          "(1 - sin phi) s1 - (1 + sin phi) s3 + 2 c cos phi < 0; or by your criterion. "
          "at = \"cycles\" judges every n cycles while the model moves (the seed's way: what "
          "breaks depends on how fast loads come on or off); at = \"equilibrium\" judges only "
          "states a solve{} has brought to its ratio: all sections on one state, those that fail "
          "break (of those that touch, the one furthest past its strength: neighbours), the "
          "model is solved again, and so on until a round breaks none; cycle() judges nothing "
          "then.",
      .keys =
          {
              {"at", Type::string, "", any_value, "\"cycles\"",
               "cycles: every `every` cycles; equilibrium: on each state a solve{} brings to its "
               "ratio, in rounds until none breaks",
               "", judging_times},
              {"every", Type::integer, "", ge(1), kOptional,
               "cycles between judgments (at = \"cycles\" only)", "10"},
              {"most", Type::integer, "", ge(0), "0",
               "at most this many sections break at a judgment (a round, at = \"equilibrium\"), "
               "those furthest past the built-in criteria first (larger of s3 / tension and the "
               "Mohr circle's radius over the shear strength at its centre); the rest are judged "
               "again next time; 0: all that fail"},
              {"neighbours", Type::string, "", any_value, kOptional,
               "wait: of failing sections that touch, only the one furthest past its strength "
               "breaks, and the others are judged again on the state that leaves (so that a "
               "coarse load step breaks what a fine one would); break: all that fail break "
               "together (the seed's way)",
               "wait at equilibrium, break at cycles", neighbour_rules},
              {"radius", Type::number, "m", ge(0), "0",
               "the stress is also fitted to every zone of the section's two blocks whose "
               "centroid lies within this distance of its point: a length of the rock's, so that "
               "finer zones judge the same averaged stress instead of sharper peaks; 0: the four "
               "nearest each side only, as the seed"},
              {"criterion", Type::function, "", any_value, kOptional,
               "fn(section) returning nil, \"shear\" or \"tension\"; the section is read-only: "
               "id, x, y, angle, length, sxx, syy, sxy, s1, s3, sn, tau, cohesion, friction, "
               "tension, overstress (the larger of s3 / tension and the Mohr circle's radius over "
               "the shear strength at its centre: 1 breaks it)",
               "the built-in criteria"},
          },
      .run = run_judge,
      .usage =
          "judge{ every = 10, criterion = function(s) if s.s3 > s.tension then return "
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
      .returns = "an iterator; each section is a read-only table as judge{ criterion } gets it, "
                 "and gone (true: its rock dug or mucked out on both sides; its stress, "
                 "strength and overstress are then zero, and it is never judged)",
      .usage = "for s in sections() do worst = math.max(worst, s.s3) end",
  };
  return command;
}

}  // namespace edem
