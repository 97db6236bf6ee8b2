#include "io/chart.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include "core/error.hpp"
#include "io/cairo_file.hpp"
#include "io/canvas.hpp"

namespace edem {
namespace {

// ---------------------------------------------------------------------------------------
// Checks, all made before anything is computed or written.

// A series as messages name it: "series 'implicit'", or "series 2" when it has no name.
std::string series_label(const ChartSeries& series, std::size_t i) {
  return series.name.empty() ? fmt::format("series {}", i + 1)
                             : fmt::format("series '{}'", series.name);
}

void check_values(const std::string& series, char axis, const std::vector<double>& values,
                  bool log) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!std::isfinite(v))
      fail("{}: {}[{}] must be finite, got {}", series, axis, i + 1,
           std::isnan(v) ? "nan"
           : v > 0       ? "inf"
                         : "-inf");
    if (log && !(v > 0))
      fail("{}: {}[{}] = {} cannot be drawn on the logarithmic {} axis: values must be > 0", series,
           axis, i + 1, v, axis);
  }
}

void check_def(const ChartDef& def) {
  check_size(def.width, def.height);
  if (def.series.empty()) fail("no series to draw: give at least one, with its x and y values");
  for (std::size_t i = 0; i < def.series.size(); ++i) {
    const ChartSeries& s = def.series[i];
    const std::string label = series_label(s, i);
    if (s.x.size() != s.y.size())
      fail("{}: x has {} value{} but y has {}", label, s.x.size(), s.x.size() == 1 ? "" : "s",
           s.y.size());
    if (s.x.empty()) fail("{} has no points", label);
    check_values(label, 'x', s.x, def.log_x);
    check_values(label, 'y', s.y, def.log_y);
  }
}

// ---------------------------------------------------------------------------------------
// Axes: the data's range and round ticks.

struct Tick {
  double at;  // axis units: the value, or its log10 on a logarithmic axis
  std::string label;
};

struct Ticks {
  std::vector<Tick> major;    // labelled, with a grid line
  std::vector<double> minor;  // axis units
};

// One axis: its range in axis units, where that range lies on the canvas, and its ticks.
struct Axis {
  bool log = false;
  double lo = 0.0, hi = 1.0;    // axis units, lo < hi
  double from = 0.0, to = 1.0;  // device coordinates of lo and hi
  Ticks ticks;
  double unit(double value) const { return log ? std::log10(value) : value; }
  double device(double at) const { return from + (at - lo) / (hi - lo) * (to - from); }
};

// The extent of every series' x (or y) in axis units, padded by 5% on each side; values all
// equal (to 1e-9) get a span of their own: a decade on a logarithmic axis, +-10% (or +-1 about
// 0) on a linear one.
Axis axis_of(const std::vector<ChartSeries>& series, bool x, bool log) {
  Axis axis;
  axis.log = log;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const ChartSeries& s : series)
    for (const double v : x ? s.x : s.y) {
      lo = std::min(lo, axis.unit(v));
      hi = std::max(hi, axis.unit(v));
    }
  double pad = 0.05 * hi - 0.05 * lo;
  if (!(hi - lo > 1e-9 * std::max(std::abs(lo), std::abs(hi)))) {
    lo = hi = 0.5 * lo + 0.5 * hi;
    pad = log ? 0.5 : lo == 0 ? 1.0 : 0.1 * std::abs(lo);
  }
  axis.lo = lo - pad;
  axis.hi = hi + pad;
  if (!std::isfinite(axis.hi - axis.lo) || !(axis.hi > axis.lo))
    fail("the {} values span a range too wide or too narrow to draw", x ? 'x' : 'y');
  return axis;
}

// Tidies the exponent of printf's "%e": "2.50e+06" -> "2.50e6", "1e-05" -> "1e-5".
std::string tidy_exponent(const std::string& text) {
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  return fmt::format("{}e{}", text.substr(0, e), std::atoi(text.c_str() + e + 1));
}

// A tick on a grid of step m*10^k: fixed decimals, or "2.5e6" for very large or small steps.
std::string linear_label(double v, int k, bool scientific) {
  if (!scientific) return fmt::format("{:.{}f}", v, std::max(0, -k));
  if (v == 0) return "0";
  const int e = static_cast<int>(std::floor(std::log10(std::abs(v))));
  return tidy_exponent(fmt::format("{:.{}e}", v, std::max(0, e - k)));
}

