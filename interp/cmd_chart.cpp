// chart{}: line charts of x-y series (PNG, SVG or PDF), such as error against run time.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <lua.hpp>

#include <algorithm>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "io/chart.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

// The axes `log` may name.
const std::vector<std::string>& chart_axes() {
  static const std::vector<std::string> axes{"x", "y"};
  return axes;
}

// The keys of one series' table.
const std::vector<std::string>& series_keys() {
  static const std::vector<std::string> keys{"name", "x", "y"};
  return keys;
}

constexpr std::string_view kSeriesForm = "{name = \"...\", x = {...}, y = {...}}";

// Puts the Lua stack's top back where it was, also when a reader fails.
class StackGuard {
 public:
  explicit StackGuard(lua_State* L) : L_(L), top_(lua_gettop(L)) {}
  ~StackGuard() { lua_settop(L_, top_); }
  StackGuard(const StackGuard&) = delete;
  StackGuard& operator=(const StackGuard&) = delete;

 private:
  lua_State* L_;
  int top_;
};

// Fails on any key of the series table on top of the stack but name, x and y.
void check_series_keys(lua_State* L, const std::string& path) {
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) != LUA_TSTRING)
      fail("{}: unnamed item {}: a series is {}", path, describe(L, -1), kSeriesForm);
    const std::string key = lua_tostring(L, -1);
    const auto& keys = series_keys();
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      fail("{}: unknown key '{}'{}: a series has name, x and y", path, key,
           did_you_mean(key, keys));
  }
}

// The list of numbers `key` of the series table on top of the stack.
std::vector<double> numbers_field(lua_State* L, const char* key, const std::string& path) {
  const StackGuard guard(L);
  lua_pushstring(L, key);
  lua_rawget(L, -2);
  const std::string name = fmt::format("{}.{}", path, key);
  if (!lua_istable(L, -1)) fail("{} must be a list of numbers, got {}", name, describe(L, -1));
  std::vector<double> values;
  const auto count = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer i = 1; i <= count; ++i) {
    lua_rawgeti(L, -1, i);
    if (lua_type(L, -1) != LUA_TNUMBER)
      fail("{}[{}] must be a number, got {}", name, i, describe(L, -1));
    values.push_back(lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
  return values;
}

// The series of the table at `index`: a list of {name = , x = , y = }. Whether each has points
// of equal count, finite and fit for a logarithmic axis, the engine checks.
std::vector<ChartSeries> read_series(lua_State* L, int index) {
  const StackGuard guard(L);
  const auto count = static_cast<lua_Integer>(lua_rawlen(L, index));
  if (count == 0) {
    lua_pushnil(L);
    if (lua_next(L, index) != 0)
      fail("series must be a list of series, like {{{}}}: one series needs braces of its own",
           kSeriesForm);
    return {};  // the engine says that there is nothing to draw
  }
  std::vector<ChartSeries> series;
  for (lua_Integer i = 1; i <= count; ++i) {
    lua_rawgeti(L, index, i);
    const std::string path = fmt::format("series[{}]", i);
    if (!lua_istable(L, -1))
      fail("{} must be a table {}, got {}", path, kSeriesForm, describe(L, -1));
    check_series_keys(L, path);
    ChartSeries s;
    lua_pushstring(L, "name");
    const int name_type = lua_rawget(L, -2);
    if (name_type != LUA_TNIL && name_type != LUA_TSTRING)
      fail("{}.name must be a string, got {}", path, describe(L, -1));
    if (name_type == LUA_TSTRING) s.name = lua_tostring(L, -1);
    lua_pop(L, 1);
    s.x = numbers_field(L, "x", path);
    s.y = numbers_field(L, "y", path);
    series.push_back(std::move(s));
    lua_pop(L, 1);
  }
  return series;
}

// The recorded histories named, each a series against the cycle: "name [unit]" in the legend.
std::vector<ChartSeries> history_series(const Model& model, const std::vector<std::string>& names) {
  std::vector<ChartSeries> series;
  for (const std::string& name : names) {
    const auto& all = model.histories();
    const auto it = std::find_if(all.begin(), all.end(), [&](const History& h) { return h.name == name; });
    if (it == all.end()) {
      std::vector<std::string> known;
      for (const History& h : all) known.push_back(h.name);
      fail("no history named '{}' ({})", name,
           known.empty() ? std::string("none recorded: history{...} first") : fmt::format("histories: {}", fmt::join(known, ", ")));
    }
    if (it->values.empty()) fail("history '{}' has no samples yet: cycle the model first", name);
    ChartSeries s;
    s.name = it->unit.empty() || it->unit == "-" ? it->name : fmt::format("{} [{}]", it->name, it->unit);
    s.x.assign(it->cycles.begin(), it->cycles.end());
    s.y = it->values;
    series.push_back(std::move(s));
  }
  return series;
}

// The unit the histories share, "[m]", or "" when they differ or have none.
std::string shared_unit(const Model& model, const std::vector<std::string>& names) {
  std::string unit;
  for (const std::string& name : names)
    for (const History& h : model.histories())
      if (h.name == name) {
        if (!unit.empty() && unit != h.unit) return "";
        unit = h.unit;
      }
  return unit.empty() || unit == "-" ? "" : "[" + unit + "]";
}

int run_chart(lua_State* L, Context& context, const Args& args) {
  ChartDef def;
  def.file = context.output_path(args.string("file"));
  if (args.has("title")) def.title = args.string("title");
  if (args.has("x_label")) def.x_label = args.string("x_label");
  if (args.has("y_label")) def.y_label = args.string("y_label");
  if (args.has("log"))
    for (const std::string& axis : args.get<std::vector<std::string>>("log"))
      (axis == "x" ? def.log_x : def.log_y) = true;
  if (!args.has("series") && !args.has("history")) fail("give series = {{...}}, history = \"name\", or both");
  if (args.has("series")) def.series = read_series(L, args.get<TableArg>("series").index);
  if (args.has("history")) {
    const auto& names = args.get<std::vector<std::string>>("history");
    for (ChartSeries& s : history_series(context.model(), names)) def.series.push_back(std::move(s));
    // Against the cycle, the excavation stages are marked where they were dug.
    const std::vector<long>& stages = context.model().stage_cycles();
    for (size_t k = 0; k < stages.size(); ++k)
      def.marks.push_back({static_cast<double>(stages[k]), fmt::format("stage {}", k + 1)});
    if (!args.has("x_label") && !args.has("series")) def.x_label = "cycle";
    if (!args.has("y_label")) def.y_label = shared_unit(context.model(), names);
  }
  const auto size = args.get<std::array<std::int64_t, 2>>("size");
  def.width = static_cast<int>(size[0]);
  def.height = static_cast<int>(size[1]);
  chart(def);
  return 0;
}

}  // namespace

