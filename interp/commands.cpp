// The registration table: one line per command. Adding a command: write its spec and runner
// in a cmd_*.cpp file, declare it in commands.hpp, list it here, and regenerate the README
// reference (`edem reference --update README.md`).
#include "commands.hpp"

#include <lua.hpp>

#include "adaptor.hpp"
#include "context.hpp"

namespace edem {

const std::vector<const Command*>& commands() {
  static const std::vector<const Command*> table = {
      &model_command(),   // cmd_model.cpp
      &block_command(),   // cmd_geometry.cpp
      &jset_command(),    //
      &crack_command(),   //
      &region_command(),  //
      &zone_command(),    //
      &info_command(),    // cmd_query.cpp
      &blocks_command(),  //
      &zones_command(),   //
      &plot_command(),    // cmd_plot.cpp
  };
  return table;
}

const Command* find_command(std::string_view name) {
  for (const Command* command : commands())
    if (command->name == name) return command;
  return nullptr;
}

namespace {

// Every command's Lua function: upvalue 1 is its Command, upvalue 2 its table of defaults.
int dispatch(lua_State* L) {
  const auto& command = *static_cast<const Command*>(lua_touserdata(L, lua_upvalueindex(1)));
  return guarded(L, command.name, [&] {
    const Args args = read_args(L, command, lua_upvalueindex(2));
    return command.run(L, context_of(L), args);
  });
}

}  // namespace

void register_commands(lua_State* L) {
  for (const Command* command : commands()) {
    lua_pushlightuserdata(L, const_cast<Command*>(command));
    push_defaults(L, *command);
    lua_pushcclosure(L, dispatch, 2);
    lua_setglobal(L, std::string(command->name).c_str());
  }
}

}  // namespace edem
