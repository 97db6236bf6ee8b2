// Bolts: bolt_material{} defines one, bolt{} lays one in the rock, bolt_head{} holds or pulls its
// head, bolts() reads them back.
#include <lua.hpp>

#include <algorithm>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "iterator.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

int run_bolt_material(lua_State*, Context& context, const Args& args) {
  BoltMaterialDef def;
  def.name = args.string("name");
  def.young = args.number("young");
  def.area = args.number("area");
  def.density = args.number("density");
  def.yield_tension = args.number("yield_tension");
  if (args.has("yield_compression")) def.yield_compression = args.number("yield_compression");
  def.failure_strain = args.number("failure_strain");
  def.bond_stiffness = args.number("bond_stiffness");
  def.bond_strength = args.number("bond_strength");
  def.spacing = args.number("spacing");
  context.model().add_bolt_material(def);
  return 0;
}

int run_bolt(lua_State* L, Context& context, const Args& args) {
  BoltDef def;
  def.from = args.point("from");
  def.to = args.point("to");
  if (args.has("segments")) def.segments = static_cast<int>(args.integer("segments"));
  if (args.has("segment_length")) def.segment_length = args.number("segment_length");
  def.free_length = args.number("free_length");
  def.material = args.string("material");
  lua_pushinteger(L, context.model().add_bolt(def) + 1);
  return 1;
}

int run_bolt_head(lua_State*, Context& context, const Args& args) {
  BoltHeadDef def;
  def.bolt = static_cast<int>(args.integer("bolt")) - 1;
  if (args.has("velocity")) def.velocity = args.number("velocity");
  if (args.has("force")) def.force = args.number("force");
  context.model().bolt_head(def);
  return 0;
}

void push_bolt(lua_State* L, const Model& model, size_t index) {
  const BoltView b = model.bolt(static_cast<int>(index));
  lua_createtable(L, 0, 12);
  set_field(L, "id", b.id + 1);
  set_field(L, "material", b.material);
  set_field(L, "stage", b.stage);
  push_point(L, b.head);
  lua_setfield(L, -2, "head");
  push_point(L, b.end);
  lua_setfield(L, -2, "tip");
  set_field(L, "length", b.length);
  set_field(L, "head_force", b.head_force);
  lua_pushboolean(L, b.removed);
  lua_setfield(L, -2, "removed");
  double largest = 0.0;
  int broken = 0, yielded = 0;
  lua_createtable(L, static_cast<int>(b.segments.size()), 0);
  for (size_t i = 0; i < b.segments.size(); ++i) {
    const BoltSegmentView& s = b.segments[i];
    lua_createtable(L, 0, 9);
    set_field(L, "x", 0.5 * (s.a.x + s.b.x));
    set_field(L, "y", 0.5 * (s.a.y + s.b.y));
    push_point(L, s.a);
    lua_setfield(L, -2, "a");
    push_point(L, s.b);
    lua_setfield(L, -2, "b");
    set_field(L, "force", s.force);
    set_field(L, "strain", s.strain);
    set_field(L, "slip", s.slip);
    set_field(L, "plastic_slip", s.plastic_slip);
    set_field(L, "state", s.state);
    lua_pushboolean(L, s.broke);
    lua_setfield(L, -2, "broke");
    lua_rawseti(L, -2, static_cast<lua_Integer>(i) + 1);
    largest = std::max(largest, s.force);
    broken += s.broke;
    yielded += s.state == "yielded";
  }
  lua_setfield(L, -2, "segments");
  set_field(L, "max_force", largest);
  set_field(L, "broken", broken);
  set_field(L, "yielded", yielded);
}

int next_bolt(lua_State* L) {
  return iterator_step(
      L, "bolts", [](const Model& m) { return static_cast<size_t>(m.bolt_count()); }, push_bolt);
}

int run_bolts(lua_State* L, Context&, const Args&) {
  lua_pushinteger(L, 0);
  lua_pushcclosure(L, next_bolt, 1);
  return 1;
}

}  // namespace

