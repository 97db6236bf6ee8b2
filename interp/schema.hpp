// The command schema: what every command of the language accepts, as data.
//
// A Command lists its positional items and its keys, each with a type, a unit, an allowed
// range, a default and one line of help. read_args() checks a call against it and converts
// the Lua values to C++ (Args) before the command touches the model; the reference in the
// README is generated from the same data (reference.hpp). Defaults are written as Lua
// literals, so they are shown as a user would write them and checked by the same reader.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/vec2.hpp"
#include "core/defs.hpp"

struct lua_State;

namespace edem {

struct Context;

// What a key or positional item accepts.
enum class Type {
  number,           // a finite number
  integer,          // a finite number with no fractional part
  string,           // a string
  boolean,          // true or false
  point,            // {x, y} or {x = x, y = y}
  pair,             // {a, b}: two numbers
  int_pair,         // {a, b}: two integers
  numbers,          // a number or a non-empty list of numbers
  polygon,          // a list of at least three points, a simple polygon
  region,           // a region's name or a polygon
  regions,          // a region (name or polygon) or a list of them
  strings,          // a string or a list of strings
  function,         // a Lua function
  table,            // a Lua table, read by the command itself (a prepass{} result)
  numbers_or_name,  // a list of numbers, or one of the key's choices: {0, -1e6, 0} or "insitu"
  pairs,            // a non-empty list of pairs of numbers: {{a, b}, {a, b}, ...}
};

inline constexpr Type kAllTypes[] = {
    Type::number,  Type::integer,  Type::string,   Type::boolean,        Type::point,
    Type::pair,    Type::int_pair, Type::numbers,  Type::polygon,        Type::region,
    Type::regions, Type::strings,  Type::function, Type::table,          Type::numbers_or_name,
    Type::pairs};

// A type's name in the reference ("point"), and how a script writes it ("`{x, y}` or ...").
std::string_view type_name(Type type);
std::string_view type_written(Type type);

// An interval of allowed values for numbers (and for each element of lists and pairs).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;  // lo itself is excluded
  bool hi_open = false;  // hi itself is excluded

  bool contains(double value) const;
  bool unbounded() const;
  std::string text() const;  // "> 0", ">= 0", "[-360, 360]", "(0, 0.001]" or ""
};

inline constexpr Range any_value{};
constexpr Range gt(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), true};
}
constexpr Range ge(double lo) {
  return {lo, std::numeric_limits<double>::infinity()};
}
constexpr Range between(double lo, double hi) {
  return {lo, hi};
}
constexpr Range above_upto(double lo, double hi) {
  return {lo, hi, true, false};
}
constexpr Range above_below(double lo, double hi) {
  return {lo, hi, true, true};
}
constexpr Range from_below(double lo, double hi) {
  return {lo, hi, false, true};
}

// A key's default, as a Lua literal ("0", "{0, 0}", "true"); or one of these markers.
inline constexpr std::string_view kRequired = "!required";  // the key must be given
inline constexpr std::string_view kOptional = "";           // may be left out: no value

// The names a string (or each string of a list) may take; the engine owns the list.
using Choices = const std::vector<std::string>& (*)();

struct Key {
  std::string_view name;
  Type type;
  std::string_view unit;         // SI unit ("m", "deg", "Pa"), "-" for ratios, "" for none
  Range range;                   // numbers only
  std::string_view fallback;     // Lua literal, kRequired or kOptional
  std::string_view help;         // one line
  std::string_view absent = {};  // for kOptional: what leaving it out means ("edge")
  Choices choices = nullptr;     // strings and numbers_or_name only
  // A last positional polygon or strings that takes every array item from its position on:
  // block{ {x,y}, {x,y}, ... }, reset{ "velocity", "state" }.
  bool rest = false;

  bool required() const { return fallback == kRequired; }
  bool has_default() const { return !required() && !fallback.empty(); }
};

// f{ ... } takes one table; f(a, b) takes plain positional arguments.
enum class Form { table, call };

struct Args;
using Runner = int (*)(lua_State* L, Context& context, const Args& args);

struct Command {
  std::string_view name;
  std::string_view help;  // one line: what it does
  Form form = Form::table;
  std::vector<Key> positional = {};
  std::vector<Key> keys = {};
  Runner run = nullptr;           // validates nothing: Args are already checked
  std::string_view returns = {};  // what it returns, if anything
  std::string_view usage = {};    // example calls, one a line; generated when empty
  bool bare_call = false;         // table form: f() is accepted as f{}
  bool item_call = false;         // table form: f(x), x not a table, is accepted as f{x}
};

// A Lua function argument: its absolute stack index while the command runs (a function given
// in the call's table is left pushed on the stack for this).
struct FunctionArg {
  int index = 0;
};

// A Lua table argument, kept on the stack the same way.
struct TableArg {
  int index = 0;
};

// Function and table arguments stay pushed while the command runs.
constexpr bool stays_pushed(Type type) { return type == Type::function || type == Type::table; }

using Value = std::variant<double, std::int64_t, std::string, bool, Vec2, std::array<double, 2>,
                           std::array<std::int64_t, 2>, std::vector<double>, Polygon, RegionRef,
                           std::vector<RegionRef>, std::vector<std::string>, FunctionArg,
                           TableArg, std::vector<std::array<double, 2>>>;

// The checked arguments of one call, by key (positional items under their declared names).
// Getters throw std::logic_error when a command asks for what its schema does not give.
struct Args {
  std::map<std::string, Value, std::less<>> values;
  // Values given that are valid but likely not what was meant (an angle in radians, a friction
  // coefficient, a tensile in-situ stress): warnings, said once the command has run.
  std::vector<std::string> doubts;

  bool has(std::string_view key) const { return values.find(key) != values.end(); }
  double number(std::string_view key) const { return get<double>(key); }
  std::int64_t integer(std::string_view key) const { return get<std::int64_t>(key); }
  const std::string& string(std::string_view key) const { return get<std::string>(key); }
  bool boolean(std::string_view key) const { return get<bool>(key); }
  Vec2 point(std::string_view key) const { return get<Vec2>(key); }

  template <typename T>
  const T& get(std::string_view key) const;
  // The value of `key` if it was given with type T, else nullptr (for keys of two types).
  template <typename T>
  const T* find(std::string_view key) const;
};

template <typename T>
const T& Args::get(std::string_view key) const {
  const auto it = values.find(key);
  const T* value = it == values.end() ? nullptr : std::get_if<T>(&it->second);
  if (value == nullptr)
    throw std::logic_error("the command reads key '" + std::string(key) +
                           "' that its schema does not give with that type");
  return *value;
}

template <typename T>
const T* Args::find(std::string_view key) const {
  const auto it = values.find(key);
  return it == values.end() ? nullptr : std::get_if<T>(&it->second);
}

// Checks the arguments of a call (the whole Lua stack) against `command` and converts them.
// `defaults` is the stack index of a table of the command's defaults (key -> Lua value).
// Throws edem::Error naming the offending key and value; reads only, never calls Lua code.
Args read_args(lua_State* L, const Command& command, int defaults);

// Evaluates every default literal of `command` into a new table left on the stack; throws
// std::logic_error if one is not valid Lua or fails the key's own schema (a programming error).
void push_defaults(lua_State* L, const Command& command);

// An example call for messages: the first line of the command's usage, or one made from its
// required keys.
std::string usage_of(const Command& command);

// Formats a number as messages show it: shortest round-trip, "nan", "inf", "-inf".
std::string show_number(double value);

}  // namespace edem