// m*10^k as "0.002" or "2e-5": plain only when the whole axis reads well that way.
std::string power_label(int m, int k, bool plain) {
  if (!plain) return fmt::format("{}e{}", m, k);
  return fmt::format("{:.{}f}", m * std::pow(10.0, k), std::max(0, -k));
}

// Ticks at i*step in [lo, hi] (values, not logs), step = m*10^k; none if more than `most`.
Ticks linear_ticks(double lo, double hi, int m, int k, int most, bool log) {
  const double step = m * std::pow(10.0, k);
  const double first = std::ceil(lo / step), last = std::floor(hi / step);
  if (!(last - first < most)) return {};
  const bool scientific = std::max(std::abs(lo), std::abs(hi)) >= 1e6 || k < -4;
  Ticks ticks;
  for (int j = 0; j <= static_cast<int>(last - first); ++j) {
    const double i = first + j, v = i == 0 ? 0.0 : i * step;
    ticks.major.push_back({log ? std::log10(v) : v, linear_label(v, k, scientific)});
  }
  return ticks;
}

// Ticks at m*10^k on a logarithmic axis over [lo, hi] (logs): labelled where m is one of
// `labelled` and k a multiple of `every`; with `minor`, minor ticks at the other m in 1..9
// (at the other decades only, when every > 1).
Ticks power_ticks(double lo, double hi, const std::vector<int>& labelled, int every, bool minor) {
  std::vector<std::array<int, 2>> major;  // m, k
  Ticks ticks;
  for (int k = static_cast<int>(std::floor(lo)); k <= static_cast<int>(std::ceil(hi)); ++k)
    for (int m = 1; m <= (every > 1 ? 1 : 9); ++m) {
      const double at = k + std::log10(static_cast<double>(m));
      if (at < lo || at > hi) continue;
      if (std::find(labelled.begin(), labelled.end(), m) != labelled.end() && k % every == 0)
        major.push_back({m, k});
      else if (minor)
        ticks.minor.push_back(at);
    }
  // Plain decimals ("0.002") where the whole axis reads well that way, else "2e-5".
  const bool plain = std::all_of(major.begin(), major.end(),
                                 [](const auto& t) { return t[1] >= -4 && t[1] <= 5; });
  for (const auto& [m, k] : major)
    ticks.major.push_back({k + std::log10(static_cast<double>(m)), power_label(m, k, plain)});
  return ticks;
}

// The along-axis size of a label [device units].
using Measure = std::function<double(const std::string&)>;

// Whether neighbouring labels keep a gap of at least `gap` between them.
bool labels_fit(const Ticks& ticks, const Axis& axis, const Measure& size, double gap) {
  for (std::size_t i = 1; i < ticks.major.size(); ++i) {
    const double room =
        std::abs(axis.device(ticks.major[i].at) - axis.device(ticks.major[i - 1].at));
    if (room < 0.5 * (size(ticks.major[i].label) + size(ticks.major[i - 1].label)) + gap)
      return false;
  }
  return true;
}

