// Reading a call against its command's schema: types, ranges, unknown keys, defaults.
//
// Every reader reads raw (no metamethods run) and leaves the Lua stack as it found it, but for
// a function or table given inside the call's table: it stays pushed, above the call's arguments,
// so that its FunctionArg or TableArg index is valid while the command runs. A failed check has no effect
// anywhere. Messages name the key as the user wrote it
// ("spacing[2] must be > 0, got 0").
#include "schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <lua.hpp>

#include "core/error.hpp"
#include "core/names.hpp"
#include "geom/polygon.hpp"
#include "lua_util.hpp"

namespace edem {

// --- types and ranges ------------------------------------------------------------------

namespace {

struct TypeText {
  std::string_view name;     // in the reference
  std::string_view phrase;   // in messages: "must be <phrase>"
  std::string_view written;  // in the reference: how a script writes it
};

TypeText type_text(Type type) {
  switch (type) {
    case Type::number:
      return {"number", "a number", "`2.5`, `-1e6`; NaN and infinity are rejected"};
    case Type::integer:
      return {"integer", "an integer", "`3`"};
    case Type::string:
      return {"string", "a string", "`\"roof\"`"};
    case Type::boolean:
      return {"boolean", "true or false", "`true` or `false`"};
    case Type::point:
      return {"point", "a point {x, y}", "`{x, y}` or `{x = 1, y = 2}`"};
    case Type::pair:
      return {"pair", "a pair of numbers {a, b}", "`{a, b}`"};
    case Type::int_pair:
      return {"integer pair", "a pair of integers {a, b}", "`{800, 600}`"};
    case Type::numbers:
      return {"number or list", "a number or a list of numbers", "`4` or `{4, 2, 2}`"};
    case Type::polygon:
      return {"polygon", "a polygon {{x, y}, {x, y}, ...}",
              "`{{x, y}, {x, y}, {x, y}, ...}`: three or more corners, no repeated corner, edges "
              "that do not cross"};
    case Type::region:
      return {"region", "a region name or a polygon",
              "a region's name, `\"stage1\"`, or a polygon"};
    case Type::regions:
      return {"region or list", "a region (name or polygon) or a list of them",
              "a region, or a list of them: `{\"stage1\", \"stage2\"}`"};
    case Type::strings:
      return {"string or list", "a string or a list of strings",
              "`\"blocks\"` or `{\"blocks\", \"zones\"}`"};
    case Type::function:
      return {"function", "a function", "`function(x) ... end`"};
    case Type::table:
      return {"table", "a table", "a table, as a command returned it: `pre` from `local pre = prepass{...}`"};
    case Type::pairs:
      return {"list of pairs", "a list of pairs of numbers {{a, b}, ...}",
              "`{{0, 2.6e8}, {5e-5, 9.4e8}}`: one or more pairs"};
    case Type::numbers_or_name:
      return {"numbers or name", "a list of numbers or a name",
              "`{0, -1e6, 0}` or one of the names listed, `\"insitu\"`"};
  }
  return {"?", "?", "?"};
}

}  // namespace

std::string_view type_name(Type type) {
  return type_text(type).name;
}
std::string_view type_written(Type type) {
  return type_text(type).written;
}

std::string show_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{}", value);
}

