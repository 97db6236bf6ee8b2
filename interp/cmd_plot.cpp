// plot{}: pictures of the model (PNG, SVG or PDF).
#include <array>
#include <lua.hpp>
#include <vector>

#include "commands.hpp"
#include "core/error.hpp"
#include "context.hpp"
#include "model/model_plot.hpp"

namespace edem {
namespace {

const std::vector<std::string>& plot_vectors() {
  static const std::vector<std::string> names{"displacement"};
  return names;
}

int run_plot(lua_State*, Context& context, const Args& args) {
  PlotDef def;
  def.file = context.output_path(args.string("file"));
  def.show = args.get<std::vector<std::string>>("show");
  const auto size = args.get<std::array<std::int64_t, 2>>("size");
  def.width = static_cast<int>(size[0]);
  def.height = static_cast<int>(size[1]);
  if (args.has("window")) {
    const auto& w = args.get<std::vector<double>>("window");
    if (w.size() != 4) fail("window must be four numbers {{x0, x1, y0, y1}}, got {}", w.size());
    def.window = std::array<double, 4>{w[0], w[1], w[2], w[3]};
  }
  if (args.has("colour")) def.colour = args.string("colour");
  if (args.has("range")) {
    const auto& r = args.get<std::array<double, 2>>("range");
    def.range = std::array<double, 2>{r[0], r[1]};
  }
  def.bands = static_cast<int>(args.integer("bands"));
  if (args.has("title")) def.title = args.string("title");
  if (args.has("vectors")) def.vectors = args.string("vectors");
  def.axes = args.boolean("axes");
  def.deform = args.number("deform");
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
               "counted in the legend), stress (principal stress ticks at zone centroids, length in "
               "proportion to magnitude: compression dark, tension red), bolts (segments where they are "
               "now: tension red, compression blue, out of service grey dashed; largest forces in the "
               "legend)",
               {},
               plot_layers},
              {"colour", Type::string, "", any_value, kOptional,
               "fill the zones in place by a quantity in equal bands (bands, range) listed in the legend in one unit, as a contour "
               "plot: zone stresses sxx, syy, sxy, szz, s1, s3 [Pa] or displacements ux, uy, u (magnitude) "
               "[m], the mean of each zone's corners",
               "none", plot_colours},
              {"range", Type::pair, "", any_value, kOptional,
               "{lo, hi}: the colour bands' range, in the quantity's unit (Pa or m), fixed so that "
               "pictures compare; values beyond it take the end bands",
               "from the least to the largest value in place"},
              {"bands", Type::integer, "", between(2, 16), "8", "the number of colour bands"},
              {"title", Type::string, "", any_value, kOptional, "the picture's title", "the model's title"},
              {"vectors", Type::string, "", any_value, kOptional,
               "\"displacement\": arrows of the zones' displacement (their corners' mean) on a grid of about 30 "
               "cells across the model, the largest a cell long and named in the legend",
               "none", plot_vectors},
              {"deform", Type::number, "-", ge(0), "0",
               "draw the zones where they are with their displacements magnified this many times (the blocks "
               "as their zones' outer edges); only with the zones' layers (regions, plastic, prepass, zones, "
               "blocks, colour, vectors); 0: where they were made"},
              {"axes", Type::boolean, "", any_value, "false",
               "coordinates [m] ticked along the bottom and left edges of the model"},
              {"size", Type::int_pair, "px", between(kPlotMinSize, kPlotMaxSize), "{1200, 900}",
               "width and height (points for SVG and PDF)"},
              {"window", Type::numbers, "m", any_value, kOptional,
               "{x0, x1, y0, y1}: draw only this part, fitted to the picture (a cavern's wall, a "
               "crack's tip)",
               "the whole model"},
          },
      .run = run_plot,
      .usage = R"(plot{ file = "model.png", show = {"blocks", "joints"} } or plot{ file = "wall.png", show = {"zones", "cracks"}, window = {-20, -4, -20, -2} } or plot{ file = "uy.png", show = {"blocks", "bolts"}, colour = "uy" })",
  };
  return command;
}

}  // namespace edem
