// model{}: starting a new model.
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"

namespace edem {
namespace {

int run_model(lua_State*, Context& context, const Args& args) {
  if (const Running* cycling = context.cycling())
    fail("cannot start a new model inside a callback while {}() at {} cycles the current one",
         cycling->command, cycling->cycling_at);
  ModelDef def;
  def.title = args.string("title");
  def.tolerance = args.number("tolerance");
  // Built before the old one is dropped, so a failure keeps the current model.
  context.replace_model(std::make_unique<Model>(def));
  return 0;
}

}  // namespace

const Command& model_command() {
  static const Command command{
      .name = "model",
      .help =
          "Starts a new, empty model and discards the current one. Commands used before any "
          "`model{}` work on a default model.",
      .keys =
          {
              {"title", Type::string, "", any_value, R"("")", "a title for pictures and output"},
              {"tolerance", Type::number, "-", above_upto(0, 1e-3), "1e-9",
               "geometric tolerance, relative to the size of the model"},
          },
      .run = run_model,
      .usage = R"(model{ title = "Case 3, H = 158 m" })",
  };
  return command;
}

}  // namespace edem
