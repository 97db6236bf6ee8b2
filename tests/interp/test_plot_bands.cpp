// plot{ colour = }: bands over a fixed range so that two pictures compare, any number of them, the
// legend in one unit, a title of the script's; excavated zones are not drawn.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "interp_test.hpp"
#include "model/model_plot.hpp"

namespace edem {
namespace {

using test::contains;

// Two stacked blocks; the region "cut" (x 1 to 3, y 0 to 1) excavated and the rest settled.
void dig(Interpreter& interpreter) {
  interpreter.context().quiet = true;
  test::expect_runs(interpreter, R"(
    model{ title = "stack" }
    block{ x = {0, 4}, y = {0, 2} }
    block{ x = {0, 4}, y = {2, 4} }
    region{ name = "cut", polygon = {{1, 0}, {3, 0}, {3, 1}, {1, 1}} }
    zone{ edge = 0.25 }
    material{ "rock", density = 2500, young = 1e8, poisson = 0.25 }
    assign{ material = "rock" }
    joint_material{ "joint", kn = 1e10, ks = 1e10, friction = 30 }
    jassign{ material = "joint" }
    gravity{ 0, -9.81 }
    boundary{ side = "bottom", fix = "xy" }
    solve{ ratio = 1e-6 }
    excavate{ "cut" }
    solve{ ratio = 1e-6 }
  )");
}

std::vector<std::string> band_labels(const Scene& scene) {
  std::vector<std::string> labels;
  for (const LegendEntry& e : scene.legend)
    if (e.label.rfind("u: ", 0) == 0) labels.push_back(e.label);
  return labels;
}

TEST(PlotBands, AFixedRangeInBandsOfOneUnit) {
  Interpreter interpreter;
  dig(interpreter);
  Model& model = interpreter.context().model();
  PlotDef def;
  def.show = {"blocks"};
  def.colour = std::string("u");
  def.range = std::array<double, 2>{0.0, 0.004};
  def.bands = 10;
  def.title = std::string("u, fixed range");
  const Scene scene = gather_scene(model, def);
  EXPECT_EQ(scene.title, "u, fixed range");
  const auto labels = band_labels(scene);
  ASSERT_EQ(labels.size(), 10u);
  EXPECT_EQ(labels.front(), "u: 3.6 to 4 mm");  // the legend reads from the highest down
  EXPECT_EQ(labels.back(), "u: 0 to 0.4 mm");
  // A range the values pass: the end band says so.
  def.range = std::array<double, 2>{0.0, 0.001};
  def.bands = 4;
  const auto narrow = band_labels(gather_scene(model, def));
  ASSERT_EQ(narrow.size(), 4u);
  EXPECT_EQ(narrow.front(), "u: 0.75 mm and above");
  // From the values' own range, every bound in the unit of the largest: no "8.52 mm to 0.0106 m".
  def.range.reset();
  def.bands = 8;
  for (const std::string& label : band_labels(gather_scene(model, def)))
    EXPECT_TRUE(label.ends_with(" mm")) << label;
}

TEST(PlotBands, BadRangeOrBandsAreRefused) {
  Interpreter interpreter;
  dig(interpreter);
  Model& model = interpreter.context().model();
  PlotDef def;
  def.colour = std::string("u");
  def.range = std::array<double, 2>{0.004, 0.0};
  EXPECT_THROW(gather_scene(model, def), Error);
  EXPECT_TRUE(contains(test::error_of(interpreter, "plot{ file = 'x.png', colour = 'u', range = {1, 0} }"),
                       "range must be {lo, hi} with lo < hi, got {1, 0}"));
  EXPECT_TRUE(contains(test::error_of(interpreter, "plot{ file = 'x.png', colour = 'u', bands = 1 }"), "bands"));
  EXPECT_TRUE(contains(test::error_of(interpreter, "plot{ file = 'x.png', range = {0, 1} }"),
                       "range and bands are for colour = ...: give a colour"));
}

TEST(PlotBands, ExcavatedZonesAreNotDrawn) {
  Interpreter interpreter;
  dig(interpreter);
  PlotDef def;
  def.show = {"zones"};
  const Scene scene = gather_scene(interpreter.context().model(), def);
  int inside = 0, segments = 0;
  for (const Scene::Lines& l : scene.lines)
    for (size_t s = 0; s < l.lines.starts.size(); ++s) {
      const Vec2 a = l.lines.points[l.lines.starts[s]], b = l.lines.points[l.lines.starts[s] + 1];
      const Vec2 mid = 0.5 * (a + b);
      ++segments;
      inside += mid.x > 1.01 && mid.x < 2.99 && mid.y > 0.01 && mid.y < 0.99;
    }
  EXPECT_GT(segments, 100);
  EXPECT_EQ(inside, 0) << "zone edges inside the excavated cut";
}

// vectors = "displacement": arrows on a grid, the largest displacement named in the legend.
TEST(PlotBands, DisplacementVectors) {
  Interpreter interpreter;
  dig(interpreter);
  Model& model = interpreter.context().model();
  PlotDef def;
  def.show = {"blocks"};
  def.vectors = std::string("displacement");
  const Scene scene = gather_scene(model, def);
  double largest = 0.0;
  for (int g = 0; g < model.mesh().gp_count(); ++g) largest = std::max(largest, norm(model.gridpoint(g).u));
  bool named = false;
  for (const LegendEntry& e : scene.legend) named = named || e.label.rfind("displacement (largest ", 0) == 0;
  EXPECT_TRUE(named);
  size_t arrows = 0;
  for (const Scene::Lines& l : scene.lines) arrows = std::max(arrows, l.lines.starts.size());
  EXPECT_GT(arrows, 100u);   // a shaft and a head each
  EXPECT_LT(arrows, 2000u);  // on a grid of about 30 cells across, not one a zone
  EXPECT_GT(largest, 0.0);
  def.vectors = std::string("velocity");
  EXPECT_THROW(gather_scene(model, def), Error);
}

// axes = true: coordinates along the bottom and left edges; without, the picture is as it was.
TEST(PlotBands, AxesTickTheCoordinates) {
  Interpreter interpreter;
  dig(interpreter);
  test::expect_runs(interpreter, R"(
    plot{ file = "plain.png", show = {"blocks"} }
    plot{ file = "axes.png", show = {"blocks"}, axes = true }
  )");
  PlotDef def;
  def.axes = true;
  EXPECT_TRUE(gather_scene(interpreter.context().model(), def).axes);
  const auto size = [](const char* f) { return std::filesystem::file_size(f); };
  EXPECT_GT(size("axes.png"), size("plain.png")) << "no tick labels drawn";
  std::filesystem::remove("plain.png");
  std::filesystem::remove("axes.png");
}

// deform = k: the zones and the blocks' outlines drawn where they are, displacements magnified k
// times; the layers drawn from the blocks' own geometry are refused with it.
TEST(PlotBands, DeformMagnifiesTheDisplacements) {
  Interpreter interpreter;
  dig(interpreter);
  Model& model = interpreter.context().model();
  double settled = 0.0;  // the top's settlement, 2 m above the cut's middle
  for (int g = 0; g < model.mesh().gp_count(); ++g) {
    const GridpointView v = model.gridpoint(g);
    if (std::abs(v.position.y - 4.0) < 1e-9 && std::abs(v.position.x - 2.0) < 0.3) settled = std::min(settled, v.u.y);
  }
  ASSERT_LT(settled, -1e-3);
  PlotDef def;
  def.show = {"zones", "blocks"};
  def.deform = 100.0;
  const Scene scene = gather_scene(model, def);
  double top = -1e300;
  for (const Scene::Lines& l : scene.lines)
    for (const Vec2& p : l.lines.points)
      if (std::abs(p.x - 2.0) < 0.3) top = std::max(top, p.y);
  EXPECT_NEAR(top, 4.0 + 100.0 * settled, 100.0 * 0.2 * std::abs(settled)) << "the top drawn 100 times its settlement down";
  EXPECT_TRUE(contains(scene.note, "displacements x 100"));
  def.show = {"joints"};
  try {
    gather_scene(model, def);
    ADD_FAILURE() << "joints drawn deformed";
  } catch (const Error& e) {
    EXPECT_TRUE(contains(e.what(), "deform draws the zones' layers only"));
  }
}

// Each excavation stage keeps the cycle it was dug at (a history chart marks them), in checkpoints too.
TEST(PlotBands, StagesKeepTheCycleTheyWereDugAt) {
  Interpreter interpreter;
  dig(interpreter);
  test::expect_runs(interpreter, R"(
    fill{ "cut", material = "rock" }
    solve{ ratio = 1e-6 }
    excavate{ "cut" }
    save("stages.h5")
    restore("stages.h5")
  )");
  const std::vector<long>& cycles = interpreter.context().model().stage_cycles();
  ASSERT_EQ(cycles.size(), 2u);
  EXPECT_GT(cycles[0], 0);
  EXPECT_GT(cycles[1], cycles[0]);
  std::filesystem::remove("stages.h5");
}

}  // namespace
}  // namespace edem
