// Calling Lua back from inside the engine: a registry reference per function, a pcall on the
// running thread, and failures turned into one CallbackError.
#include "callbacks.hpp"

#include <fmt/format.h>

#include <lua.hpp>
#include <memory>
#include <vector>

#include "adaptor.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "errors.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

// The thread to call Lua on: the one running the innermost command (the main thread when
// none runs, as while the interpreter closes).
lua_State* thread_of(const Context& context) {
  return context.running != nullptr ? context.running->L : context.lua;
}

// A Lua function kept in the registry for as long as this lives.
class LuaRef {
 public:
  LuaRef(lua_State* L, int index) : context_(context_of(L)) {
    lua_pushvalue(L, index);
    ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  ~LuaRef() {
    lua_State* L = thread_of(context_);
    if (context_.lua == nullptr || L == nullptr) return;  // closed: the registry is gone
    luaL_unref(L, LUA_REGISTRYINDEX, ref_);
  }
  LuaRef(const LuaRef&) = delete;
  LuaRef& operator=(const LuaRef&) = delete;

  Context& context() const { return context_; }
  int ref() const { return ref_; }

 private:
  Context& context_;
  int ref_ = LUA_NOREF;
};

// Message handler of a callback's pcall: returns {headline, traceback line, ...} with the
// frames of the callback only. Upvalue 1: the stack depth outside the call; 2: the word.
int callback_handler(lua_State* L) {
  return guarded(L, lua_tostring(L, lua_upvalueindex(2)), [&] {
    const int outside = static_cast<int>(lua_tointeger(L, lua_upvalueindex(1)));
    // Level 0 is this handler; the callback's frames come next, then the `outside` ones.
    const int inside = stack_levels(L) - outside - 1;
    const std::string headline = error_headline(L);
    const std::vector<std::string> frames = traceback_lines(L, 1, inside);
    lua_createtable(L, static_cast<int>(frames.size()) + 1, 0);
    lua_pushlstring(L, headline.data(), headline.size());
    lua_rawseti(L, -2, 1);
    for (size_t i = 0; i < frames.size(); ++i) {
      lua_pushlstring(L, frames[i].data(), frames[i].size());
      lua_rawseti(L, -2, static_cast<lua_Integer>(i + 2));
    }
    return 1;
  });
}

// "(while cycle() at test.lua:12 was running)", or "" outside any command.
std::string while_running(const Context& context) {
  if (const Running* cycling = context.cycling())
    return fmt::format(" (while {}() at {} was running)", cycling->command, cycling->cycling_at);
  if (const Running* running = context.running) {
    const Command* command = find_command(running->command);
    const bool call = command != nullptr && command->form == Form::call;
    return fmt::format(" (while {}{} was running)", running->command, call ? "()" : "{}");
  }
  return {};
}

// Where to blame an error that has no position of its own: the cycling command's call.
std::string fallback_location(const Context& context) {
  const Running* cycling = context.cycling();
  return cycling != nullptr ? cycling->cycling_at : "?";
}

// The failure of a call: the headline and frames the handler returned at the top of `L`.
[[noreturn]] void fail_call(lua_State* L, int top, std::string_view word, std::string_view what) {
  const Context& context = context_of(L);
  std::string headline;
  std::vector<std::string> frames;
  if (lua_istable(L, -1)) {
    const auto count = static_cast<lua_Integer>(lua_rawlen(L, -1));
    for (lua_Integer i = 1; i <= count; ++i) {
      lua_rawgeti(L, -1, i);
      std::string line = lua_tostring(L, -1);
      lua_pop(L, 1);
      if (i == 1)
        headline = std::move(line);
      else
        frames.push_back(std::move(line));
    }
  } else {
    const char* text = lua_tostring(L, -1);  // the handler itself failed
    headline = text != nullptr ? text : "error while reporting an error";
  }
  lua_settop(L, top);
  std::string location, text;
  if (const auto located = split_position(headline)) {
    location = located->source + ":" + located->line;
    text = located->text;
  } else {
    location = fallback_location(context);
    text = headline;
  }
  // The runner's words for Lua's own errors say nothing more here; a command's name does.
  for (const std::string_view word_of_lua : {"lua: ", "error: "})
    if (text.starts_with(word_of_lua)) text.erase(0, word_of_lua.size());
  throw CallbackError(
      fmt::format("{}: {}: error in {}{}: {}", location, word, what, while_running(context), text),
      std::move(frames));
}

struct Call {
  lua_State* L;
  int top;  // the stack top before the call: results are above it
};

// Calls `fn` with the arguments that `push` pushes (it returns their count) and leaves
// `results` results above the returned top; a failure throws CallbackError.
template <typename Push>
Call call(const LuaRef& fn, Push&& push, int results, std::string_view word,
          std::string_view what) {
  lua_State* L = thread_of(fn.context());
  if (L == nullptr) fail("{} was called while no script runs", what);
  if (!lua_checkstack(L, 8)) fail("no room on the Lua stack to call {}", what);
  const int top = lua_gettop(L);
  lua_pushinteger(L, stack_levels(L));
  lua_pushlstring(L, word.data(), word.size());
  lua_pushcclosure(L, callback_handler, 2);
  lua_rawgeti(L, LUA_REGISTRYINDEX, fn.ref());
  const int args = push(L);
  if (lua_pcall(L, args, results, top + 1) != LUA_OK) fail_call(L, top, word, what);
  lua_remove(L, top + 1);  // the handler
  return {L, top};
}

// A call returned the wrong thing (at the top of its thread): no line ran it, so the error
// blames the function's definition. "LOCATION: WORD: MUST, got VALUE (while ...)".
[[noreturn]] void fail_return(const LuaRef& fn, const Call& done, std::string_view word,
                              const std::string& must) {
  lua_State* T = done.L;
  const std::string got = describe(T, -1);
  lua_settop(T, done.top);
  lua_rawgeti(T, LUA_REGISTRYINDEX, fn.ref());
  lua_Debug info;
  lua_getinfo(T, ">S", &info);
  const Context& context = fn.context();
  const std::string location = info.linedefined > 0
                                   ? fmt::format("{}:{}", source_of(info), info.linedefined)
                                   : fallback_location(context);
  throw CallbackError(
      fmt::format("{}: {}: {}, got {}{}", location, word, must, got, while_running(context)), {});
}

}  // namespace

