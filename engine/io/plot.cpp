#include "io/plot.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "io/rect_clip.hpp"

namespace edem {
namespace {

// Sizes in units of the canvas scale.
constexpr double kMargin = 14.0, kTitleHeight = 30.0, kFooterHeight = 30.0;
constexpr double kTitleFont = 16.0, kLabelFont = 11.0, kNoteFont = 10.0;

// ---------------------------------------------------------------------------------------
// The scene's parts on the canvas.

// Scene metres to device units: uniform scale, y up.
struct View {
  Box box{};
  double k = 1.0;             // device units per metre
  double ox = 0.0, oy = 0.0;  // device position of the box's top-left corner
  Rect guard{};               // what is drawn is cut to this, a margin beyond the visible area
  Vec2 operator()(Vec2 p) const { return {ox + k * (p.x - box.x0), oy + k * (box.y1 - p.y)}; }
};

// One path, one stroke for the whole batch, cut to the guard.
void stroke(Canvas& p, const Polylines& lines, const View& view, const Pen& pen) {
  if (lines.empty()) return;
  cairo_t* cr = p.cr();
  cairo_new_path(cr);
  for (std::size_t i = 0; i < lines.starts.size(); ++i) {
    const std::size_t end = i + 1 < lines.starts.size() ? lines.starts[i + 1] : lines.points.size();
    bool drawing = false;  // a piece of this line was drawn, ending at `at`
    Vec2 at{};
    for (std::size_t j = lines.starts[i]; j + 1 < end; ++j) {
      const auto piece = clip_segment(view(lines.points[j]), view(lines.points[j + 1]), view.guard);
      if (!piece) {
        drawing = false;
        continue;
      }
      const auto [a, b] = *piece;
      if (!drawing || a.x != at.x || a.y != at.y) cairo_move_to(cr, a.x, a.y);
      cairo_line_to(cr, b.x, b.y);
      at = b;
      drawing = true;
    }
  }
  p.pen(pen);
  cairo_stroke(cr);
}

// Many thin segments (zones): on a raster surface, filled as quads with coarser antialiasing,
// which rasterizes about twice as fast as a stroke and looks the same.
void hairlines(Canvas& p, const Polylines& lines, const View& view, const Pen& pen) {
  cairo_t* cr = p.cr();
  const bool raster = cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE;
  if (!raster || !pen.dash.empty()) {
    stroke(p, lines, view, pen);
    return;
  }
  if (lines.empty()) return;
  const double half = 0.5 * pen.width * p.s();
  cairo_new_path(cr);
  for (std::size_t i = 0; i < lines.starts.size(); ++i) {
    const std::size_t end = i + 1 < lines.starts.size() ? lines.starts[i + 1] : lines.points.size();
    for (std::size_t j = lines.starts[i]; j + 1 < end; ++j) {
      const auto piece = clip_segment(view(lines.points[j]), view(lines.points[j + 1]), view.guard);
      if (!piece) continue;
      const auto [a, b] = *piece;
      const double length = norm(b - a);
      if (!(length > 0)) continue;
      const Vec2 n{-(b.y - a.y) * half / length, (b.x - a.x) * half / length};
      // Every quad turns the same way, so overlaps never cancel under the winding rule.
      cairo_move_to(cr, a.x + n.x, a.y + n.y);
      cairo_line_to(cr, b.x + n.x, b.y + n.y);
      cairo_line_to(cr, b.x - n.x, b.y - n.y);
      cairo_line_to(cr, a.x - n.x, a.y - n.y);
      cairo_close_path(cr);
    }
  }
  p.colour(pen.colour);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_FAST);
  cairo_fill(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
}

// The polygons as one path, filled, then outlined: an outline in the fill's own colour leaves no
// hairline gaps between neighbours.
void draw_fill(Canvas& p, const Scene::Fill& fill, const View& view) {
  if (fill.polygons.empty()) return;
  cairo_t* cr = p.cr();
  cairo_new_path(cr);
  std::vector<Vec2> device;
  for (const Polygon& polygon : fill.polygons) {
    device.clear();
    bool inside = true;
    for (const Vec2& corner : polygon) {
      device.push_back(view(corner));
      inside = inside && view.guard.contains(device.back().x, device.back().y);
    }
    if (!inside) device = clip_polygon(device, view.guard);
    for (std::size_t i = 0; i < device.size(); ++i) {
      if (i == 0)
        cairo_move_to(cr, device[i].x, device[i].y);
      else
        cairo_line_to(cr, device[i].x, device[i].y);
    }
    if (!device.empty()) cairo_close_path(cr);
  }
  p.colour(fill.colour, fill.opacity);
  cairo_fill_preserve(cr);
  p.pen(fill.outline);
  cairo_stroke(cr);
}

void draw_labels(Canvas& p, const std::vector<Scene::Label>& labels, const View& view) {
  for (const Scene::Label& label : labels) {
    const Box& box = label.extent;
    // A label much larger than what it names would only hide the picture.
    if (p.text_width(label.text, kLabelFont) > 2.0 * view.k * (box.x1 - box.x0) ||
        kLabelFont * p.s() > 2.0 * view.k * (box.y1 - box.y0))
      continue;
    const Vec2 c = view(label.at);
    if (!view.guard.grown(view.guard.w).contains(c.x, c.y)) continue;  // too far out to reach into view
    p.text(label.text, c.x, c.y, Align::centre, {.size = kLabelFont, .halo = true});
  }
}

// ---------------------------------------------------------------------------------------
// Layout: title, scene, scale bar and legend.

// Where each part goes. Title, scene, scale bar and legend form one block centred on the
// canvas; the legend goes right of the scene or below it, whichever leaves the scene larger.
struct Layout {
  View view;
  Rect area{};    // the scene's box on the canvas
  Rect legend{};  // empty when there is no legend or no room for it
  int legend_columns = 1;
  double title_y = 0.0;   // centre line of the title
  double footer_y = 0.0;  // centre line of the scale bar
  double right = 0.0;     // right end of the block
  bool has_legend() const { return legend.w > 0; }
};

enum class LegendPlace { none, right, below };

struct LegendPlan {
  LegendPlace place = LegendPlace::none;
  double w = 0.0, h = 0.0;  // size of the legend box
  int columns = 1;
  double k = 0.0;  // the scene's scale it leaves [device units per metre]
};

// Right of the scene (one column) or below it (as many columns as fit), whichever leaves the
// scene larger; no legend when either would shrink the scene to less than half.
LegendPlan plan_legend(Canvas& p, const std::vector<LegendEntry>& legend, double free_w,
                       double free_h, double ew, double eh) {
  auto scale = [&](double w, double h) { return w > 0 && h > 0 ? std::min(w / ew, h / eh) : 0.0; };
  const double margin = kMargin * p.s();
  LegendPlan none{LegendPlace::none, 0.0, 0.0, 1, scale(free_w, free_h)};
  const auto n = static_cast<int>(legend.size());
  if (n == 0) return none;
  const double col_w = p.legend_column_width(legend, LegendStyle{});
  const auto height = [&](int rows) { return p.legend_height(static_cast<std::size_t>(rows)); };
  const int columns = std::clamp(static_cast<int>(free_w / col_w), 1, n);
  const int rows = (n + columns - 1) / columns;
  const LegendPlan right{LegendPlace::right, col_w, height(n), 1,
                         height(n) <= free_h ? scale(free_w - col_w - margin, free_h) : 0.0};
  const LegendPlan below{LegendPlace::below, col_w * columns, height(rows), columns,
                         scale(free_w, free_h - height(rows) - 0.5 * margin)};
  const LegendPlan& best = right.k >= below.k ? right : below;
  return best.k >= 0.5 * none.k ? best : none;
}

// Room for coordinate axes: the y labels' width left of the scene, a line of x labels below it,
// and half the last x label (with its unit) right of it.
constexpr double kAxisLeft = 52.0, kAxisBelow = 18.0, kAxisRight = 18.0;

Layout layout(Canvas& p, const Box& box, double width, double height, bool has_title,
              const std::vector<LegendEntry>& legend, bool axes) {
  const double s = p.s(), margin = kMargin * s;
  const double title_h = has_title ? kTitleHeight * s : 0.0;
  const double axis_left = axes ? kAxisLeft * s : 0.0, axis_below = axes ? kAxisBelow * s : 0.0;
  const double axis_right = axes ? kAxisRight * s : 0.0;
  const double footer_h = kFooterHeight * s + axis_below;
  double ew = box.x1 - box.x0, eh = box.y1 - box.y0;
  if (!(ew > 0)) ew = eh > 0 ? eh : 1.0;
  if (!(eh > 0)) eh = ew;
  const LegendPlan plan =
      plan_legend(p, legend, width - 2 * margin - axis_left - axis_right, height - 2 * margin - title_h - footer_h,
                  ew, eh);
  const bool right = plan.place == LegendPlace::right, below = plan.place == LegendPlace::below;

  // The block of title, scene, scale bar and legend, centred on the canvas.
  const double mw = plan.k * ew, mh = plan.k * eh;
  const double block_w = axis_left + axis_right + (right ? mw + margin + plan.w : std::max(mw, plan.w));
  const double block_h = title_h + mh + footer_h + (below ? plan.h + 0.5 * margin : 0.0);
  const double x0 = 0.5 * (width - block_w) + axis_left, y0 = 0.5 * (height - block_h);

  Layout out;
  out.area = {right ? x0 : x0 + 0.5 * (block_w - axis_left - axis_right - mw), y0 + title_h, mw, mh};
  if (right) out.legend = {x0 + mw + margin + axis_right, out.area.y, plan.w, plan.h};
  if (below)
    out.legend = {x0 + 0.5 * (block_w - axis_left - axis_right - plan.w), out.area.y + mh + footer_h, plan.w, plan.h};
  out.legend_columns = plan.columns;
  out.title_y = y0 + 0.5 * title_h;
  out.footer_y = out.area.y + mh + axis_below + 0.5 * (footer_h - axis_below);
  out.right = right ? out.legend.x + out.legend.w : out.area.x + mw;
  out.view = View{box, plan.k, out.area.x + 0.5 * (mw - plan.k * (box.x1 - box.x0)),
                  out.area.y + 0.5 * (mh - plan.k * (box.y1 - box.y0))};
  out.view.guard = out.area.grown(32.0 * p.s());
  return out;
}

// The largest 1, 2 or 5 x 10^k not above `target` [m].
double round_length(double target) {
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (const double m : {5.0, 2.0, 1.0})
    if (m * decade <= target * (1 + 1e-9)) return m * decade;
  return decade;
}

std::string length_label(double metres) {
  if (metres >= 1000.0) return fmt::format("{:g} km", metres / 1000.0);
  if (metres < 0.01) return fmt::format("{:g} mm", metres * 1000.0);
  return fmt::format("{:g} m", metres);
}

// A bar about a fifth of the scene's width, of a round length; returns its label's right end.
double draw_scale_bar(Canvas& p, const Layout& lay) {
  const double s = p.s();
  const double length = round_length(0.2 * lay.area.w / lay.view.k);
  if (!std::isfinite(length) || length <= 0) return lay.area.x;
  const double w = length * lay.view.k, h = 5.0 * s;
  const double x = lay.area.x, y = lay.footer_y - 0.5 * h;
  for (int half = 0; half < 2; ++half) {
    p.rectangle({x + 0.5 * w * half, y, 0.5 * w, h});
    const double shade = half == 0 ? 0.12 : 1.0;
    p.colour({shade, shade, shade});
    cairo_fill(p.cr());
  }
  p.rectangle({x, y, w, h});
  p.pen({kInk, 0.8, {}});
  cairo_stroke(p.cr());
  const std::string label = length_label(length);
  const double label_x = x + w + 6.0 * s;
  p.text(label, label_x, lay.footer_y, Align::left, {kLabelFont});
  return label_x + p.text_width(label, kLabelFont);
}

// Coordinates along the scene's bottom and left edges: round steps, about six a side, ticked
// outward, each labelled in metres.
void draw_axes(Canvas& p, const Layout& lay) {
  const double s = p.s(), tick = 4.0 * s;
  const Box& b = lay.view.box;
  const Rect& a = lay.area;
  // Ticks at whole steps, counted in steps, not added up: far from 0 a step can be below the
  // coordinates' resolution. None where more than 20 would be needed.
  const auto round_steps = [](double lo, double hi, double step) {
    std::vector<double> at;
    if (!(std::isfinite(step) && step > 0)) return at;
    const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
    if (!(last - first <= 20.0)) return at;
    for (double n = first; n <= last; ++n) {
      const double v = n * step;
      if (!at.empty() && v == at.back()) continue;
      at.push_back(std::abs(v) < 1e-9 * step ? 0.0 : v);
    }
    return at;
  };
  // Labels with as many decimals as the step needs, so that a narrow window's ticks differ.
  const auto label = [](double v, double step) {
    const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 17);
    return fmt::format("{:.{}f}", v, decimals);
  };
  const double x_step = round_length((b.x1 - b.x0) / 6.0), y_step = round_length((b.y1 - b.y0) / 6.0);
  std::vector<std::pair<double, double>> xs, ys;  // (device position, coordinate)
  for (const double x : round_steps(b.x0, b.x1, x_step)) {
    const double dx = lay.view(Vec2{x, b.y0}).x;
    if (dx >= a.x - 0.5 && dx <= a.x + a.w + 0.5) xs.push_back({dx, x});
  }
  for (const double y : round_steps(b.y0, b.y1, y_step)) {
    const double dy = lay.view(Vec2{b.x0, y}).y;
    if (dy >= a.y - 0.5 && dy <= a.y + a.h + 0.5) ys.push_back({dy, y});
  }
  cairo_new_path(p.cr());
  for (const auto& [dx, x] : xs) p.segment(dx, a.y + a.h, dx, a.y + a.h + tick);
  for (const auto& [dy, y] : ys) p.segment(a.x - tick, dy, a.x, dy);
  p.pen({kInk, 0.8, {}});
  cairo_stroke(p.cr());
  // The x labels under the ticks, the last with the unit; the y labels left of theirs, but for one
  // so near the bottom corner that it would run into the first x label.
  const double below = a.y + a.h + tick + 0.8 * kNoteFont * s;
  for (std::size_t i = 0; i < xs.size(); ++i)
    p.text(label(xs[i].second, x_step) + (i + 1 == xs.size() ? " m" : ""), xs[i].first, below,
           Align::centre, {kNoteFont});
  for (const auto& [dy, y] : ys)
    if (a.y + a.h - dy > 1.2 * kNoteFont * s || xs.empty() || xs.front().first - a.x > 3.0 * kNoteFont * s)
      p.text(label(y, y_step), a.x - tick - 2.0 * s, dy, Align::right, {kNoteFont});
}

// The title, shrunk to fit the canvas; left out when it would be too small to read.
void draw_title(Canvas& p, const std::string& title, double width, double y) {
  const double size = p.fitted_size(title, kTitleFont, width - 2 * kMargin * p.s());
  if (size * p.s() >= 6.0)
    p.text(title, 0.5 * width, y, Align::centre, {.size = size, .bold = true});
}

// The note, right-aligned under the block, when it clears the scale bar.
void draw_note(Canvas& p, const std::string& note, const Layout& lay, double left_limit) {
  if (note.empty() || lay.right - p.text_width(note, kNoteFont) < left_limit + 12.0 * p.s()) return;
  p.text(note, lay.right, lay.footer_y, Align::right, {.size = kNoteFont, .colour = rgb(0x707070)});
}

void render(cairo_t* cr, const Scene& scene, double width, double height) {
  Canvas p(cr, width, height);
  const Layout lay = layout(p, scene.box, width, height, !scene.title.empty(), scene.legend, scene.axes);
  const View& view = lay.view;

  p.paint(rgb(0xffffff));
  // The scene, clipped to its box (fills may reach outside it).
  cairo_save(cr);
  p.clip(lay.area.grown(4.0 * p.s()));
  for (const Scene::Fill& f : scene.fills) draw_fill(p, f, view);
  for (const Scene::Lines& l : scene.lines) {
    if (l.hairlines)
      hairlines(p, l.lines, view, l.pen);
    else
      stroke(p, l.lines, view, l.pen);
  }
  draw_labels(p, scene.labels, view);
  cairo_restore(cr);

  if (scene.axes) draw_axes(p, lay);
  if (!scene.title.empty()) draw_title(p, scene.title, width, lay.title_y);
  if (lay.has_legend()) p.legend(lay.legend, scene.legend, {.columns = lay.legend_columns});
  draw_note(p, scene.note, lay, draw_scale_bar(p, lay));
}

}  // namespace

void plot_scene(const Scene& scene, const std::string& file, int width, int height) {
  check_size(width, height);
  write_picture(file, width, height, scene.title,
                [&](cairo_t* cr) { render(cr, scene, width, height); });
}

}  // namespace edem
