// plot{}: pictures of the model (PNG, SVG or PDF).
#include <lua.hpp>

#include "commands.hpp"
#include "context.hpp"
#include "io/plot.hpp"

namespace edem {
namespace {

int run_plot(lua_State*, Context& context, const Args& args) {
  PlotDef def;
  def.file = context.output_path(args.string("file"));
  def.show = args.get<std::vector<std::string>>("show");
  const auto size = args.get<std::array<std::int64_t, 2>>("size");
  def.width = static_cast<int>(size[0]);
  def.height = static_cast<int>(size[1]);
  plot(context.model(), def);
  return 0;
}

}  // namespace

const Command& plot_command() {
  static const Command command{
      .name = "plot",
      .help =
          "Draws the model to a picture; the file's extension (.png, .svg or .pdf) picks the "
          "format.",
      .keys =
          {
              {"file", Type::string, "", any_value, kRequired, "the picture to write"},
              {"show",
               Type::strings,
               "",
               any_value,
               R"({"blocks", "joints"})",
               "layers to draw, in any order: regions (named regions, filled), plastic (zones that "
               "have yielded in the run, now or earlier: shear orange, tension blue, both purple), "
               "prepass (the same for the last prepass{}, over all its stages), zones (triangle "
               "edges), blocks (outlines), joints (edges by origin: joint sets coloured, crack{} "
               "traces red, region outlines, potential cracks dotted, the boundary thick), cracks "
               "(crack{} traces, and the new cracks as their sections: tension red, shear blue, "
               "counted in the legend)",
               {},
               plot_layers},
              {"size", Type::int_pair, "px", between(kPlotMinSize, kPlotMaxSize), "{1200, 900}",
               "width and height (points for SVG and PDF)"},
          },
      .run = run_plot,
      .usage = R"(plot{ file = "model.png", show = {"blocks", "joints"} })",
  };
  return command;
}

}  // namespace edem