std::function<void(long cycle)> lua_callback(lua_State* L, int index) {
  auto fn = std::make_shared<const LuaRef>(L, index);
  Context* context = &context_of(L);  // the interpreter's: it outlives every model
  return [fn, context](long cycle) {
    // cancel() inside the callback may drop this std::function while it runs: hold our own.
    const std::shared_ptr<const LuaRef> keep = fn;
    context->close_progress_line();  // what the callback prints starts on a line of its own
    const auto push = [cycle](lua_State* T) {
      lua_pushinteger(T, static_cast<lua_Integer>(cycle));
      return 1;
    };
    const Call done = call(*keep, push, 0, "every", "the callback");
    lua_settop(done.L, done.top);
  };
}

std::function<double()> lua_sampler(lua_State* L, int index, const std::string& name) {
  auto fn = std::make_shared<const LuaRef>(L, index);
  return [fn, name]() {
    const std::shared_ptr<const LuaRef> keep = fn;
    const std::string what = fmt::format("fn of history '{}'", name);
    const Call done = call(
        *keep, [](lua_State*) { return 0; }, 1, "history", what);
    lua_State* T = done.L;
    if (lua_type(T, -1) == LUA_TNUMBER) {
      const double value = lua_tonumber(T, -1);
      lua_settop(T, done.top);
      return value;
    }
    fail_return(*keep, done, "history", fmt::format("{} must return a number", what));
  };
}

std::function<CrackMode(const SectionView&)> lua_criterion(lua_State* L, int index) {
  auto fn = std::make_shared<const LuaRef>(L, index);
  push_section(L, SectionView{});
  auto view = std::make_shared<const LuaRef>(L, -1);
  lua_pop(L, 1);
  return [fn, view](const SectionView& section) {
    const std::shared_ptr<const LuaRef> keep = fn;
    const auto push = [&section, &view](lua_State* T) {
      lua_rawgeti(T, LUA_REGISTRYINDEX, view->ref());
      lua_getmetatable(T, -1);
      lua_getfield(T, -1, "__index");
      set_section_fields(T, section);
      lua_pop(T, 2);
      return 1;
    };
    const Call done = call(*keep, push, 1, "judge", "the criterion");
    lua_State* T = done.L;
    const int type = lua_type(T, -1);
    if (type == LUA_TNIL) {
      lua_settop(T, done.top);
      return CrackMode::none;
    }
    if (type == LUA_TSTRING) {
      const std::string_view word = lua_tostring(T, -1);
      const CrackMode mode = word == "shear"     ? CrackMode::shear
                             : word == "tension" ? CrackMode::tension
                                                 : CrackMode::none;
      if (mode != CrackMode::none) {
        lua_settop(T, done.top);
        return mode;
      }
    }
    fail_return(*keep, done, "judge", "the criterion must return nil, \"shear\" or \"tension\"");
  };
}

}  // namespace edem
