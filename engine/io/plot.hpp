// Pictures of a scene in metres with cairo: PNG, SVG or PDF chosen by the file's extension.
//
// A scene is plain data: filled polygons, polylines in a pen each, labels, a legend, a title
// and a note. Its box is fitted to the canvas with square metres kept square, y up, the title
// above, the legend right of it or below, whichever leaves it larger, and a scale bar with the
// note under it. model/model_plot.hpp gathers a scene from a model. The file is written to
// FILE.PID.tmp and renamed, so a failed plot never leaves a half-written picture behind.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "geom/polygon.hpp"
#include "io/cairo_file.hpp"
#include "io/canvas.hpp"

namespace edem {

// Polylines stroked together: one cairo path per pen, never one stroke per segment [m].
struct Polylines {
  std::vector<Vec2> points;
  std::vector<std::size_t> starts;  // index in `points` where each polyline begins
  void begin(Vec2 p) {
    starts.push_back(points.size());
    points.push_back(p);
  }
  void add(Vec2 p) { points.push_back(p); }
  bool empty() const { return starts.empty(); }
};

struct Scene {
  // Polygons filled in one colour as one path, and outlined [m].
  struct Fill {
    std::vector<Polygon> polygons;
    Rgb colour;
    double opacity = 1.0;
    Pen outline;
  };
  struct Lines {
    Polylines lines;
    Pen pen;
    // Many thin segments (zones): filled as quads on a raster surface, which is faster.
    bool hairlines = false;
  };
  // A name over its area, with a halo; left out when much larger than the area on the canvas.
  struct Label {
    std::string text;
    Vec2 at;     // the label's centre [m]
    Box extent;  // of what it names [m]
  };

  std::string title;  // "" for none
  Box box{};          // the part of the plane drawn, fitted to the canvas [m]
  // Drawn in this order, clipped to the box: fills, lines, then labels.
  std::vector<Fill> fills;
  std::vector<Lines> lines;
  std::vector<Label> labels;
  std::vector<LegendEntry> legend;
  std::string note;  // right of the scale bar, when there is room
  bool axes = false;  // coordinates [m] ticked along the scene's bottom and left edges
};

// Draws the scene to `file`, width x height px (points for SVG and PDF). Throws edem::Error,
// leaving no file, for an unknown extension, a size out of range or a file that cannot be
// written.
void plot_scene(const Scene& scene, const std::string& file, int width, int height);

}  // namespace edem