bool Range::contains(double value) const {
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

bool Range::unbounded() const {
  return std::isinf(lo) && std::isinf(hi);
}

std::string Range::text() const {
  if (unbounded()) return {};
  if (std::isinf(hi)) return fmt::format("{} {}", lo_open ? ">" : ">=", show_number(lo));
  if (std::isinf(lo)) return fmt::format("{} {}", hi_open ? "<" : "<=", show_number(hi));
  return fmt::format("{}{}, {}{}", lo_open ? "(" : "[", show_number(lo), show_number(hi),
                     hi_open ? ")" : "]");
}

// --- reading one value -----------------------------------------------------------------

namespace {

[[noreturn]] void wrong_type(lua_State* L, int index, std::string_view path, Type type) {
  fail("{} must be {}, got {}", path, type_text(type).phrase, describe(L, index));
}

void check_range(double value, std::string_view path, const Range& range) {
  if (range.contains(value)) return;
  const bool interval = !std::isinf(range.lo) && !std::isinf(range.hi);
  fail("{} must be {}{}, got {}", path, interval ? "in " : "", range.text(), show_number(value));
}

double read_number(lua_State* L, int index, std::string_view path, const Range& range) {
  if (lua_type(L, index) != LUA_TNUMBER) wrong_type(L, index, path, Type::number);
  const double value = lua_tonumber(L, index);
  if (!std::isfinite(value)) fail("{} must be a finite number, got {}", path, show_number(value));
  check_range(value, path, range);
  return value;
}

std::int64_t read_integer(lua_State* L, int index, std::string_view path, const Range& range) {
  if (lua_type(L, index) != LUA_TNUMBER) wrong_type(L, index, path, Type::integer);
  if (lua_isinteger(L, index)) {
    const auto value = static_cast<std::int64_t>(lua_tointeger(L, index));
    check_range(static_cast<double>(value), path, range);
    return value;
  }
  const double value = lua_tonumber(L, index);
  // 2^63 bounds the values an int64 holds exactly.
  if (!std::isfinite(value) || std::floor(value) != value || std::fabs(value) >= 0x1p63)
    fail("{} must be an integer, got {}", path, show_number(value));
  check_range(value, path, range);
  return static_cast<std::int64_t>(value);
}

std::string read_string(lua_State* L, int index, std::string_view path, Choices choices) {
  if (lua_type(L, index) != LUA_TSTRING) wrong_type(L, index, path, Type::string);
  size_t length = 0;
  const char* text = lua_tolstring(L, index, &length);
  std::string value(text, length);
  if (choices == nullptr) return value;
  const auto& names = choices();
  if (std::find(names.begin(), names.end(), value) != names.end()) return value;
  fail("{} must be one of {}, got \"{}\"{}", path, fmt::join(names, ", "), value,
       did_you_mean(value, names));
}

// Entries of the table at `index` that are not its sequence 1..#t; lists must have none.
int extra_entries(lua_State* L, int index) {
  const auto length = static_cast<lua_Integer>(lua_rawlen(L, index));
  int extra = 0;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    const bool in_sequence =
        lua_isinteger(L, -2) && lua_tointeger(L, -2) >= 1 && lua_tointeger(L, -2) <= length;
    if (!in_sequence) ++extra;
    lua_pop(L, 1);
  }
  return extra;
}

// The length of the list at `index`; fails if it is not a table or has other keys.
int list_length(lua_State* L, int index, std::string_view path, Type type) {
  if (!lua_istable(L, index)) wrong_type(L, index, path, type);
  if (extra_entries(L, index) != 0)
    fail("{} must be {}: a list with items 1..n and no other keys", path, type_text(type).phrase);
  return static_cast<int>(lua_rawlen(L, index));
}

std::string item_path(std::string_view path, int i) {
  return fmt::format("{}[{}]", path, i);
}

// Reads t[i] of the table at `index` with `read`, keeping the stack balanced.
template <typename Read>
auto read_item(lua_State* L, int index, int i, Read&& read) {
  lua_rawgeti(L, index, i);
  auto value = read(lua_gettop(L));
  lua_pop(L, 1);
  return value;
}

template <typename Read>
auto read_named(lua_State* L, int index, const char* key, Read&& read) {
  lua_pushstring(L, key);
  lua_rawget(L, index);
  auto value = read(lua_gettop(L));
  lua_pop(L, 1);
  return value;
}

Vec2 read_point(lua_State* L, int index, std::string_view path) {
  if (!lua_istable(L, index)) wrong_type(L, index, path, Type::point);
  // {x, y} or {x = , y = }; points handed out by queries carry both, which is accepted.
  bool named = false;
  int count = 0;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    ++count;
    if (lua_type(L, -2) == LUA_TSTRING) {
      const std::string_view key = lua_tostring(L, -2);
      if (key != "x" && key != "y") {
        lua_pop(L, 2);
        fail("{} must be a point {{x, y}}: unexpected key '{}'", path, key);
      }
      named = true;
    }
    lua_pop(L, 1);
  }
  if (named) {
    const auto coordinate = [&](const char* axis) {
      return read_named(L, index, axis, [&](int top) {
        return read_number(L, top, fmt::format("{}.{}", path, axis), any_value);
      });
    };
    return {coordinate("x"), coordinate("y")};
  }
  if (count != 2 || lua_rawlen(L, index) != 2)
    fail("{} must be a point {{x, y}}, got a table with {} item{}", path, count,
         count == 1 ? "" : "s");
  const auto coordinate = [&](int i) {
    return read_item(L, index, i,
                     [&](int top) { return read_number(L, top, item_path(path, i), any_value); });
  };
  return {coordinate(1), coordinate(2)};
}

