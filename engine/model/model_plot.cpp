// plot(): the layers of a model gathered into a scene of fills, styled lines, labels and a
// legend, which io/plot draws.
#include "model/model_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <tuple>
#include <numbers>
#include <optional>
#include <string_view>
#include <unordered_set>

#include "core/error.hpp"
#include "core/names.hpp"
#include "io/cairo_file.hpp"
#include "io/plot.hpp"
#include "model/model.hpp"

namespace edem {

const std::vector<std::string>& plot_layers() {
  static const std::vector<std::string> layers{"regions", "plastic", "prepass", "zones", "blocks",
                                               "joints",  "cracks",  "stress",  "bolts"};
  return layers;
}

const std::vector<std::string>& plot_colours() {
  static const std::vector<std::string> colours{"sxx", "syy", "sxy", "szz", "s1",
                                                "s3",  "ux",  "uy",  "u"};
  return colours;
}

namespace {

// ---------------------------------------------------------------------------------------
// What to draw, checked before anything is computed or written.

struct Layers {
  bool regions = false, plastic = false, prepass = false, zones = false, blocks = false,
       joints = false, cracks = false, stress = false, bolts = false;
};

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

Layers layers_of(const std::vector<std::string>& show) {
  const auto& valid = plot_layers();
  // The flag of each name in plot_layers(), in the same order.
  constexpr std::array kFlags{&Layers::regions, &Layers::plastic, &Layers::prepass,
                              &Layers::zones,   &Layers::blocks,  &Layers::joints,
                              &Layers::cracks,  &Layers::stress,  &Layers::bolts};
  static_assert(kFlags.size() == 9, "one flag per name in plot_layers()");
  if (show.empty()) fail("show lists no layers: use any of {}", join(valid));
  Layers layers;
  for (const auto& name : show) {
    const auto it = std::find(valid.begin(), valid.end(), name);
    if (it == valid.end())
      fail("unknown layer '{}'{}: layers are {}", name, did_you_mean(name, valid), join(valid));
    layers.*kFlags[static_cast<std::size_t>(it - valid.begin())] = true;
  }
  return layers;
}

// A window narrower than the model's geometric tolerance shows nothing it could tell apart.
void check_window(const std::optional<std::array<double, 4>>& window, double tolerance) {
  if (!window) return;
  const auto& [x0, x1, y0, y1] = *window;
  if (!(std::isfinite(x0) && std::isfinite(x1) && std::isfinite(y0) && std::isfinite(y1) &&
        x0 < x1 && y0 < y1))
    fail(
        "window must be {{x0, x1, y0, y1}} with x0 < x1 and y0 < y1, got {{{:g}, {:g}, {:g}, "
        "{:g}}}",
        x0, x1, y0, y1);
  if (x1 - x0 < tolerance || y1 - y0 < tolerance)
    fail("window is {:.3g} m by {:.3g} m, smaller than the model's geometric tolerance, {:.3g} m: nothing in it "
         "could be told apart; give a larger window",
         x1 - x0, y1 - y0, tolerance);
}

void check_colour(const std::string& colour) {
  if (colour.empty()) return;
  const auto& valid = plot_colours();
  if (std::find(valid.begin(), valid.end(), colour) == valid.end())
    fail("unknown colour quantity '{}'{}: quantities are {}", colour, did_you_mean(colour, valid),
         join(valid));
}

// ---------------------------------------------------------------------------------------
// Geometry gathered from the model, in metres.

// How a block edge is drawn. Tiers are in drawing order: later ones lie on top.
enum class Tier : std::uint8_t { potential, region, joint, crack, boundary };

struct EdgeClass {
  Tier tier = Tier::boundary;
  int set = -1;  // joint set, else -1
  bool glued = false;
  auto operator<=>(const EdgeClass&) const = default;
};

EdgeClass class_of(const EdgeOrigin& origin) {
  switch (origin.kind) {
    case EdgeKind::potential:
      return {Tier::potential, -1, false};
    case EdgeKind::region:
      return {Tier::region, -1, origin.glued};
    case EdgeKind::joint:
      return {Tier::joint, origin.set, origin.glued};
    case EdgeKind::crack:
      return {Tier::crack, -1, origin.glued};
    case EdgeKind::boundary:
      break;
  }
  return {Tier::boundary, -1, false};
}

// An undirected edge, identical for both blocks that share it (vertices are shared exactly).
struct EdgeKey {
  Vec2 a, b;
  bool operator==(const EdgeKey& o) const { return a == o.a && b == o.b; }
};

EdgeKey key_of(Vec2 p, Vec2 q) {
  const bool ordered = p.x < q.x || (p.x == q.x && p.y <= q.y);
  return ordered ? EdgeKey{p, q} : EdgeKey{q, p};
}

struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& k) const {
    std::size_t h = 0;
    for (const double v : {k.a.x, k.a.y, k.b.x, k.b.y})
      h = (h ^ std::hash<double>{}(v)) * 1099511628211ull;
    return h;
  }
};