const Command& chart_command() {
  static const Command command{
      .name = "chart",
      .help =
          "Draws x-y series as a line chart (a line through each series' points in order, a "
          "marker at each point, a legend of the names in the corner of the frame that hides the "
          "least data, or above the frame when every corner would hide a point); the file's "
          "extension (.png, .svg or .pdf) picks the format.",
      .keys =
          {
              {"file", Type::string, "", any_value, kRequired, "the picture to write"},
              {"series", Type::table, "", any_value, kOptional,
               "the lines: a list of `{name = \"...\", x = {...}, y = {...}}`, x and y lists of "
               "numbers of the same length (at least one point); name (optional) is shown in the "
               "legend",
               "none; give history"},
              {"history", Type::strings, "", any_value, kOptional,
               "recorded histories (history{}) by name, each a line against the cycle, named with "
               "its unit, the excavation stages marked where they were dug; x_label then defaults to "
               "cycle and y_label to their shared unit",
               "none; give series"},
              {"title", Type::string, "", any_value, kOptional, "the title above the chart",
               "none"},
              {"x_label", Type::string, "", any_value, kOptional, "the label of the x axis",
               "none"},
              {"y_label", Type::string, "", any_value, kOptional, "the label of the y axis",
               "none"},
              {"log", Type::strings, "", any_value, kOptional,
               "the logarithmic axes (their values must be > 0)", "both linear", chart_axes},
              {"size", Type::int_pair, "px", between(kPlotMinSize, kPlotMaxSize), "{1200, 900}",
               "width and height (points for SVG and PDF)"},
          },
      .run = run_chart,
      .usage =
          R"(chart{ file = "speed.png", log = {"x", "y"}, x_label = "run time [s]", series = { {name = "implicit", x = {0.5, 2, 9}, y = {0.02, 0.005, 0.001}} } } or chart{ file = "roof.png", history = {"roof_sag"} })",
  };
  return command;
}

}  // namespace edem
