// The drawing plot() and chart() share: a thin wrapper over a cairo context for colours, line
// styles, rectangles, aligned text and a framed legend.
//
// Sizes (line widths, dashes, font sizes) are in units of the canvas scale, about a pixel on a
// canvas 800 px across, so that a picture reads alike at any size; positions are in device
// units, y down.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

// cairo's own declaration of its context: styles and scenes built elsewhere need no cairo headers.
typedef struct _cairo cairo_t;

namespace edem {

struct Rgb {
  double r, g, b;
};

constexpr Rgb rgb(unsigned hex) {
  return {((hex >> 16) & 0xff) / 255.0, ((hex >> 8) & 0xff) / 255.0, (hex & 0xff) / 255.0};
}

inline constexpr Rgb kInk = rgb(0x202020);  // text and scale marks

// A line style.
struct Pen {
  Rgb colour;
  double width;
  std::vector<double> dash;  // on, off, ...; empty: solid
  bool round = true;         // round caps and joins; butt is much faster for many segments
};

struct Rect {
  double x, y, w, h;  // device units, y down
  bool contains(double px, double py) const {
    return px >= x && px <= x + w && py >= y && py <= y + h;
  }
  Rect grown(double d) const { return {x - d, y - d, w + 2 * d, h + 2 * d}; }
};

enum class Align { left, centre, right };

struct TextStyle {
  double size;  // font size
  Rgb colour = kInk;
  bool bold = false;
  double angle = 0.0;  // [rad], turned about the text's anchor
  // A white halo keeps the text legible over lines; without one it stays real text in SVG and
  // PDF (selectable, searchable).
  bool halo = false;
};

// One row of a legend: a sample of the pen, then the label.
struct LegendEntry {
  std::string label;
  Pen pen;
};

// A legend's look: rows fill its columns top down, one column after the other.
struct LegendStyle {
  double swatch = 26.0;  // the length of each sample line
  double ground = 1.0;   // the opacity of the box's white ground
  int columns = 1;
};

class Canvas {
 public:
  // The scale is the smaller of width and height [device units] over 800, within 0.5 to 4.
  Canvas(cairo_t* cr, double width, double height);
  double s() const { return s_; }
  cairo_t* cr() const { return cr_; }

  // The whole canvas in one colour.
  void paint(Rgb c);
  // The colour of the next fill or stroke.
  void colour(Rgb c, double alpha = 1.0);
  // The colour and line style of the next stroke.
  void pen(const Pen& pen);
  // A new path of the rectangle.
  void rectangle(const Rect& r);
  // A line added to the path.
  void segment(double x0, double y0, double x1, double y1);
  // Drawing kept inside `r` until the caller's cairo_restore().
  void clip(const Rect& r);

  // Text may be any bytes: it is drawn as printable() makes it. Its vertical centre is at y.
  double text_width(std::string_view text, double size, bool bold = false);
  void text(std::string_view text, double x, double y, Align align, const TextStyle& style);
  // `size`, or less so that bold `text` fits `room` [device units].
  double fitted_size(std::string_view text, double size, double room);

  // The width of a legend's column of these entries, and the height of `rows` rows
  // [device units].
  double legend_column_width(const std::vector<LegendEntry>& entries, const LegendStyle& style);
  double legend_height(std::size_t rows) const;
  // The box and its rows; `mark` adds to each sample, at its centre, what the pen does not draw
  // (a chart's marker).
  using Mark = std::function<void(std::size_t entry, double x, double y)>;
  void legend(const Rect& box, const std::vector<LegendEntry>& entries, const LegendStyle& style,
              const Mark& mark = {});

 private:
  void font(double size, bool bold);
  double advance(const std::string& text);  // in the current font
  void halo(const TextStyle& style);

  cairo_t* cr_;
  double s_;
};

}  // namespace edem