using Classify = std::function<std::optional<EdgeClass>(const EdgeOrigin&)>;

// Every block edge once, sorted into classes; consecutive edges of one class along a ring are
// chained so that dash patterns run on across vertices.
std::map<EdgeClass, Polylines> collect_edges(const BlockSet& set, const Classify& classify) {
  std::map<EdgeClass, Polylines> out;
  std::unordered_set<EdgeKey, EdgeKeyHash> seen;
  auto walk = [&](const Ring& ring) {
    const std::size_t n = ring.points.size();
    if (n < 2 || ring.edges.size() != n) return;
    Polylines* chain = nullptr;  // the class whose last polyline ends at the current vertex
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = ring.points[i], b = ring.points[(i + 1) % n];
      const auto cls = classify(ring.edges[i]);
      if (!cls || !seen.insert(key_of(a, b)).second) {
        chain = nullptr;
        continue;
      }
      Polylines& lines = out[*cls];
      if (chain != &lines) lines.begin(a);
      lines.add(b);
      chain = &lines;
    }
  };
  for (const Block& block : set.blocks) {
    walk(block.outer);
    for (const Ring& hole : block.holes) walk(hole);
  }
  return out;
}

// The edges of the zones not excavated, each once (interior edges are shared by two zones).
Polylines zone_edges(const Model& model, const std::vector<Vec2>& at) {
  const Mesh& mesh = model.mesh();
  std::vector<std::uint64_t> keys;
  keys.reserve(mesh.zone_gp.size() * 3);
  const auto gp_count = static_cast<std::uint64_t>(mesh.gp_position.size());
  for (int z = 0; z < mesh.zone_count(); ++z) {
    if (model.zone_view(z).excavated != 0) continue;
    const auto& zone = mesh.zone_gp[static_cast<std::size_t>(z)];
    for (int i = 0; i < 3; ++i) {
      const auto a = static_cast<std::uint64_t>(zone[i]);
      const auto b = static_cast<std::uint64_t>(zone[(i + 1) % 3]);
      if (a >= gp_count || b >= gp_count) continue;
      keys.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  Polylines lines;
  lines.points.reserve(keys.size() * 2);
  lines.starts.reserve(keys.size());
  for (const std::uint64_t key : keys) {
    lines.begin(at[key >> 32]);
    lines.add(at[key & 0xffffffffu]);
  }
  return lines;
}

// Bounding box of every block's outer ring [m]; nullopt when there are no blocks.
std::optional<Box> extent_of(const BlockSet& set) {
  std::optional<Box> box;
  for (const Block& block : set.blocks) {
    for (const Vec2 p : block.outer.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      if (!box) box = Box{p.x, p.x, p.y, p.y};
      box->x0 = std::min(box->x0, p.x);
      box->x1 = std::max(box->x1, p.x);
      box->y0 = std::min(box->y0, p.y);
      box->y1 = std::max(box->y1, p.y);
    }
  }
  return box;
}

// ---------------------------------------------------------------------------------------
// Styles. Widths and dashes are in units of the canvas scale (about a pixel at 800 px).

// Qualitative colours for joint sets (no red: red means crack).
constexpr std::array kSetColours{rgb(0x1f77b4), rgb(0xff7f0e), rgb(0x2ca02c), rgb(0x9467bd),
                                 rgb(0x8c564b), rgb(0xe377c2), rgb(0xbcbd22), rgb(0x17becf)};
// Light fills for regions, neighbours told apart.
constexpr std::array kRegionColours{rgb(0xb3cde3), rgb(0xfbb4ae), rgb(0xccebc5), rgb(0xdecbe4),
                                    rgb(0xfed9a6), rgb(0xffffcc), rgb(0xe5d8bd), rgb(0xfddaec)};
// Yielded zones (plastic and prepass layers): shear, tension, both.
constexpr std::array kYieldColours{rgb(0xf4a582), rgb(0x92c5de), rgb(0xc2a5cf)};
constexpr Rgb kCrack = rgb(0xd62728);
constexpr Rgb kShearCrack = rgb(0x1a35d4);  // deeper than joint set 1's blue, and thicker

// Viridis at 8 steps: dark blue (lowest) to yellow (highest), readable in grey; other band
// counts are taken between them.
constexpr std::array kViridis{rgb(0x440154), rgb(0x46327e), rgb(0x365c8d), rgb(0x277f8e),
                              rgb(0x1fa187), rgb(0x4ac16d), rgb(0xa0da39), rgb(0xfde725)};

// The colour of band b of n, lowest first: 8 bands are viridis' own steps.
Rgb band_colour(int b, int n) {
  const double at = n > 1 ? static_cast<double>(b) * (kViridis.size() - 1) / (n - 1) : 0.0;
  const auto i = std::min(static_cast<std::size_t>(at), kViridis.size() - 2);
  const double t = at - static_cast<double>(i);
  const Rgb &a = kViridis[i], &c = kViridis[i + 1];
  return {a.r + t * (c.r - a.r), a.g + t * (c.g - a.g), a.b + t * (c.b - a.b)};
}

Rgb set_colour(int set) {
  return kSetColours[static_cast<std::size_t>(std::max(set, 0)) % kSetColours.size()];
}

// Joints coloured by set, cracks red, glued edges dashed, potential cracks dotted.
Pen pen_of(const EdgeClass& cls) {
  Pen pen{rgb(0x000000), 2.4, {}};  // boundary
  switch (cls.tier) {
    case Tier::potential:
      pen = {rgb(0x8c8c8c), 0.7, {1.5, 2.0}};
      break;
    case Tier::region:
      pen = {rgb(0x303030), 1.2, {}};
      break;
    case Tier::joint:
      pen = {set_colour(cls.set), 1.3, {}};
      break;
    case Tier::crack:
      pen = {kCrack, 1.8, {}};
      break;
    case Tier::boundary:
      return pen;
  }
  if (cls.glued) pen.dash = {6.0, 3.5};
  return pen;
}

// Joint sets are numbered from 1 in the order of the jset{} commands.
std::string label_of(const EdgeClass& cls) {
  const std::string glued = cls.glued ? ", glued" : "";
  switch (cls.tier) {
    case Tier::potential:
      return "potential crack";
    case Tier::region:
      return "region outline" + glued;
    case Tier::joint:
      return fmt::format("joint set {}{}", cls.set + 1, glued);
    case Tier::crack:
      return "crack" + glued;
    case Tier::boundary:
      break;
  }
  return "boundary";
}

// New cracks by how they broke, as in the seed paper's Figure 9: thicker than any edge, so that
// they read over the dotted potential crack they broke from.
Pen crack_pen(CrackMode mode) {
  return {mode == CrackMode::shear ? kShearCrack : kCrack, 3.2, {}};
}

std::string label_of(CrackMode mode, std::size_t count) {
  return fmt::format("{} crack ({})", mode == CrackMode::shear ? "shear" : "tension", count);
}

// Zones filled in one colour, each also outlined in it.
Pen fill_pen(Rgb colour) {
  return {colour, 0.5, {}};
}

// A filled area in the legend.
Pen swatch_pen(Rgb colour) {
  return {colour, 6.0, {}};
}

const Pen kCompressionTick{rgb(0x202020), 0.9, {}, false};
const Pen kTensionTick{rgb(0xd62728), 0.9, {}, false};
const Pen kBoltTension{rgb(0xb2182b), 2.2, {}};
const Pen kVectorPen{rgb(0x202020), 1.1, {}};
const Pen kBoltCompression{rgb(0x2166ac), 2.2, {}};
const Pen kBoltOut{rgb(0x9a9a9a), 1.6, {3.0, 2.0}};
const Pen kBlockPen{rgb(0x404040), 0.8, {}, false};
const Pen kZonePen{rgb(0xc4c4c4), 0.45, {}, false};

// ---------------------------------------------------------------------------------------
// The layers, gathered.

// The new cracks of one mode, each its section's segment [m].
struct CrackBatch {
  CrackMode mode = CrackMode::none;
  Polylines lines;  // one polyline per crack
};

// Drawing and legend order.
constexpr std::array kCrackModes{CrackMode::tension, CrackMode::shear};

// A crack is drawn as the section that broke: `length` along `angle` through its midpoint.
void add_section(Polylines& lines, const CrackView& crack) {
  const double a = crack.angle * std::numbers::pi / 180.0;
  const Vec2 half = 0.5 * crack.length * Vec2{std::cos(a), std::sin(a)};
  lines.begin(crack.position - half);
  lines.add(crack.position + half);
}

// The broken potential-crack sections by mode; modes without cracks are left out.
std::vector<CrackBatch> new_cracks_of(const Model& model) {
  std::vector<CrackBatch> out;
  for (const CrackMode mode : kCrackModes) {
    CrackBatch batch{mode, {}};
    for (int id = 0; id < model.crack_count(); ++id)
      if (model.crack(id).mode == mode) add_section(batch.lines, model.crack(id));
    if (!batch.lines.empty()) out.push_back(std::move(batch));
  }
  return out;
}

// Everything the picture needs from the model, by layer, gathered before any file is opened.
struct Gathered {
  std::string title;
  Box box{};
  std::size_t blocks = 0;
  std::optional<std::size_t> zones;  // when the zones layer is shown
  std::vector<RegionDef> regions;
  Polylines zone_lines;
  Polylines block_lines;
  std::map<EdgeClass, Polylines> edges;  // joints and cracks layers
  std::vector<CrackBatch> new_cracks;    // cracks layer
  // plastic and prepass layers: zones that yielded in shear only, tension only, both.
  std::array<std::vector<Polygon>, 3> yielded;
  std::string yield_source;  // "plastic" or "prepass", for the legend
  // colour: zones in place by band, lowest first, and each band's legend line
  std::vector<std::vector<Polygon>> bands;
  std::vector<std::string> band_labels;  // highest first, as the legend reads
  // stress layer: ticks in compression and in tension, and the largest magnitude of each [Pa]
  Polylines compression_ticks, tension_ticks;
  double max_compression = 0.0, max_tension = 0.0;
  // bolts layer: segments in tension, compression, out of service; largest force of each [N/m]
  Polylines bolts_tension, bolts_compression, bolts_out;
  double max_bolt_tension = 0.0, max_bolt_compression = 0.0;
  // vectors: displacement arrows; the largest displacement [m]
  Polylines arrows;
  double max_displacement = 0.0;
  double deform = 0.0;  // displacements magnified this many times (0: not drawn deformed)
};

// Zones in place: not excavated, with a material.
bool in_place(const ZoneView& zone) {
  return zone.excavated == 0 && !zone.material.empty();
}

Polygon triangle_of(const Mesh& mesh, const std::vector<Vec2>& at, int zone) {
  Polygon triangle;
  for (int gp : mesh.zone_gp[static_cast<std::size_t>(zone)]) triangle.push_back(at[static_cast<std::size_t>(gp)]);
  return triangle;
}

// Where each gridpoint is drawn: where it was made, moved by `deform` times its displacement.
std::vector<Vec2> drawn_positions(const Model& model, double deform) {
  std::vector<Vec2> at = model.mesh().gp_position;
  if (deform > 0.0)
    for (std::size_t gp = 0; gp < at.size(); ++gp) at[gp] = at[gp] + deform * model.gridpoint(static_cast<int>(gp)).u;
  return at;
}

// The blocks' outlines as their zones' outer edges (an edge of one zone of its block only), drawn
// at `at`: the deformed shape of the blocks.
Polylines block_edges_of_zones(const Model& model, const std::vector<Vec2>& at) {
  const Mesh& mesh = model.mesh();
  std::map<std::tuple<int, int, int>, int> uses;  // (block, lower gp, higher gp) -> zones using it
  for (int z = 0; z < mesh.zone_count(); ++z) {
    if (model.zone_view(z).excavated != 0) continue;
    const auto& corners = mesh.zone_gp[static_cast<std::size_t>(z)];
    for (int i = 0; i < 3; ++i) {
      const int a = corners[static_cast<std::size_t>(i)], b = corners[static_cast<std::size_t>((i + 1) % 3)];
      ++uses[{mesh.zone_block[static_cast<std::size_t>(z)], std::min(a, b), std::max(a, b)}];
    }
  }
  Polylines lines;
  for (const auto& [key, count] : uses)
    if (count == 1) {
      lines.begin(at[static_cast<std::size_t>(std::get<1>(key))]);
      lines.add(at[static_cast<std::size_t>(std::get<2>(key))]);
    }
  return lines;
}

// Zones that yielded, as the seed's Figure 8 shows them: in the model's own run (plastic: now
// or earlier) or in the last prepass{} (over all its stages), filled by mode.
void gather_yielded(const Model& model, bool from_prepass, const std::vector<Vec2>& at, Gathered& g) {
  const Mesh& mesh = model.mesh();
  const std::vector<std::uint8_t>& prepass = model.prepass_yield();
  if (from_prepass && prepass.size() != mesh.zone_gp.size())
    fail("show = \"prepass\": no prepass{{}} result for this mesh (run prepass{{}} first)");
  g.yield_source = from_prepass ? "prepass" : "plastic";
  for (int z = 0; z < static_cast<int>(mesh.zone_gp.size()); ++z) {
    const std::uint8_t bits =
        from_prepass ? prepass[static_cast<std::size_t>(z)] : model.zone_view(z).state;
    const bool shear = bits & (kShearNow | kShearPast),
               tension = bits & (kTensionNow | kTensionPast);
    if (!shear && !tension) continue;
    g.yielded[shear && tension ? 2 : shear ? 0 : 1].push_back(triangle_of(mesh, at, z));
  }
}

// The multiple of `unit` ("m" or "Pa") that suits values up to `largest` in size: mm, MPa, ...
std::pair<double, std::string> unit_for(double largest, const char* unit) {
  const double a = std::abs(largest);
  if (std::string_view(unit) == "m") return a != 0 && a < 0.01 ? std::pair{1e3, std::string("mm")} : std::pair{1.0, std::string("m")};
  if (a >= 1e6) return {1e-6, "MPa"};
  if (a >= 1e3) return {1e-3, "kPa"};
  return {1.0, "Pa"};
}

// An SI value in engineering notation, short: "-1.25 MPa", "3.4 mm".
std::string with_unit(double value, const char* unit) {
  const auto [factor, name] = unit_for(value, unit);
  return fmt::format("{:.3g} {}", value * factor, name);
}

// Zones in place by `quantity` in `count` equal bands over `range` (none: from its least to its
// largest value); beyond the range, the end bands. The legend gives every bound in one unit.
void gather_bands(const Model& model, const std::string& quantity, std::optional<std::array<double, 2>> range,
                  int count, const std::vector<Vec2>& at, Gathered& g) {
  const Mesh& mesh = model.mesh();
  if (mesh.zone_count() == 0)
    fail("colour = \"{}\": the model has no zones (zone{{}} first)", quantity);
  const bool displacement = quantity == "ux" || quantity == "uy" || quantity == "u";
  std::vector<int> zones;
  std::vector<double> values;
  for (int z = 0; z < mesh.zone_count(); ++z) {
    const ZoneView zone = model.zone_view(z);
    if (!in_place(zone)) continue;
    double value = 0.0;
    if (displacement) {
      for (int gp : mesh.zone_gp[static_cast<std::size_t>(z)]) {
        const Vec2 u = model.gridpoint(gp).u;
        value += (quantity == "ux" ? u.x : quantity == "uy" ? u.y : norm(u)) / 3.0;
      }
    } else {
      const std::map<std::string_view, double> stress{{"sxx", zone.sxx}, {"syy", zone.syy},
                                                      {"sxy", zone.sxy}, {"szz", zone.szz},
                                                      {"s1", zone.s1},   {"s3", zone.s3}};
      value = stress.at(quantity);
    }
    zones.push_back(z);
    values.push_back(value);
  }
  if (zones.empty()) fail("colour = \"{}\": no zone is in place to colour", quantity);
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  const double lo = range ? (*range)[0] : *low, hi = range ? (*range)[1] : *high;
  const double width = (hi - lo) / count;
  const bool below = *low < lo, above = *high > hi;  // values beyond a fixed range
  const char* unit = displacement ? "m" : "Pa";
  const auto [factor, name] = unit_for(std::max(std::abs(lo), std::abs(hi)), unit);
  const auto show = [&, factor = factor](double v) { return fmt::format("{:.3g}", v * factor); };
  g.bands.assign(static_cast<std::size_t>(count), {});
  for (std::size_t i = 0; i < zones.size(); ++i) {
    const int band = width > 0 ? std::clamp(static_cast<int>(std::floor((values[i] - lo) / width)), 0, count - 1) : 0;
    g.bands[static_cast<std::size_t>(band)].push_back(triangle_of(mesh, at, zones[i]));
  }
  for (int b = count - 1; b >= 0; --b) {  // the legend reads from the highest down
    const double from = lo + b * width, to = lo + (b + 1) * width;
    if (!(width > 0)) g.band_labels.push_back(fmt::format("{}: {} {}", quantity, show(lo), name));
    else if (b == count - 1 && above) g.band_labels.push_back(fmt::format("{}: {} {} and above", quantity, show(from), name));
    else if (b == 0 && below) g.band_labels.push_back(fmt::format("{}: below {} {}", quantity, show(to), name));
    else g.band_labels.push_back(fmt::format("{}: {} to {} {}", quantity, show(from), show(to), name));
  }
}

// Principal stress ticks through each zone's centroid, of length in proportion to magnitude: the
// largest magnitude anywhere spans about the zone's width.
void gather_stress(const Model& model, Gathered& g) {
  const Mesh& mesh = model.mesh();
  std::vector<ZoneView> zones;
  double largest = 0.0;
  for (int z = 0; z < mesh.zone_count(); ++z) {
    ZoneView zone = model.zone_view(z);
    if (!in_place(zone)) continue;
    largest = std::max({largest, std::abs(zone.s1), std::abs(zone.s3)});
    zones.push_back(std::move(zone));
  }
  if (zones.empty() || !(largest > 0)) return;
  for (const ZoneView& zone : zones) {
    const double tick =
        1.6 * std::sqrt(mesh.zone_area(zone.id));  // about its zone across, graded as the mesh
    // The direction of the algebraically larger principal stress s3; s1 is at right angles to it.
    const double angle = 0.5 * std::atan2(2.0 * zone.sxy, zone.sxx - zone.syy);
    const Vec2 d3{std::cos(angle), std::sin(angle)}, d1{-d3.y, d3.x};
    for (const auto& [value, dir] : {std::pair{zone.s1, d1}, std::pair{zone.s3, d3}}) {
      const double half = 0.5 * tick * std::abs(value) / largest;
      if (!(half > 0)) continue;
      Polylines& lines = value < 0 ? g.compression_ticks : g.tension_ticks;
      lines.begin(zone.centroid - half * dir);
      lines.add(zone.centroid + half * dir);
      (value < 0 ? g.max_compression : g.max_tension) =
          std::max(value < 0 ? g.max_compression : g.max_tension, std::abs(value));
    }
  }
}

// Displacement arrows on a grid of about 30 cells across the model: in each cell, the first zone
// in place, from its centroid as drawn (deformed, with deform) along its corners' mean
// displacement; the largest a cell long.
void gather_vectors(const Model& model, const std::vector<Vec2>& drawn, Gathered& g) {
  const Mesh& mesh = model.mesh();
  const double cell = std::max(g.box.x1 - g.box.x0, g.box.y1 - g.box.y0) / 30.0;
  std::map<std::pair<long, long>, std::pair<Vec2, Vec2>> picked;  // by cell: centroid, displacement
  for (int z = 0; z < mesh.zone_count(); ++z) {
    const ZoneView zone = model.zone_view(z);
    if (!in_place(zone)) continue;
    const std::pair<long, long> key{std::lround(std::floor((zone.centroid.x - g.box.x0) / cell)),
                                    std::lround(std::floor((zone.centroid.y - g.box.y0) / cell))};
    if (picked.count(key)) continue;
    Vec2 u{0.0, 0.0}, centre{0.0, 0.0};
    for (int gp : mesh.zone_gp[static_cast<std::size_t>(z)]) {
      u = u + (1.0 / 3.0) * model.gridpoint(gp).u;
      centre = centre + (1.0 / 3.0) * drawn[static_cast<std::size_t>(gp)];
    }
    picked[key] = {centre, u};
    g.max_displacement = std::max(g.max_displacement, norm(u));
  }
  if (picked.empty() || !(g.max_displacement > 0.0)) return;
  const double scale = cell / g.max_displacement;
  for (const auto& [key, at_u] : picked) {
    const auto& [at, u] = at_u;
    const Vec2 d = scale * u;
    const double length = norm(d);
    if (!(length > 0.02 * cell)) continue;  // too short to see
    const Vec2 tip = at + d, dir = (1.0 / length) * d, normal{-dir.y, dir.x};
    const double head = 0.3 * length;  // the head's length, half as wide each side
    g.arrows.begin(at);
    g.arrows.add(tip);
    g.arrows.begin(tip - head * dir + 0.5 * head * normal);
    g.arrows.add(tip);
    g.arrows.add(tip - head * dir - 0.5 * head * normal);
  }
}

void gather_bolts(const Model& model, Gathered& g) {
  for (int b = 0; b < model.bolt_count(); ++b) {
    const BoltView bolt = model.bolt(b);
    for (const BoltSegmentView& seg : bolt.segments) {
      const bool out = bolt.removed || seg.state == "broken" || seg.state == "removed";
      Polylines& lines = out ? g.bolts_out : seg.force >= 0 ? g.bolts_tension : g.bolts_compression;
      lines.begin(seg.a);
      lines.add(seg.b);
      if (out) continue;
      double& largest = seg.force >= 0 ? g.max_bolt_tension : g.max_bolt_compression;
      largest = std::max(largest, std::abs(seg.force));
    }
  }
}

Gathered gather(Model& model, const Layers& layers, const PlotDef& def) {
  Gathered g;
  const std::vector<Vec2> at = drawn_positions(model, def.deform);
  g.title = def.title.empty() ? model.title() : def.title;
  const BlockSet& set = model.blocks();
  const auto box = extent_of(set);
  if (!box) fail("nothing to plot: the model has no blocks (add a block{{}} first)");
  g.box = *box;
  g.blocks = set.blocks.size();
  if (layers.regions) g.regions = model.regions();
  if (layers.zones) {
    const Mesh& mesh = model.mesh();
    g.zones = mesh.zone_gp.size();
    g.zone_lines = zone_edges(model, at);
  }
  // Edges the joints or cracks layer restyles are left out of the neutral block outlines,
  // so that dashes are not filled in underneath.
  const bool joints = layers.joints, cracks = layers.cracks;
  const Classify neutral = [&](const EdgeOrigin& o) -> std::optional<EdgeClass> {
    if (joints || (cracks && o.kind == EdgeKind::crack)) return std::nullopt;
    return EdgeClass{};
  };
  const Classify styled = [&](const EdgeOrigin& o) -> std::optional<EdgeClass> {
    if (!joints && o.kind != EdgeKind::crack) return std::nullopt;
    return class_of(o);
  };
  if (layers.blocks)
    g.block_lines = def.deform > 0.0 ? block_edges_of_zones(model, at) : std::move(collect_edges(set, neutral)[EdgeClass{}]);
  if (joints || cracks) g.edges = collect_edges(set, styled);
  if (cracks) g.new_cracks = new_cracks_of(model);
  if (layers.plastic || layers.prepass) gather_yielded(model, layers.prepass, at, g);
  if (!def.colour.empty()) gather_bands(model, def.colour, def.range, def.bands, at, g);
  if (layers.stress) gather_stress(model, g);
  if (layers.bolts) gather_bolts(model, g);
  if (def.vectors == "displacement") gather_vectors(model, at, g);
  if (def.deform > 0.0) g.deform = def.deform;
  return g;
}

// The edge styles drawn (block outlines and zones explain themselves), then the new cracks
// with their counts, the colour bands, the stress ticks, the bolts and the yielded zones.
std::vector<LegendEntry> legend_of(const Gathered& g) {
  // Boundary, joint sets in order, cracks, region outlines, potential cracks.
  auto order = [](Tier tier) {
    constexpr std::array kOrder{4, 3, 1, 2, 0};  // position in the legend, by tier
    return kOrder[static_cast<std::size_t>(tier)];
  };
  std::vector<EdgeClass> classes;
  for (const auto& [cls, lines] : g.edges)
    if (!lines.empty()) classes.push_back(cls);
  std::stable_sort(classes.begin(), classes.end(), [&](const EdgeClass& a, const EdgeClass& b) {
    return order(a.tier) < order(b.tier);
  });
  std::vector<LegendEntry> entries;
  for (const EdgeClass& cls : classes) entries.push_back({label_of(cls), pen_of(cls)});
  for (const CrackBatch& batch : g.new_cracks)
    entries.push_back({label_of(batch.mode, batch.lines.starts.size()), crack_pen(batch.mode)});
  const int bands = static_cast<int>(g.band_labels.size());
  for (int i = 0; i < bands; ++i)
    entries.push_back({g.band_labels[static_cast<std::size_t>(i)], swatch_pen(band_colour(bands - 1 - i, bands))});
  if (!g.compression_ticks.empty())
    entries.push_back(
        {"principal stress, compression (largest " + with_unit(g.max_compression, "Pa") + ")",
         kCompressionTick});
  if (!g.tension_ticks.empty())
    entries.push_back({"principal stress, tension (largest " + with_unit(g.max_tension, "Pa") + ")",
                       kTensionTick});
  if (!g.bolts_tension.empty())
    entries.push_back(
        {fmt::format("bolt in tension (largest {:.3g} kN/m)", g.max_bolt_tension * 1e-3),
         kBoltTension});
  if (!g.bolts_compression.empty())
    entries.push_back(
        {fmt::format("bolt in compression (largest {:.3g} kN/m)", g.max_bolt_compression * 1e-3),
         kBoltCompression});
  if (!g.bolts_out.empty()) entries.push_back({"bolt broken or out of service", kBoltOut});
  if (!g.arrows.empty())
    entries.push_back({"displacement (largest " + with_unit(g.max_displacement, "m") + ")", kVectorPen});
  constexpr std::array<const char*, 3> kYieldNames{"shear", "tension", "shear and tension"};
  for (std::size_t i = 0; i < g.yielded.size(); ++i)
    if (!g.yielded[i].empty())
      entries.push_back({fmt::format("{}: {} ({} zone{})", g.yield_source, kYieldNames[i],
                                     g.yielded[i].size(), g.yielded[i].size() == 1 ? "" : "s"),
                         swatch_pen(kYieldColours[i])});
  return entries;
}

std::string counts_of(const Gathered& g) {
  std::string counts = fmt::format("{} block{}", g.blocks, g.blocks == 1 ? "" : "s");
  if (g.deform > 0.0) counts = fmt::format("displacements x {:g}; ", g.deform) + counts;
  if (g.zones && *g.zones == 0) counts += ", not zoned";
  if (g.zones && *g.zones > 0)
    counts += fmt::format(", {} zone{}", *g.zones, *g.zones == 1 ? "" : "s");
  return counts;
}

// Regions with a light fill, outlined a shade darker, and their names.
void add_regions(const std::vector<RegionDef>& regions, Scene& scene) {
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const Polygon& polygon = regions[i].polygon;
    if (polygon.size() < 3) continue;
    const Rgb fill = kRegionColours[i % kRegionColours.size()];
    scene.fills.push_back(
        {{polygon}, fill, 0.7, {{fill.r * 0.6, fill.g * 0.6, fill.b * 0.6}, 0.8, {}}});
    if (!regions[i].name.empty())
      scene.labels.push_back({regions[i].name, centroid(polygon), bounding_box(polygon)});
  }
}

// The layers in drawing order: fills (regions, colour bands, yielded zones), then lines (zones,
// block outlines, edges by class, new cracks, stress ticks, bolts), then region names.
Scene scene_of(Gathered g) {
  Scene scene;
  scene.title = g.title;
  scene.box = g.box;
  scene.legend = legend_of(g);
  scene.note = counts_of(g);
  add_regions(g.regions, scene);
  const int bands = static_cast<int>(g.bands.size());
  for (int b = 0; b < bands; ++b) {
    const Rgb colour = band_colour(b, bands);
    scene.fills.push_back({std::move(g.bands[static_cast<std::size_t>(b)]), colour, 1.0, fill_pen(colour)});
  }
  // Over colour bands the yielded zones are translucent, so that the contours show through.
  const double yield_opacity = bands > 0 ? 0.45 : 1.0;
  for (std::size_t i = 0; i < g.yielded.size(); ++i)
    scene.fills.push_back(
        {std::move(g.yielded[i]), kYieldColours[i], yield_opacity, fill_pen(kYieldColours[i])});
  auto add = [&](Polylines& lines, const Pen& pen, bool hairlines = false) {
    scene.lines.push_back({std::move(lines), pen, hairlines});
  };
  add(g.zone_lines, kZonePen, true);
  add(g.block_lines, kBlockPen);
  for (auto& [cls, lines] : g.edges) add(lines, pen_of(cls));
  for (CrackBatch& batch : g.new_cracks) add(batch.lines, crack_pen(batch.mode));
  add(g.compression_ticks, kCompressionTick);
  add(g.tension_ticks, kTensionTick);
  add(g.bolts_out, kBoltOut);
  add(g.bolts_compression, kBoltCompression);
  add(g.bolts_tension, kBoltTension);
  add(g.arrows, kVectorPen);
  return scene;
}

}  // namespace