template <typename T, typename Read>
std::array<T, 2> read_pair(lua_State* L, int index, std::string_view path, Type type, Read&& read) {
  const int length = list_length(L, index, path, type);
  if (length != 2)
    fail("{} must be {}, got {} item{}", path, type_text(type).phrase, length,
         length == 1 ? "" : "s");
  return {read_item(L, index, 1, [&](int top) { return read(top, item_path(path, 1)); }),
          read_item(L, index, 2, [&](int top) { return read(top, item_path(path, 2)); })};
}

std::vector<double> read_numbers(lua_State* L, int index, std::string_view path,
                                 const Range& range) {
  if (lua_type(L, index) == LUA_TNUMBER) return {read_number(L, index, path, range)};
  const int length = list_length(L, index, path, Type::numbers);
  if (length == 0) fail("{} must not be an empty list", path);
  std::vector<double> values;
  for (int i = 1; i <= length; ++i)
    values.push_back(read_item(
        L, index, i, [&](int top) { return read_number(L, top, item_path(path, i), range); }));
  return values;
}

// The points of a polygon: items first..last of the list at `index`, each named by `name_of`.
template <typename Name>
Polygon read_points(lua_State* L, int index, int first, int last, std::string_view what,
                    Name&& name_of) {
  Polygon polygon;
  for (int i = first; i <= last; ++i)
    polygon.push_back(
        read_item(L, index, i, [&](int top) { return read_point(L, top, name_of(i)); }));
  validate_polygon(polygon, what);
  return polygon;
}

Polygon read_polygon(lua_State* L, int index, std::string_view path) {
  const int length = list_length(L, index, path, Type::polygon);
  return read_points(L, index, 1, length, path, [&](int i) { return item_path(path, i); });
}

RegionRef read_region(lua_State* L, int index, std::string_view path) {
  RegionRef ref;
  if (lua_type(L, index) == LUA_TSTRING) {
    ref.name = read_string(L, index, path, nullptr);
    if (ref.name.empty()) fail("{} must name a region, got an empty string", path);
  } else if (lua_istable(L, index)) {
    ref.polygon = read_polygon(L, index, path);
  } else {
    wrong_type(L, index, path, Type::region);
  }
  return ref;
}

// A table whose first item is a point is one polygon, not a list of regions.
bool is_one_polygon(lua_State* L, int index) {
  lua_rawgeti(L, index, 1);
  bool point = false;
  if (lua_istable(L, -1)) {
    lua_rawgeti(L, -1, 1);
    lua_pushstring(L, "x");
    lua_rawget(L, -3);
    point = lua_type(L, -2) == LUA_TNUMBER || lua_type(L, -1) == LUA_TNUMBER;
    lua_pop(L, 2);
  }
  lua_pop(L, 1);
  return point;
}

std::vector<RegionRef> read_regions(lua_State* L, int index, std::string_view path) {
  if (!lua_istable(L, index) || is_one_polygon(L, index)) return {read_region(L, index, path)};
  const int length = list_length(L, index, path, Type::regions);
  std::vector<RegionRef> refs;
  for (int i = 1; i <= length; ++i)
    refs.push_back(
        read_item(L, index, i, [&](int top) { return read_region(L, top, item_path(path, i)); }));
  return refs;
}

std::vector<std::string> read_strings(lua_State* L, int index, std::string_view path,
                                      Choices choices) {
  if (lua_type(L, index) == LUA_TSTRING) return {read_string(L, index, path, choices)};
  const int length = list_length(L, index, path, Type::strings);
  std::vector<std::string> values;
  for (int i = 1; i <= length; ++i)
    values.push_back(read_item(
        L, index, i, [&](int top) { return read_string(L, top, item_path(path, i), choices); }));
  return values;
}

