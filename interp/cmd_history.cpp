// Histories: history{} records a quantity every n cycles, history_write() writes them all.
//
// A script that ends with histories that no history_write() wrote gets them written to
// "<script>_history.csv" (interpreter.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <lua.hpp>

#include "callbacks.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "schema.hpp"

namespace edem {
namespace {

// The built-in quantities of Model::history_sampler: of the whole model, or at a point.
const std::vector<std::string>& model_quantities() { return Model::history_model_quantities(); }

const std::vector<std::string>& history_quantities() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = Model::history_model_quantities();
    const auto& point = Model::history_point_quantities();
    all.insert(all.end(), point.begin(), point.end());
    return all;
  }();
  return names;
}

// A name is a CSV column heading: nothing that would split or quote it.
void check_name(const std::string& name) {
  if (name.empty()) fail("name must not be empty");
  if (name.find_first_of(",\"\n\r") != std::string::npos)
    fail(
        "name must not contain commas, quotes or line breaks (it heads a CSV column), got "
        "\"{}\"",
        name);
}

bool at_a_point(const std::string& quantity) {
  const auto& whole = model_quantities();
  return std::find(whole.begin(), whole.end(), quantity) == whole.end();
}

int run_history(lua_State* L, Context& context, const Args& args) {
  const bool builtin = args.has("quantity"), fn = args.has("fn");
  if (builtin && fn) fail("give a quantity or fn, not both");
  if (!builtin && !fn)
    fail("what to record? give a quantity, history{{ \"ratio\" }}, or fn = function() ... end");
  Model& model = context.model();
  HistoryDef def;
  def.every = static_cast<long>(args.integer("every"));
  if (fn) {
    if (!args.has("name")) fail("a history with fn needs a name");
    if (args.has("at")) fail("at is for the built-in quantities; fn computes its own value");
    def.name = args.string("name");
    check_name(def.name);
    def.unit = args.has("unit") ? args.string("unit") : "-";
    def.sample = lua_sampler(L, args.get<FunctionArg>("fn").index, def.name);
  } else {
    const std::string& quantity = args.string("quantity");
    std::optional<Vec2> at;
    if (args.has("at")) at = args.point("at");
    if (at_a_point(quantity) && !at)
      fail("{} is measured at a point: give at = {{x, y}}", quantity);
    if (!at_a_point(quantity) && at) fail("{} belongs to the whole model: leave out at", quantity);
    if (args.has("unit"))
      fail("unit is for fn histories; {} is in {}", quantity, Model::history_unit(quantity));
    def.name = args.has("name") ? args.string("name")
               : at ? fmt::format("{}@({} {})", quantity, show_number(at->x), show_number(at->y))
                    : quantity;
    check_name(def.name);
    def.unit = Model::history_unit(quantity);
    def.quantity = quantity;
    def.at = at;
  }
  const std::string name = def.name;
  model.add_history(std::move(def));
  lua_pushlstring(L, name.data(), name.size());
  return 1;
}

int run_history_write(lua_State*, Context& context, const Args& args) {
  context.model().write_histories(context.output_path(args.string("file")));
  context.histories_written = true;
  return 0;
}

}  // namespace

const Command& history_command() {
  static const Command command{
      .name = "history",
      .help =
          "Records a quantity after every n-th cycle: a built-in one (of the whole model, or "
          "at the gridpoint nearest to `at` / in the zone containing `at`) or what a function "
          "returns. A point history follows its rock: when an excavation takes its gridpoint it "
          "goes on at the gridpoint of rock at the same place across the excavation's outline "
          "(said once), or else it records nothing more (a warning at the excavate line; its "
          "cells stay empty), never zeros. Histories that no `history_write` wrote are written at "
          "the end of a successful run to `<script>_history.csv` in the working directory.",
      .positional =
          {
              {"quantity", Type::string, "", any_value, kOptional,
               "of the model: ratio, time, kinetic, cycle, contacts, slipping, open (counts of "
               "contacts as last found), max_slip, cracks, shear_cracks, tension_cracks, stage, energy.TERM "
               "(a term of the energy balance, as energy() names it: energy.kinetic, energy.slip, energy.error, "
               "...); at a point: ux, uy, vx, vy (nearest "
               "gridpoint), sxx, syy, sxy, szz, s1, s3 (zone containing it), joint_sn, "
               "joint_tau, joint_un, joint_us, joint_slip (the contact nearest to it when the "
               "history is made, followed by its gridpoint; 0 while that has no contact)",
               "or fn", history_quantities},
          },
      .keys =
          {
              {"at", Type::point, "m", any_value, kOptional, "where a point quantity is measured",
               "none"},
              {"fn", Type::function, "", any_value, kOptional,
               "function() returning the number to record", "or a quantity"},
              {"name", Type::string, "", any_value, kOptional, "the column's name",
               "the quantity, with \"@(x y)\" for a point: \"uy@(0 24)\"; required with fn"},
              {"unit", Type::string, "", any_value, kOptional,
               "the unit of fn's value, for the column heading", "\"-\""},
              {"every", Type::integer, "", ge(1), "10", "cycles between samples"},
          },
      .run = run_history,
      .returns = "the history's name",
      .usage =
          "history{ \"ratio\" }\nhistory{ \"uy\", at = {0, 24}, every = 50 }\n"
          "history{ name = \"roof_sag\", unit = \"m\", fn = function() return -gp_near(0, 24).uy "
          "end }",
  };
  return command;
}

const Command& history_write_command() {
  static const Command command{
      .name = "history_write",
      .help =
          "Writes every history to a CSV file: a column of cycle numbers, then one column per "
          "history headed `name [unit]`; a history not sampled at a cycle leaves its cell empty.",
      .form = Form::call,
      .positional =
          {
              {"file", Type::string, "", any_value, kRequired, "the CSV file to write"},
          },
      .run = run_history_write,
      .usage = "history_write(\"case3_history.csv\")",
  };
  return command;
}

}  // namespace edem