void plot(Model& model, const PlotDef& def) {
  picture_format(def.file);  // checked before anything is computed
  check_size(def.width, def.height);
  check_window(def.window, model.tolerance());
  check_writable(def.file);
  plot_scene(gather_scene(model, def), def.file, def.width, def.height);
}

Scene gather_scene(Model& model, const PlotDef& def) {
  const Layers layers = layers_of(def.show);
  check_colour(def.colour);
  if (def.range && !((*def.range)[0] < (*def.range)[1] && std::isfinite((*def.range)[0]) && std::isfinite((*def.range)[1])))
    fail("range must be {{lo, hi}} with lo < hi, got {{{}, {}}}", (*def.range)[0], (*def.range)[1]);
  if (def.bands < 2 || def.bands > 16) fail("bands must be 2 to 16, got {}", def.bands);
  if ((def.range || def.bands != 8) && def.colour.empty()) fail("range and bands are for colour = ...: give a colour");
  if (!(def.deform >= 0.0 && std::isfinite(def.deform))) fail("deform must be a number >= 0, got {}", def.deform);
  if (def.deform > 0.0 && (layers.joints || layers.cracks || layers.stress || layers.bolts))
    fail("deform draws the zones' layers only (regions, plastic, prepass, zones, blocks, a colour, vectors); "
         "leave out joints, cracks, stress and bolts, or deform");
  if (def.deform > 0.0 && model.mesh().zone_count() == 0) fail("deform needs zones: zone{{}} the blocks first");
  if (!def.vectors.empty() && def.vectors != "displacement")
    fail("vectors must be \"displacement\", got \"{}\"", def.vectors);
  Scene scene = scene_of(gather(model, layers, def));
  if (def.window)
    scene.box = Box{(*def.window)[0], (*def.window)[1], (*def.window)[2], (*def.window)[3]};
  scene.axes = def.axes;
  return scene;
}

}  // namespace edem
