#include "io/canvas.hpp"

#include <cairo.h>

#include <algorithm>

#include "io/cairo_file.hpp"

namespace edem {
namespace {

constexpr double kLegendFont = 11.0, kLegendRow = 18.0, kLegendPad = 8.0;
constexpr double kLegendGap = 6.0;  // between a sample and its label

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
// fontconfig, loaded by cairo's text, keeps process-lifetime allocations that LeakSanitizer
// reports at exit; they are not ours and cannot be freed from here.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libfontconfig.so\n";
}
#endif

Canvas::Canvas(cairo_t* cr, double width, double height)
    : cr_(cr), s_(std::clamp(std::min(width, height) / 800.0, 0.5, 4.0)) {}

void Canvas::paint(Rgb c) {
  colour(c);
  cairo_paint(cr_);
}

void Canvas::colour(Rgb c, double alpha) {
  cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha);
}

void Canvas::pen(const Pen& pen) {
  colour(pen.colour);
  cairo_set_line_width(cr_, pen.width * s_);
  std::vector<double> dash = pen.dash;
  for (double& d : dash) d *= s_;
  cairo_set_dash(cr_, dash.data(), static_cast<int>(dash.size()), 0.0);
  // Caps would fill in the gaps of a dash pattern.
  const bool round = pen.round && dash.empty();
  cairo_set_line_cap(cr_, round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(cr_, round ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_BEVEL);
}

void Canvas::rectangle(const Rect& r) {
  cairo_new_path(cr_);
  cairo_rectangle(cr_, r.x, r.y, r.w, r.h);
}

void Canvas::segment(double x0, double y0, double x1, double y1) {
  cairo_move_to(cr_, x0, y0);
  cairo_line_to(cr_, x1, y1);
}

void Canvas::clip(const Rect& r) {
  rectangle(r);
  cairo_clip(cr_);
}

void Canvas::font(double size, bool bold) {
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, size * s_);
}

double Canvas::advance(const std::string& text) {
  cairo_text_extents_t ext;
  cairo_text_extents(cr_, text.c_str(), &ext);
  return ext.x_advance;
}

double Canvas::text_width(std::string_view text, double size, bool bold) {
  font(size, bold);
  return advance(printable(text));
}

void Canvas::text(std::string_view text, double x, double y, Align align, const TextStyle& style) {
  const std::string str = printable(text);
  font(style.size, style.bold);
  const double width = advance(str);
  cairo_font_extents_t fe;
  cairo_font_extents(cr_, &fe);
  const double left = align == Align::centre ? -0.5 * width : align == Align::right ? -width : 0.0;
  cairo_save(cr_);
  cairo_translate(cr_, x, y);
  cairo_rotate(cr_, style.angle);
  cairo_new_path(cr_);
  cairo_move_to(cr_, left, 0.5 * (fe.ascent - fe.descent));
  if (style.halo) {
    cairo_text_path(cr_, str.c_str());
  } else {
    colour(style.colour);
    cairo_show_text(cr_, str.c_str());
  }
  cairo_restore(cr_);
  if (style.halo) halo(style);
  cairo_new_path(cr_);
}

// The text's outline (the current path) stroked wide in translucent white, then filled.
void Canvas::halo(const TextStyle& style) {
  colour(rgb(0xffffff), 0.85);
  cairo_set_line_width(cr_, 0.25 * (style.size * s_));
  cairo_set_dash(cr_, nullptr, 0, 0.0);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke_preserve(cr_);
  colour(style.colour);
  cairo_fill(cr_);
}

double Canvas::fitted_size(std::string_view text, double size, double room) {
  const double width = text_width(text, size, true);
  return width > room ? size * room / width : size;
}

double Canvas::legend_column_width(const std::vector<LegendEntry>& entries,
                                   const LegendStyle& style) {
  double text = 0.0;
  for (const LegendEntry& e : entries) text = std::max(text, text_width(e.label, kLegendFont));
  return (2 * kLegendPad + style.swatch + kLegendGap) * s_ + text;
}

double Canvas::legend_height(std::size_t rows) const {
  return (2 * kLegendPad + kLegendRow * static_cast<double>(rows)) * s_;
}

void Canvas::legend(const Rect& box, const std::vector<LegendEntry>& entries,
                    const LegendStyle& style, const Mark& mark) {
  rectangle(box);
  colour(rgb(0xffffff), style.ground);
  cairo_fill_preserve(cr_);
  pen({rgb(0xb0b0b0), 0.8, {}});
  cairo_stroke(cr_);
  const auto columns = static_cast<std::size_t>(std::max(style.columns, 1));
  const std::size_t rows = (entries.size() + columns - 1) / columns;
  const double column_w = box.w / static_cast<double>(columns);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double row = static_cast<double>(i % rows), column = static_cast<double>(i / rows);
    const double y = box.y + (kLegendPad + kLegendRow * (row + 0.5)) * s_;
    const double x = box.x + column * column_w + kLegendPad * s_;
    cairo_new_path(cr_);
    segment(x, y, x + style.swatch * s_, y);
    Pen sample = entries[i].pen;
    sample.width = std::max(sample.width, 1.0);  // hairlines would vanish in the legend
    pen(sample);
    cairo_stroke(cr_);
    if (mark) mark(i, x + 0.5 * style.swatch * s_, y);
    text(entries[i].label, x + (style.swatch + kLegendGap) * s_, y, Align::left, {kLegendFont});
  }
}

}  // namespace edem
