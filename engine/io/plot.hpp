// Pictures of a model with cairo: PNG, SVG or PDF chosen by the file's extension.
#pragma once

#include <string>
#include <vector>

namespace edem {

class Model;

struct PlotDef {
  std::string file;                                // .png, .svg or .pdf
  std::vector<std::string> show{"blocks", "joints"};  // any of plot_layers()
  int width = 1200;                                // [px] (points for SVG/PDF)
  int height = 900;                                // [px]
};

// The layer names `show` accepts, in drawing order.
const std::vector<std::string>& plot_layers();

// Draws the model; throws edem::Error for an unknown layer, extension or unwritable file.
void plot(Model& model, const PlotDef& def);

}  // namespace edem