const Command& bolt_material_command() {
  static const Command command{
      .name = "bolt_material",
      .help =
          "Defines a bolt (or cable) material: the steel's axial stiffness and strength and "
          "the grout's bond, for one bolt; `spacing` is the distance between bolts out of the "
          "plane, and the model carries each bolt's forces and stiffnesses divided by it (per "
          "metre of thickness, as 2D codes do). Defining a name again is allowed until a bolt "
          "uses it.",
      .positional = {{"name", Type::string, "", any_value, kRequired, "the material's name"}},
      .keys =
          {
              {"young", Type::number, "Pa", gt(0), kRequired, "Young's modulus of the steel"},
              {"area", Type::number, "m^2", gt(0), kRequired, "cross-section of the bolt"},
              {"density", Type::number, "kg/m^3", gt(0), "7850", "density of the steel"},
              {"yield_tension", Type::number, "N", gt(0), kRequired, "axial force at which it yields in tension"},
              {"yield_compression", Type::number, "N", gt(0), kOptional, "the same in compression",
               "yield_tension"},
              {"failure_strain", Type::number, "-", gt(0), kRequired,
               "tensile strain at which a segment breaks (the seed's bolts: 0.035)"},
              {"bond_stiffness", Type::number, "N/m/m", gt(0), kRequired,
               "grout shear stiffness per metre of bolt"},
              {"bond_strength", Type::number, "N/m", gt(0), kRequired, "grout shear strength per metre of bolt"},
              {"spacing", Type::number, "m", gt(0), "1", "between bolts out of the plane"},
          },
      .run = run_bolt_material,
      .usage =
          "bolt_material{ \"rebar\", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, "
          "failure_strain = 0.035, bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }",
  };
  return command;
}

const Command& bolt_command() {
  static const Command command{
      .name = "bolt",
      .help =
          "Lays a straight grouted bolt from its head (at the wall) to its end, as a line of "
          "segments with nodes; the ends are points as the model was drawn, like every point a "
          "script gives, and the bolt is laid, stress-free, where that rock is now: axial force "
          "EA/L with tensile and compressive yield, broken past the failure strain; the grout "
          "ties each node to the rock around it along the bolt (bond stiffness and strength), "
          "and the node follows the rock across the bolt, into the next block when it slides "
          "there. Every grouted point must be in rock. Where its rock is later excavated (a step "
          "dug, a fallen block mucked out) the bolt is cut: the segments reaching that rock carry "
          "nothing from then on, and the rest, grouted in the rock still there, stays in service.",
      .keys =
          {
              {"from", Type::point, "m", any_value, kRequired, "the head, at the wall"},
              {"to", Type::point, "m", any_value, kRequired, "the end, in the rock"},
              {"segments", Type::integer, "", ge(1), kOptional, "segments over the grouted length",
               "or segment_length"},
              {"segment_length", Type::number, "m", gt(0), kOptional,
               "the longest segment (the grouted length is cut into equal ones)", "or segments"},
              {"free_length", Type::number, "m", ge(0), "0",
               "ungrouted length from the head, one segment of its own (a tendon's free length)"},
              {"material", Type::string, "", any_value, kRequired, "a bolt material's name"},
          },
      .run = run_bolt,
      .returns = "the bolt's id (1, 2, ...)",
      .usage = "bolt{ from = {12, 0}, to = {17, 0}, segments = 10, material = \"rebar\" }",
  };
  return command;
}

const Command& bolt_head_command() {
  static const Command command{
      .name = "bolt_head",
      .help =
          "Holds a bolt's head: a jack pulling it out of the hole at a velocity, or a constant "
          "pull (a pretension, or a plate's load); with neither, the head is free again. The "
          "pull on the head is the bolt's head_force in bolts(). A head whose rock is excavated, "
          "even by an excavate{} since the last cycle, is cut off: a drive on it is refused.",
      .keys =
          {
              {"bolt", Type::integer, "", ge(1), kRequired, "the bolt's id, as bolt{} returned it"},
              {"velocity", Type::number, "m/s", any_value, kOptional,
               "outwards along the bolt (static mode: m per cycle)", "not driven"},
              {"force", Type::number, "N", any_value, kOptional, "outwards, for one bolt (divided by its spacing)",
               "no pull"},
          },
      .run = run_bolt_head,
      .usage = "bolt_head{ bolt = 1, velocity = 1e-6 }",
  };
  return command;
}

const Command& bolts_command() {
  static const Command command{
      .name = "bolts",
      .help = "Iterates over the bolts laid so far, in order.",
      .form = Form::call,
      .run = run_bolts,
      .returns =
          "an iterator; each bolt is a table: id, material, stage (when it was laid), head, tip "
          "({x =, y =} as laid [m]), length [m], head_force (the pull on its head [N/m]), "
          "max_force [N/m], broken (segments that have broken, also those cut away with their rock "
          "since), yielded (segments yielded now, of those still in the rock), removed (none of "
          "its rock is left: out of service), segments (a list from the head: a, b (its ends now, "
          "{x =, y =} [m]), x, y (its midpoint), force (axial, tension positive [N/m]), strain "
          "[-], slip (grout, bolt against rock along it [m]), plastic_slip [m], state "
          "(\"elastic\", \"yielded\", \"broken\", \"removed\": an end's rock is gone), broke "
          "(true once it has broken, whatever its state now)))",
      .usage = "for b in bolts() do print(b.id, b.max_force, b.broken) end",
  };
  return command;
}

}  // namespace edem