// The ticks of an axis, from candidates in order of preference: the first with enough labels
// that do not overlap; failing all, the densest that fits (maybe none, on a tiny canvas).
Ticks choose_ticks(const Axis& axis, const Measure& size, double gap, double minor_room) {
  struct Candidate {
    Ticks ticks;
    std::size_t fewest;  // labels it needs to be taken at once
  };
  std::vector<Candidate> candidates;
  const auto linear = [&](double lo, double hi, bool log) {
    if (!std::isfinite(hi - lo) || !(hi > lo)) return;
    const int k0 = static_cast<int>(std::floor(std::log10(hi - lo))) - 2;
    for (int k = k0; k <= k0 + 3; ++k)
      for (const int m : {1, 2, 5}) candidates.push_back({linear_ticks(lo, hi, m, k, 8, log), 4});
  };
  if (axis.log) {
    // Minor ticks only where they stand apart: within a decade, or at unlabelled decades.
    const double decade = std::abs(axis.device(axis.lo + 1) - axis.device(axis.lo));
    const bool minor = decade >= minor_room, decade_minor = decade >= 0.1 * minor_room;
    candidates.push_back({power_ticks(axis.lo, axis.hi, {1}, 1, minor), 3});
    candidates.push_back({power_ticks(axis.lo, axis.hi, {1, 2, 5}, 1, true), 3});
    for (const int n : {2, 3, 5, 10, 20, 50, 100})
      candidates.push_back({power_ticks(axis.lo, axis.hi, {1}, n, decade_minor), 2});
    candidates.push_back({power_ticks(axis.lo, axis.hi, {1}, 1, minor), 2});
    candidates.push_back({power_ticks(axis.lo, axis.hi, {1, 2, 3, 4, 5, 6, 7, 8, 9}, 1, false), 3});
    if (axis.lo > -300 && axis.hi < 300)
      linear(std::pow(10.0, axis.lo), std::pow(10.0, axis.hi), true);
  } else {
    linear(axis.lo, axis.hi, false);
  }
  const Ticks* fallback = nullptr;
  for (const Candidate& c : candidates) {
    const std::size_t n = c.ticks.major.size();
    if (n == 0 || n > 10 || !labels_fit(c.ticks, axis, size, gap)) continue;
    if (n >= c.fewest) return c.ticks;
    if (!fallback || n > fallback->major.size()) fallback = &c.ticks;
  }
  return fallback ? *fallback : Ticks{};
}

// ---------------------------------------------------------------------------------------
// Styles. Sizes are in units of the canvas scale (about a pixel at 800 px).

// Series colours, told apart in print and by most colour-blind readers together with the
// marker shapes.
constexpr std::array kSeriesColours{rgb(0x1f77b4), rgb(0xff7f0e), rgb(0x2ca02c), rgb(0xd62728),
                                    rgb(0x9467bd), rgb(0x8c564b), rgb(0xe377c2), rgb(0x17becf)};
enum class Marker { circle, square, triangle, diamond, triangle_down };
constexpr std::array kMarkers{Marker::circle, Marker::square, Marker::triangle, Marker::diamond,
                              Marker::triangle_down};
constexpr Rgb kGrid = rgb(0xe4e4e4);
constexpr Rgb kFrame = rgb(0x606060);

constexpr double kMargin = 14.0, kTitleHeight = 30.0, kLabelHeight = 26.0;
constexpr double kTitleFont = 16.0, kLabelFont = 12.5, kTickFont = 11.0;
constexpr double kTickLength = 5.0, kMinorLength = 3.0, kTickGap = 4.0;
constexpr double kMinorRoom = 40.0;  // the shortest decade with minor ticks
constexpr double kLineWidth = 1.8, kMarkerRadius = 5.0;
// A series of more points than this is a line alone: markers on a dense history hide it.
constexpr std::size_t kMarkedPoints = 40;
// Over the data, the legend's ground lets a little of it show through.
constexpr LegendStyle kLegend{.swatch = 30.0, .ground = 0.9, .columns = 1};
constexpr double kLegendInset = 10.0;  // from the frame
constexpr int kPointCover = 20;  // what a point a legend covers counts, against a line sample's 1

Rgb colour_of(std::size_t series) {
  return kSeriesColours[series % kSeriesColours.size()];
}

Marker marker_of(std::size_t series) {
  return kMarkers[series % kMarkers.size()];
}

Pen line_pen(std::size_t series) {
  return {colour_of(series), kLineWidth, {}};
}

// ---------------------------------------------------------------------------------------
// Drawing.

void corners(cairo_t* cr, double x, double y,
             std::initializer_list<std::array<double, 2>> offsets) {
  for (const auto& [dx, dy] : offsets) cairo_line_to(cr, x + dx, y + dy);
  cairo_close_path(cr);
}

void marker(Canvas& p, Marker shape, double x, double y, Rgb fill) {
  cairo_t* cr = p.cr();
  const double r = kMarkerRadius * p.s();
  cairo_new_path(cr);
  switch (shape) {
    case Marker::circle:
      cairo_arc(cr, x, y, r, 0, 2 * std::numbers::pi);
      break;
    case Marker::square:
      cairo_rectangle(cr, x - 0.85 * r, y - 0.85 * r, 1.7 * r, 1.7 * r);
      break;
    case Marker::diamond:
      corners(cr, x, y, {{0, -1.25 * r}, {1.0 * r, 0}, {0, 1.25 * r}, {-1.0 * r, 0}});
      break;
    case Marker::triangle:
      corners(cr, x, y, {{0, -1.2 * r}, {1.1 * r, 0.8 * r}, {-1.1 * r, 0.8 * r}});
      break;
    case Marker::triangle_down:
      corners(cr, x, y, {{0, 1.2 * r}, {1.1 * r, -0.8 * r}, {-1.1 * r, -0.8 * r}});
      break;
  }
  p.colour(fill);
  cairo_fill_preserve(cr);
  p.pen({rgb(0xffffff), 0.8, {}});
  cairo_stroke(cr);
}