Value read_value(lua_State* L, int index, const Key& key, std::string_view path) {
  switch (key.type) {
    case Type::number:
      return read_number(L, index, path, key.range);
    case Type::integer:
      return read_integer(L, index, path, key.range);
    case Type::string:
      return read_string(L, index, path, key.choices);
    case Type::boolean:
      if (!lua_isboolean(L, index)) wrong_type(L, index, path, key.type);
      return lua_toboolean(L, index) != 0;
    case Type::point:
      return read_point(L, index, path);
    case Type::pair:
      return read_pair<double>(L, index, path, key.type, [&](int top, const std::string& item) {
        return read_number(L, top, item, key.range);
      });
    case Type::int_pair:
      return read_pair<std::int64_t>(
          L, index, path, key.type,
          [&](int top, const std::string& item) { return read_integer(L, top, item, key.range); });
    case Type::numbers:
      return read_numbers(L, index, path, key.range);
    case Type::polygon:
      return read_polygon(L, index, path);
    case Type::region:
      return read_region(L, index, path);
    case Type::regions:
      return read_regions(L, index, path);
    case Type::strings:
      return read_strings(L, index, path, key.choices);
    case Type::function:
      if (!lua_isfunction(L, index)) wrong_type(L, index, path, key.type);
      return FunctionArg{lua_absindex(L, index)};
    case Type::table:
      if (!lua_istable(L, index)) wrong_type(L, index, path, key.type);
      return TableArg{lua_absindex(L, index)};
    case Type::pairs: {
      const int length = list_length(L, index, path, Type::pairs);
      if (length == 0) fail("{} must not be an empty list", path);
      std::vector<std::array<double, 2>> pairs;
      for (int i = 1; i <= length; ++i)
        pairs.push_back(read_item(L, index, i, [&](int top) {
          const std::string item = item_path(path, i);
          return read_pair<double>(L, top, item, Type::pair, [&](int inner, const std::string& name) {
            return read_number(L, inner, name, key.range);
          });
        }));
      return pairs;
    }
    case Type::numbers_or_name:
      if (lua_type(L, index) == LUA_TSTRING) return read_string(L, index, path, key.choices);
      if (!lua_istable(L, index)) wrong_type(L, index, path, key.type);
      return read_numbers(L, index, path, key.range);
  }
  throw std::logic_error("unhandled schema type");
}

// --- reading a call --------------------------------------------------------------------

std::vector<std::string> key_names(const Command& command) {
  std::vector<std::string> names;
  for (const Key& key : command.keys) names.emplace_back(key.name);
  return names;
}

const Key* find_key(const std::vector<Key>& keys, std::string_view name) {
  for (const Key& key : keys)
    if (key.name == name) return &key;
  return nullptr;
}

[[noreturn]] void unknown_key(const Command& command, const std::string& name) {
  const auto names = key_names(command);
  const std::string hint = did_you_mean(name, names);
  if (!hint.empty()) fail("unknown key '{}'{}", name, hint);
  if (names.empty()) fail("unknown key '{}': {} takes no keys", name, command.name);
  fail("unknown key '{}' (keys: {})", name, fmt::join(names, ", "));
}

const Key* rest_key(const Command& command) {
  for (const Key& key : command.positional)
    if (key.rest) return &key;
  return nullptr;
}

// Items 1..#t of the call's table, by their declared positions.
void read_table_items(lua_State* L, const Command& command, int table, Args& args) {
  const int length = static_cast<int>(lua_rawlen(L, table));
  const int declared = static_cast<int>(command.positional.size());
  const Key* rest = rest_key(command);
  if (rest == nullptr && length > declared) {
    if (declared == 0) {
      const std::string first = read_item(L, table, 1, [&](int top) { return describe(L, top); });
      fail("unexpected positional item #1 ({}): {} takes only named keys, like {}", first,
           command.name, usage_of(command));
    }
    fail("too many positional items: {} takes {}, got {}", command.name, declared, length);
  }
  for (int i = 1; i <= std::min(length, declared); ++i) {
    const Key& key = command.positional[static_cast<size_t>(i - 1)];
    if (&key == rest) {
      const auto name_of = [](int item) { return fmt::format("item #{}", item); };
      if (key.type == Type::polygon) {
        args.values[std::string(key.name)] = read_points(L, table, i, length, key.name, name_of);
      } else {
        std::vector<std::string> items;
        for (int item = i; item <= length; ++item)
          items.push_back(read_item(L, table, item, [&](int top) {
            return read_string(L, top, name_of(item), key.choices);
          }));
        args.values[std::string(key.name)] = std::move(items);
      }
      return;
    }
    lua_rawgeti(L, table, i);
    args.values[std::string(key.name)] =
        read_value(L, lua_gettop(L), key, fmt::format("item #{} ({})", i, key.name));
    if (!stays_pushed(key.type)) lua_pop(L, 1);  // a function or table stays: see the top
  }
}

