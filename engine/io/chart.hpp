// Line charts with cairo: x-y series to PNG, SVG or PDF chosen by the file's extension.
//
// Each series is a line through its points in the order given, with a marker at each point,
// in a colour (and marker shape) of its own. Axes are linear or logarithmic, with ticks at
// round values, a light grid at the labelled ones and the data's range padded a little; a
// legend of the series' names sits in the corner of the chart that hides the least data. No
// model is needed: the numbers come from the caller. Like plot(), the file is written to
// FILE.PID.tmp and renamed, so a failed chart never leaves a half-written picture behind.
#pragma once

#include <string>
#include <vector>

#include "io/cairo_file.hpp"  // kPlotMinSize, kPlotMaxSize

namespace edem {

struct ChartSeries {
  std::string name;          // in the legend and in messages; "" leaves it out of the legend
  std::vector<double> x, y;  // the points, drawn in this order; the same length, at least 1
};

// A vertical line across the chart at x, labelled at its top (an excavation stage).
struct ChartMark {
  double x = 0.0;
  std::string label;
};

struct ChartDef {
  std::string file;              // .png, .svg or .pdf (any case)
  std::string title;             // above the chart; "" for none
  std::string x_label, y_label;  // under the x axis and left of the y axis; "" for none
  bool log_x = false;            // logarithmic x axis: every x must be > 0
  bool log_y = false;            // logarithmic y axis: every y must be > 0
  std::vector<ChartSeries> series;
  std::vector<ChartMark> marks;  // those within the x axis' range are drawn, dashed
  int width = 1200;  // [px] (points for SVG/PDF), kPlotMinSize to kPlotMaxSize
  int height = 900;  // [px]
};

// Draws the chart. Throws edem::Error, leaving no file, for an unknown extension, a size out
// of range, no series, a series without points or with x and y of different lengths, a value
// that is not finite or not > 0 on a logarithmic axis, or a file that cannot be written.
void chart(const ChartDef& def);

}  // namespace edem