// Where everything goes: the frame of the data, and both axes with their ticks. The y ticks
// are chosen first, since the frame's left edge depends on how wide their labels are.
struct Layout {
  Rect frame{};
  Axis x, y;
  double title_y = 0.0;
};

// `band`: room kept above the frame, below the title, for a legend that no corner inside can take.
Layout layout(Canvas& p, const ChartDef& def, double width, double height, double band = 0.0) {
  const double s = p.s(), margin = kMargin * s;
  Layout lay;
  lay.x = axis_of(def.series, true, def.log_x);
  lay.y = axis_of(def.series, false, def.log_y);
  const double title_h = def.title.empty() ? 0.0 : kTitleHeight * s;
  const double tick_room = (kTickLength + kTickGap + 1.3 * kTickFont) * s;
  const double top = margin + title_h + 4.0 * s + band;
  const double bottom =
      height - margin - (def.x_label.empty() ? 0.0 : kLabelHeight * s) - tick_room;
  lay.title_y = margin + 0.5 * title_h;

  lay.y.from = bottom;
  lay.y.to = top;
  const double font_h = 1.2 * kTickFont * s;
  lay.y.ticks = choose_ticks(
      lay.y, [&](const std::string&) { return font_h; }, 4.0 * s, kMinorRoom * s);
  double label_w = 0.0;
  for (const Tick& t : lay.y.ticks.major)
    label_w = std::max(label_w, p.text_width(t.label, kTickFont));

  const double left = margin + (def.y_label.empty() ? 0.0 : kLabelHeight * s) + label_w +
                      (kTickLength + kTickGap) * s;
  const double right = width - margin - 18.0 * s;
  lay.x.from = left;
  lay.x.to = right;
  lay.x.ticks = choose_ticks(
      lay.x, [&](const std::string& t) { return p.text_width(t, kTickFont); }, 10.0 * s,
      kMinorRoom * s);
  lay.frame = {left, top, std::max(right - left, 0.0), std::max(bottom - top, 0.0)};
  return lay;
}

void draw_grid(Canvas& p, const Layout& lay) {
  const Rect& f = lay.frame;
  cairo_new_path(p.cr());
  for (const Tick& t : lay.x.ticks.major)
    p.segment(lay.x.device(t.at), f.y, lay.x.device(t.at), f.y + f.h);
  for (const Tick& t : lay.y.ticks.major)
    p.segment(f.x, lay.y.device(t.at), f.x + f.w, lay.y.device(t.at));
  p.pen({kGrid, 0.8, {}, false});
  cairo_stroke(p.cr());
}

// Ticks outward from the bottom and left edges of the frame, then their labels.
void draw_axes(Canvas& p, const Layout& lay) {
  cairo_t* cr = p.cr();
  const double s = p.s();
  const Rect& f = lay.frame;
  p.rectangle(f);
  p.pen({kFrame, 1.0, {}});
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);  // square corners
  cairo_stroke(cr);

  const double bottom = f.y + f.h;
  for (const auto& [length, minor] :
       {std::pair{kTickLength, false}, std::pair{kMinorLength, true}}) {
    cairo_new_path(cr);
    const auto tick_x = [&](double at) {
      p.segment(lay.x.device(at), bottom, lay.x.device(at), bottom + length * s);
    };
    const auto tick_y = [&](double at) {
      p.segment(f.x, lay.y.device(at), f.x - length * s, lay.y.device(at));
    };
    if (minor) {
      for (const double at : lay.x.ticks.minor) tick_x(at);
      for (const double at : lay.y.ticks.minor) tick_y(at);
    } else {
      for (const Tick& t : lay.x.ticks.major) tick_x(t.at);
      for (const Tick& t : lay.y.ticks.major) tick_y(t.at);
    }
    p.pen({kFrame, minor ? 0.7 : 1.0, {}, false});
    cairo_stroke(cr);
  }

  const double label_y = bottom + (kTickLength + kTickGap + 0.6 * kTickFont) * s;
  for (const Tick& t : lay.x.ticks.major)
    p.text(t.label, lay.x.device(t.at), label_y, Align::centre, {kTickFont});
  const double label_x = f.x - (kTickLength + kTickGap) * s;
  for (const Tick& t : lay.y.ticks.major)
    p.text(t.label, label_x, lay.y.device(t.at), Align::right, {kTickFont});
}