// Every string key must be declared; integer keys must be items 1..#t without holes.
void check_table_keys(lua_State* L, const Command& command, int table) {
  const auto length = static_cast<lua_Integer>(lua_rawlen(L, table));
  lua_pushnil(L);
  while (lua_next(L, table) != 0) {
    lua_pop(L, 1);  // only the key matters
    if (lua_type(L, -1) == LUA_TSTRING) {
      const std::string name = lua_tostring(L, -1);
      if (find_key(command.keys, name) != nullptr) continue;
      lua_pop(L, 1);
      unknown_key(command, name);
    }
    if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= length)
      continue;
    const std::string key = describe(L, -1);
    const bool integer = lua_isinteger(L, -1);
    lua_pop(L, 1);
    if (integer)
      fail("item [{}] is out of sequence: positional items are 1, 2, ... without holes", key);
    fail("unexpected key [{}]: keys are names like {}", key, usage_of(command));
  }
}

void read_table(lua_State* L, const Command& command, Args& args) {
  if (lua_gettop(L) == 0 && command.bare_call) lua_newtable(L);
  if (lua_gettop(L) == 1 && !lua_istable(L, 1) && command.item_call) {
    lua_createtable(L, 1, 0);
    lua_pushvalue(L, 1);
    lua_rawseti(L, -2, 1);
    lua_replace(L, 1);
  }
  const int count = lua_gettop(L);
  if (count != 1 || !lua_istable(L, 1)) {
    if (count == 0) fail("expects a table, like {}", usage_of(command));
    if (count > 1) fail("expects one table, like {}, got {} arguments", usage_of(command), count);
    fail("expects a table, like {}, got {}", usage_of(command), describe(L, 1));
  }
  check_table_keys(L, command, 1);
  read_table_items(L, command, 1, args);
  for (const Key& key : command.keys) {
    const std::string name(key.name);
    lua_pushstring(L, name.c_str());
    const bool given = lua_rawget(L, 1) != LUA_TNIL;
    if (given) args.values[name] = read_value(L, lua_gettop(L), key, name);
    if (!given || !stays_pushed(key.type)) lua_pop(L, 1);  // a function or table stays: see the top
  }
}

void read_call(lua_State* L, const Command& command, Args& args) {
  const int count = lua_gettop(L);
  const int declared = static_cast<int>(command.positional.size());
  if (count > declared) {
    if (declared == 0) fail("takes no arguments, got {}", count);
    fail("takes {} argument{}, got {}", declared, declared == 1 ? "" : "s", count);
  }
  for (int i = 1; i <= count; ++i) {
    const Key& key = command.positional[static_cast<size_t>(i - 1)];
    if (!lua_isnil(L, i))
      args.values[std::string(key.name)] =
          read_value(L, i, key, fmt::format("argument #{} ({})", i, key.name));
  }
}

// Defaults for what was left out; what is required and left out is an error.
void complete(lua_State* L, const Command& command, int defaults, Args& args) {
  const auto fill = [&](const Key& key, const std::string& missing) {
    const std::string name(key.name);
    if (args.has(name)) return;
    if (key.required()) fail("{}", missing);
    if (!key.has_default()) return;
    lua_getfield(L, defaults, name.c_str());
    args.values[name] = read_value(L, lua_gettop(L), key, name);
    lua_pop(L, 1);
  };
  const bool table = command.form == Form::table;
  for (size_t i = 0; i < command.positional.size(); ++i) {
    const Key& key = command.positional[i];
    fill(key, fmt::format("missing {} #{} ({}), like {}", table ? "item" : "argument", i + 1,
                          key.name, usage_of(command)));
  }
  for (const Key& key : command.keys) fill(key, fmt::format("missing required key '{}'", key.name));
}

}  // namespace

