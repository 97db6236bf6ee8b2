// Pictures of a model, as plot{} draws them: the layers asked for, gathered from the model into
// a scene that io/plot.hpp draws to PNG, SVG or PDF, chosen by the file's extension.
//
// The model's extent (or a window) is fitted to the canvas with square metres kept square, y up,
// a title, a legend of the edge styles and new cracks drawn, and a scale bar. The file is written
// to FILE.PID.tmp and renamed, so a failed plot never leaves a half-written picture behind.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "io/cairo_file.hpp"  // kPlotMinSize, kPlotMaxSize
#include "io/plot.hpp"

namespace edem {

class Model;

struct PlotDef {
  std::string file;                                   // .png, .svg or .pdf (any case)
  std::vector<std::string> show{"blocks", "joints"};  // any of plot_layers()
  int width = 1200;  // [px] (points for SVG/PDF), kPlotMinSize to kPlotMaxSize
  int height = 900;  // [px]
  // {x0, x1, y0, y1} [m]: draw only this part of the model, fitted to the canvas; none: all of it
  std::optional<std::array<double, 4>> window;
  // Zones in place filled by this quantity in `bands` equal bands, with the bands in the legend
  // (as UDEC's contour plots): any of plot_colours(); "": none.
  std::string colour;
  // The bands' range [Pa or m]: fixed, so that two pictures compare; values beyond it take the end
  // bands. None: from the least to the largest value in place.
  std::optional<std::array<double, 2>> range;
  int bands = 8;       // 2 to 16
  std::string title;   // "": the model's title
  // "displacement": arrows of the zones' displacement on a grid of about 30 cells across the
  // model, the largest a cell long; "": none.
  std::string vectors;
  bool axes = false;   // coordinates [m] along the bottom and left edges
  // > 0: the zones drawn where they are, their displacements magnified this many times (the
  // blocks as their zones' outer edges); only the layers of zones (regions, plastic, prepass,
  // zones, blocks, a colour, vectors) can be drawn so. 0: where they were made.
  double deform = 0.0;
};

// The layer names `show` accepts, in drawing order:
//   regions  light fill and name of each named region
//   plastic  zones that have yielded in the model's run (now or earlier), filled: shear orange,
//            tension blue, both purple, with counts in the legend
//   prepass  the same for the last prepass{}, over all its stages (the seed's Figure 8)
//   zones    triangle edges
//   blocks   block outlines, one neutral style
//   joints   block edges by origin: joints coloured by set, cracks red, region outlines
//            (dashed when glued), potential cracks dotted, the boundary thick
//   cracks   the crack{} edges, red, and the new cracks (broken potential-crack sections),
//            each its section, thick: tension red, shear blue, with counts in the legend
//   stress   principal stress ticks at zone centroids, along each principal direction, length
//            in proportion to its magnitude: compression dark, tension red
//   bolts    bolt segments where they are now, coloured by axial force: tension red,
//            compression blue, out of service grey; the largest forces in the legend
const std::vector<std::string>& plot_layers();

// The quantities `colour` accepts: zone stresses sxx, syy, sxy, szz, s1, s3 [Pa]; gridpoint
// displacements ux, uy and their magnitude u [m], averaged over each zone's corners.
const std::vector<std::string>& plot_colours();

// Draws the model. Throws edem::Error, leaving no file, for an unknown layer or extension,
// a size out of range, a window that is not x0 < x1, y0 < y1 (finite), a range that is not
// lo < hi, bands out of 2 to 16, a model without blocks, or a file that cannot be written.
void plot(Model& model, const PlotDef& def);

// What plot() draws, before it is drawn: its title, fills, lines and legend (def.file unused).
Scene gather_scene(Model& model, const PlotDef& def);

}  // namespace edem
