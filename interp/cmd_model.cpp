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
  def.max_blocks = args.number("max_blocks");
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
              {"max_blocks", Type::number, "-", gt(0), "1e5",
               "most blocks the joint sets, cracks and crack seeds may cut: a command that would cut more, "
               "about (estimated before any cutting from the sets' spacings and the areas they cover), is "
               "refused"},
          },
      .run = run_model,
      .usage = R"(model{ title = "Case 3, H = 158 m" })",
  };
  return command;
}

}  // namespace edem