std::string usage_of(const Command& command) {
  if (!command.usage.empty()) return std::string(command.usage.substr(0, command.usage.find('\n')));
  std::vector<std::string> parts;
  for (const Key& key : command.positional) {
    if (!key.rest)
      parts.emplace_back(key.name);
    else
      parts.emplace_back(key.type == Type::polygon ? "{x, y}, {x, y}, ..." : "...");
  }
  bool optional = false;
  for (const Key& key : command.keys) {
    if (key.required())
      parts.push_back(fmt::format("{} = ...", key.name));
    else
      optional = true;
  }
  if (optional) parts.push_back("...");
  if (command.form == Form::call)
    return fmt::format("{}({})", command.name, fmt::join(parts, ", "));
  if (parts.empty()) return fmt::format("{}{{}}", command.name);
  return fmt::format("{}{{ {} }}", command.name, fmt::join(parts, ", "));
}

namespace {

// An angle in degrees that reads as radians: within one turn of radians and not a whole or
// half degree (pi / 6 is 0.5236; 1.5 deg or 2 deg are not doubted).
bool looks_like_radians(double deg) {
  const double a = std::fabs(deg);
  return a > 0.0 && a <= 2.0 * M_PI + 1e-9 && std::fabs(2.0 * a - std::round(2.0 * a)) > 1e-9;
}

// The doubts about the values given (not the defaults), read before the defaults fill in.
std::vector<std::string> doubts_of(const Command& command, const Args& given) {
  std::vector<std::string> doubts;
  const auto numbers_of = [](const Value& value) {
    if (const double* v = std::get_if<double>(&value)) return std::vector<double>{*v};
    if (const auto* v = std::get_if<std::vector<double>>(&value)) return *v;
    return std::vector<double>{};
  };
  for (const auto* keys : {&command.positional, &command.keys})
    for (const Key& key : *keys) {
      const auto it = given.values.find(key.name);
      if (it == given.values.end()) continue;
      for (const double v : numbers_of(it->second)) {
        if (key.unit == "deg" && key.name.find("friction") != std::string_view::npos) {
          if (v > 0.0 && v < 1.5 && looks_like_radians(v))
            doubts.push_back(fmt::format("{} = {:.6g} is an angle in degrees; as a coefficient (tan phi) it would "
                                         "be {:.3g} deg",
                                         key.name, v, std::atan(v) * 180.0 / M_PI));
        } else if (key.unit == "deg" && looks_like_radians(v)) {
          doubts.push_back(
              fmt::format("{} = {:.6g} is in degrees; it looks like radians ({:.4g} deg)", key.name, v, v * 180.0 / M_PI));
        }
        if (command.name == "insitu" && (key.name == "sxx" || key.name == "syy" || key.name == "szz") && v > 0.0)
          doubts.push_back(fmt::format("{} = {:.6g} Pa is tension (compression is negative): rock at depth is in "
                                       "compression, {} = {:.6g}?",
                                       key.name, v, key.name, -v));
      }
    }
  return doubts;
}

}  // namespace

Args read_args(lua_State* L, const Command& command, int defaults) {
  defaults = lua_absindex(L, defaults);
  Args args;
  if (command.form == Form::table)
    read_table(L, command, args);
  else
    read_call(L, command, args);
  args.doubts = doubts_of(command, args);
  complete(L, command, defaults, args);
  return args;
}

void push_defaults(lua_State* L, const Command& command) {
  lua_newtable(L);
  const int table = lua_gettop(L);
  const auto add = [&](const Key& key) {
    if (!key.has_default()) return;
    const std::string code = fmt::format("return {}", key.fallback);
    const std::string name = fmt::format("{}.{}", command.name, key.name);
    if (luaL_loadbuffer(L, code.data(), code.size(), "=default") != LUA_OK ||
        lua_pcall(L, 0, 1, 0) != LUA_OK) {
      const std::string message = lua_tostring(L, -1);
      lua_pop(L, 1);
      throw std::logic_error(fmt::format("default of {} is not Lua: {}", name, message));
    }
    try {
      read_value(L, lua_gettop(L), key, key.name);
    } catch (const Error& e) {
      // A default that fails its own key's schema is a bug in the schema, not user input.
      lua_pop(L, 1);
      throw std::logic_error(fmt::format("default of {} is invalid: {}", name, e.what()));
    }
    lua_setfield(L, table, std::string(key.name).c_str());
  };
  for (const Key& key : command.positional) add(key);
  for (const Key& key : command.keys) add(key);
}

}  // namespace edem