void draw_labels(Canvas& p, const Layout& lay, const ChartDef& def, double width, double height) {
  const double s = p.s();
  const Rect& f = lay.frame;
  if (!def.x_label.empty())
    p.text(def.x_label, f.x + 0.5 * f.w, height - kMargin * s - 0.6 * kLabelHeight * s,
           Align::centre, {kLabelFont});
  if (!def.y_label.empty())
    p.text(def.y_label, kMargin * s + 0.4 * kLabelHeight * s, f.y + 0.5 * f.h, Align::centre,
           {.size = kLabelFont, .angle = -0.5 * std::numbers::pi});
  if (def.title.empty()) return;
  // Centred over the frame, shrunk to fit the canvas; left out when too small to read.
  const double room = width - 2 * kMargin * s;
  const double tw = p.text_width(def.title, kTitleFont, true);
  const double size = p.fitted_size(def.title, kTitleFont, room);
  const double centre = std::clamp(f.x + 0.5 * f.w, kMargin * s + 0.5 * tw * size / kTitleFont,
                                   width - kMargin * s - 0.5 * tw * size / kTitleFont);
  if (size * s >= 6.0)
    p.text(def.title, centre, lay.title_y, Align::centre, {.size = size, .bold = true});
}

// Each series' points on the canvas.
std::vector<std::vector<std::array<double, 2>>> points_of(const ChartDef& def, const Layout& lay) {
  std::vector<std::vector<std::array<double, 2>>> out;
  for (const ChartSeries& s : def.series) {
    auto& points = out.emplace_back();
    for (std::size_t i = 0; i < s.x.size(); ++i)
      points.push_back({lay.x.device(lay.x.unit(s.x[i])), lay.y.device(lay.y.unit(s.y[i]))});
  }
  return out;
}

void draw_series(Canvas& p, const Layout& lay,
                 const std::vector<std::vector<std::array<double, 2>>>& points) {
  cairo_t* cr = p.cr();
  cairo_save(cr);
  p.clip(lay.frame.grown(2.0 * kMarkerRadius * p.s()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].size() < 2) continue;
    cairo_new_path(cr);
    for (const auto& [x, y] : points[i]) cairo_line_to(cr, x, y);
    p.pen(line_pen(i));
    cairo_stroke(cr);
  }
  // Markers above every line, so that no line hides a point.
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].size() <= kMarkedPoints || points[i].size() == 1)
      for (const auto& [x, y] : points[i]) marker(p, marker_of(i), x, y, colour_of(i));
  cairo_restore(cr);
}

// The marks: dashed vertical lines with their labels just inside the frame's top.
void draw_marks(Canvas& p, const Layout& lay, const std::vector<ChartMark>& marks) {
  const Rect& f = lay.frame;
  const double s = p.s();
  for (const ChartMark& m : marks) {
    if (lay.x.log && !(m.x > 0.0)) continue;
    const double x = lay.x.device(lay.x.unit(m.x));
    if (!(x >= f.x && x <= f.x + f.w)) continue;
    cairo_new_path(p.cr());
    p.segment(x, f.y, x, f.y + f.h);
    p.pen({kFrame, 0.9, {4.0, 3.0}, false});
    cairo_stroke(p.cr());
    p.text(m.label, x + 3.0 * s, f.y + 1.2 * kTickFont * s, Align::left, {.size = kTickFont, .colour = kFrame});
  }
}

// The named series, in order, as legend rows.
struct Legend {
  std::vector<LegendEntry> entries;
  std::vector<std::size_t> series;  // of each entry
};

Legend legend_of(const ChartDef& def) {
  Legend legend;
  for (std::size_t i = 0; i < def.series.size(); ++i) {
    if (def.series[i].name.empty()) continue;
    legend.entries.push_back({def.series[i].name, line_pen(i)});
    legend.series.push_back(i);
  }
  return legend;
}

