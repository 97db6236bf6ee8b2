// The interpreter's state that commands share: the current model and run options.
//
// One Context per lua_State, owned by the Interpreter and reached from Lua C functions through
// the state's extra space (context_of), so the language keeps no global mutable state.
#pragma once

#include <memory>
#include <string>

#include "model/model.hpp"

struct lua_State;

namespace edem {

struct Context {
  std::unique_ptr<Model> current;  // null until the first command needs a model
  bool quiet = false;              // --quiet: commands print no progress
  std::string last_command_error;  // the last "FILE:LINE: command: message" raised

  // The current model; a script that starts without model{} gets a default one.
  Model& model() {
    if (!current) current = std::make_unique<Model>();
    return *current;
  }
};

// Makes `context` reachable from every C function running in `L`.
void attach(lua_State* L, Context& context);

// The Context attached to `L`.
Context& context_of(lua_State* L);

}  // namespace edem