// The legend's box in the corner of the frame that covers the fewest points and line samples
// (top right first on a tie), with how much it covers (kPointCover a point, 1 a line sample);
// nothing when no series has a name.
struct LegendPlace {
  Rect box;
  int covered = 0;
};
std::optional<LegendPlace> legend_box(
    Canvas& p, const Layout& lay, const Legend& legend,
    const std::vector<std::vector<std::array<double, 2>>>& points) {
  if (legend.entries.empty()) return std::nullopt;
  const double s = p.s();
  const double w = p.legend_column_width(legend.entries, kLegend);
  const double h = p.legend_height(legend.entries.size());
  const Rect& f = lay.frame;
  const double inset = kLegendInset * s;
  const double left = f.x + inset, right = f.x + f.w - inset - w;
  const double top = f.y + inset, bottom = f.y + f.h - inset - h;
  const std::array<Rect, 4> corners{Rect{right, top, w, h}, Rect{left, top, w, h},
                                    Rect{right, bottom, w, h}, Rect{left, bottom, w, h}};
  // Points count most; each line is sampled along its segments.
  const double grow = kMarkerRadius * s;
  const auto covered = [&](const Rect& r) {
    const Rect near = r.grown(grow);
    int score = 0;
    for (const auto& series : points)
      for (std::size_t i = 0; i < series.size(); ++i) {
        if (near.contains(series[i][0], series[i][1])) score += kPointCover;
        if (i == 0) continue;
        for (int k = 1; k < 20; ++k) {
          const double t = k / 20.0;
          score += near.contains(series[i - 1][0] + t * (series[i][0] - series[i - 1][0]),
                                 series[i - 1][1] + t * (series[i][1] - series[i - 1][1]));
        }
      }
    return score;
  };
  const Rect* best = &corners[0];
  int best_score = covered(*best);
  for (const Rect& r : corners) {
    const int score = covered(r);
    if (score < best_score) {
      best = &r;
      best_score = score;
    }
  }
  return LegendPlace{*best, best_score};
}

// The legend's height and the gap to the frame, when it stands above the frame.
double legend_band(Canvas& p, const Legend& legend) {
  return p.legend_height(legend.entries.size()) + kLegendInset * p.s();
}

void render(cairo_t* cr, const ChartDef& def, double width, double height) {
  Canvas p(cr, width, height);
  Layout lay = layout(p, def, width, height);
  auto points = points_of(def, lay);
  const Legend legend = legend_of(def);
  std::optional<LegendPlace> place = legend_box(p, lay, legend, points);
  // Every corner of the frame would hide a point, or as much line as a point counts: the frame
  // gives up a band at its top, if it keeps half its height, and the legend stands there,
  // right-aligned over it.
  const double band = place ? legend_band(p, legend) : 0.0;
  if (place && place->covered >= kPointCover && band < 0.5 * lay.frame.h) {
    lay = layout(p, def, width, height, band);
    points = points_of(def, lay);
    const Rect& f = lay.frame;
    place->box.x = f.x + f.w - place->box.w;
    place->box.y = f.y - band;
  }

  p.paint(rgb(0xffffff));
  draw_grid(p, lay);
  draw_marks(p, lay, def.marks);
  draw_series(p, lay, points);
  draw_axes(p, lay);
  draw_labels(p, lay, def, width, height);
  if (place)
    p.legend(place->box, legend.entries, kLegend, [&](std::size_t entry, double x, double y) {
      const std::size_t i = legend.series[entry];
      if (points[i].size() <= kMarkedPoints) {
        marker(p, marker_of(i), x, y, colour_of(i));
        return;
      }
      cairo_new_path(p.cr());
      p.segment(x - 2.0 * kMarkerRadius * p.s(), y, x + 2.0 * kMarkerRadius * p.s(), y);
      p.pen(line_pen(i));
      cairo_stroke(p.cr());
    });
}

}  // namespace

void chart(const ChartDef& def) {
  picture_format(def.file);  // checked before anything is computed
  check_def(def);
  check_writable(def.file);
  write_picture(def.file, def.width, def.height, def.title,
                [&](cairo_t* cr) { render(cr, def, def.width, def.height); });
}

}  // namespace edem
