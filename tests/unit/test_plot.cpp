// plot{}: a picture of each file type with the right header, and bad input rejected
// without leaving a file behind.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/temp_file.hpp"
#include "model/model.hpp"
#include "model/model_plot.hpp"
#include "picture_files.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

// A 10 m box cut by two joint sets and a crack, with a glued square region, zoned.
Model jointed_box(bool zoned = true, bool glued = true) {
  Model model(ModelDef{"Plot test: jointed box"});
  model.add_block(BlockDef{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
  JointSetDef main_set;
  main_set.angle = 30;
  main_set.spacing = {2.5};
  model.add_joint_set(main_set);
  JointSetDef cross;
  cross.angle = -60;
  cross.spacing = {3.0};
  cross.origin = {0.3, 0.7};
  model.add_joint_set(cross);
  model.add_crack(CrackDef{{1.2, 8.1}, {6.3, 9.2}});
  model.add_region(RegionDef{"opening", {{4, 4}, {6, 4}, {6, 6}, {4, 6}}, glued});
  if (zoned) {
    ZoneDef zone;
    zone.edge = 0.6;
    model.zone(zone);
  }
  return model;
}

std::string message_of(Model& model, const PlotDef& def) {
  try {
    plot(model, def);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

using test::read_all;

class PlotTest : public test::PictureDir {};

PlotDef all_layers(const std::string& file) {
  PlotDef def;
  def.file = file;
  def.show = {"regions", "zones", "blocks", "joints"};
  return def;
}

TEST_F(PlotTest, WritesPngOfTheRequestedSize) {
  Model model = jointed_box();
  PlotDef def = all_layers(file("box.png"));
  def.width = 640;
  def.height = 480;
  plot(model, def);
  const std::string data = read_all(def.file);
  ASSERT_GT(data.size(), 24u);
  EXPECT_EQ(data.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // IHDR: width and height, big-endian, at bytes 16 and 20.
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(data[at + i]);
    return v;
  };
  EXPECT_EQ(be32(16), 640u);
  EXPECT_EQ(be32(20), 480u);
  EXPECT_FALSE(fs::exists(temporary_for(def.file)));
}

TEST_F(PlotTest, WindowDrawsThatPartFittedToThePicture) {
  Model model = jointed_box();
  PlotDef def;
  def.show = {"regions"};  // the opening, 2 m x 2 m in a 10 m box, filled
  def.file = file("whole.png");
  plot(model, def);
  def.file = file("window.png");
  def.window = std::array<double, 4>{3.5, 6.5, 3.5, 6.5};
  plot(model, def);
  const test::Picture whole = test::read_png(file("whole.png")), window = test::read_png(file("window.png"));
  ASSERT_EQ(window.width, 1200);
  // The region covers 4 % of the model's square and 44 % of the window's.
  EXPECT_GT(window.inked(), 5.0 * whole.inked()) << whole.inked() << " " << window.inked();
}

TEST_F(PlotTest, BadWindowThrowsNamingItAndLeavesNoFile) {
  Model model = jointed_box();
  for (const auto& window : {std::array<double, 4>{5, 5, 0, 1}, std::array<double, 4>{0, 1, 2, -2},
                             std::array<double, 4>{0, std::nan(""), 0, 1}}) {
    PlotDef def = all_layers(file("bad.png"));
    def.window = window;
    EXPECT_NE(message_of(model, def).find("window must be {x0, x1, y0, y1} with x0 < x1 and y0 < y1, got {"),
              std::string::npos)
        << message_of(model, def);
  }
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(PlotTest, AWindowBelowTheToleranceIsRefusedAtOnce) {
  Model model = jointed_box();
  PlotDef def = all_layers(file("tiny.pdf"));
  def.axes = true;
  def.window = std::array<double, 4>{5, 5 + 1e-15, 5, 5 + 1e-15};
  EXPECT_NE(message_of(model, def).find("smaller than the model's geometric tolerance"), std::string::npos)
      << message_of(model, def);
  EXPECT_TRUE(dir_is_empty());
}

// A window a thousandth of the model wide: what is far outside it is not drawn at all (Cairo would
// wrap its coordinates round into the picture), and the file holds only what the window shows.
TEST_F(PlotTest, ANarrowWindowDrawsOnlyWhatIsNearIt) {
  Model model = jointed_box();
  PlotDef def = all_layers(file("whole.svg"));
  def.axes = true;
  plot(model, def);
  def.file = file("narrow.svg");
  def.window = std::array<double, 4>{5.2, 5.21, 5.2, 5.21};
  plot(model, def);
  // Line segments drawn, after the font's glyphs (which both files define alike).
  const auto segments = [](const std::string& svg) {
    std::size_t count = 0;
    for (std::size_t at = svg.find("</defs>"); (at = svg.find(" L ", at)) != std::string::npos; at += 3) ++count;
    return count;
  };
  const std::size_t whole = segments(read_all(file("whole.svg"))), narrow = segments(read_all(file("narrow.svg")));
  EXPECT_LT(narrow, whole / 20) << whole << " " << narrow;
}

TEST_F(PlotTest, WritesSvg) {
  Model model = jointed_box();
  const PlotDef def = all_layers(file("box.svg"));
  plot(model, def);
  const std::string data = read_all(def.file);
  ASSERT_FALSE(data.empty());
  EXPECT_TRUE(data.rfind("<?xml", 0) == 0 || data.rfind("<svg", 0) == 0) << data.substr(0, 40);
  EXPECT_NE(data.find("</svg>"), std::string::npos);
}

TEST_F(PlotTest, WritesPdf) {
  Model model = jointed_box();
  const PlotDef def = all_layers(file("box.pdf"));
  plot(model, def);
  const std::string data = read_all(def.file);
  ASSERT_FALSE(data.empty());
  EXPECT_EQ(data.substr(0, 4), "%PDF");
  EXPECT_NE(data.find("%%EOF"), std::string::npos);
}

TEST_F(PlotTest, ExtensionIsCaseInsensitive) {
  Model model = jointed_box(false);
  PlotDef def;
  def.file = file("BOX.PNG");
  plot(model, def);
  EXPECT_EQ(read_all(def.file).substr(1, 3), "PNG");
}

// Every layer but "prepass", which needs a prepass{} result first and says so (tests/interp/
// test_prepass.cpp draws one).
TEST_F(PlotTest, EveryLayerAloneAndAllTogether) {
  Model model = jointed_box();
  std::vector<std::string> all;
  for (const std::string& layer : plot_layers()) {
    PlotDef def;
    def.file = file(layer + ".png");
    def.show = {layer};
    if (layer == "prepass") {
      EXPECT_THROW(plot(model, def), Error);
      EXPECT_FALSE(fs::exists(def.file));
      continue;
    }
    EXPECT_NO_THROW(plot(model, def)) << layer;
    EXPECT_TRUE(fs::exists(def.file)) << layer;
    all.push_back(layer);
  }
  PlotDef def;
  def.file = file("all.svg");
  def.show = all;
  EXPECT_NO_THROW(plot(model, def));
}

// cairo's SVG names dash patterns, so the outline style can be checked without rasterizing.
TEST_F(PlotTest, GluedRegionOutlinesAreDashed) {
  PlotDef def;
  def.file = file("joints.svg");
  def.show = {"joints"};
  Model glued = jointed_box(false, true);
  plot(glued, def);
  EXPECT_NE(read_all(def.file).find("stroke-dasharray"), std::string::npos);
  Model open = jointed_box(false, false);
  plot(open, def);
  EXPECT_EQ(read_all(def.file).find("stroke-dasharray"), std::string::npos);
}

TEST_F(PlotTest, OverwritesAnExistingFile) {
  Model model = jointed_box(false);
  const std::string path = file("box.png");
  std::ofstream(path) << "old";
  PlotDef def;
  def.file = path;
  plot(model, def);
  EXPECT_EQ(read_all(path).substr(1, 3), "PNG");
}

TEST_F(PlotTest, UnzonedModelPlotsWithZonesLayer) {
  Model model = jointed_box(false);
  const PlotDef def = all_layers(file("unzoned.png"));
  EXPECT_NO_THROW(plot(model, def));
  EXPECT_TRUE(fs::exists(def.file));
}

TEST_F(PlotTest, UnknownLayerThrowsWithHintAndLeavesNoFile) {
  Model model = jointed_box(false);
  PlotDef def;
  def.file = file("box.png");
  def.show = {"blocks", "jionts"};
  const std::string message = message_of(model, def);
  EXPECT_NE(message.find("unknown layer 'jionts'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'joints'"), std::string::npos) << message;
  EXPECT_NE(message.find("regions, plastic, prepass, zones, blocks, joints"), std::string::npos) << message;
  EXPECT_THROW(plot(model, def), Error);
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(PlotTest, EmptyLayerListThrows) {
  Model model = jointed_box(false);
  PlotDef def;
  def.file = file("box.png");
  def.show = {};
  EXPECT_THROW(plot(model, def), Error);
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(PlotTest, BadExtensionThrowsAndLeavesNoFile) {
  Model model = jointed_box(false);
  PlotDef def;
  def.file = file("box.xyz");
  EXPECT_EQ(message_of(model, def), "unsupported file type '.xyz': use .png, .svg or .pdf");
  def.file = file("box");
  EXPECT_NE(message_of(model, def).find("no extension"), std::string::npos);
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(PlotTest, UnwritablePathThrowsNamingTheFile) {
  Model model = jointed_box(false);
  for (const char* ext : {".png", ".svg", ".pdf"}) {
    PlotDef def;
    def.file = file(std::string("missing/box") + ext);
    const std::string message = message_of(model, def);
    EXPECT_NE(message.find("cannot write '" + def.file + "'"), std::string::npos) << message;
  }
  PlotDef def;
  def.file = file("adir.png");
  fs::create_directory(def.file);
  EXPECT_NE(message_of(model, def).find("cannot write"), std::string::npos);
}

TEST_F(PlotTest, FailedPlotKeepsThePreviousFile) {
  Model model = jointed_box(false);
  const std::string path = file("box.png");
  std::ofstream(path) << "previous picture";
  PlotDef def;
  def.file = path;
  def.show = {"blokcs"};
  EXPECT_THROW(plot(model, def), Error);
  EXPECT_EQ(read_all(path), "previous picture");
  EXPECT_FALSE(fs::exists(temporary_for(path)));
}

TEST_F(PlotTest, SizeOutOfRangeThrows) {
  Model model = jointed_box(false);
  PlotDef def;
  def.file = file("box.png");
  def.width = 0;
  EXPECT_THROW(plot(model, def), Error);
  def.width = 800;
  def.height = 1000000;
  EXPECT_THROW(plot(model, def), Error);
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(PlotTest, SmallestAndOddSizesWork) {
  Model model = jointed_box();
  for (const auto& [w, h] :
       {std::pair{kPlotMinSize, kPlotMinSize}, std::pair{2000, 100}, std::pair{100, 1500}}) {
    PlotDef def = all_layers(file("small.png"));
    def.width = w;
    def.height = h;
    EXPECT_NO_THROW(plot(model, def)) << w << "x" << h;
  }
}

// Names may be any bytes; cairo refuses invalid UTF-8, which must not stop the picture.
TEST_F(PlotTest, TitleAndNamesInAnyBytes) {
  for (const std::string& title : {std::string("Kaverne \xe2\x80\x93 Stufe 1, \xc3\xa4"),
                                   std::string("bad \xff\xfe\xc0\x80 \xed\xa0\x80 title\n\t")}) {
    Model model(ModelDef{title});
    model.add_block(BlockDef{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
    model.add_region(RegionDef{title, {{4, 4}, {6, 4}, {6, 6}, {4, 6}}, true});
    PlotDef def = all_layers(file("names.pdf"));
    EXPECT_NO_THROW(plot(model, def)) << title;
    def.file = file("names.png");
    EXPECT_NO_THROW(plot(model, def)) << title;
  }
}

TEST_F(PlotTest, ModelWithoutBlocksThrows) {
  Model model;
  PlotDef def;
  def.file = file("empty.png");
  def.show = {"zones"};
  const std::string message = message_of(model, def);
  EXPECT_NE(message.find("no blocks"), std::string::npos) << message;
  EXPECT_TRUE(dir_is_empty());
}

// A model of ~14k zones plots completely. Its speed is measured in benchmarks, not here.
TEST_F(PlotTest, ManyZonesPlot) {
  Model model(ModelDef{"many zones"});
  model.add_block(BlockDef{{{0, 0}, {100, 0}, {100, 60}, {0, 60}}});
  JointSetDef set;
  set.angle = 60;
  set.spacing = {8};
  model.add_joint_set(set);
  ZoneDef zone;
  zone.edge = 1.0;
  model.zone(zone);
  ASSERT_GT(model.mesh().zone_count(), 10000);
  const PlotDef def = all_layers(file("many.png"));
  plot(model, def);
  EXPECT_TRUE(fs::exists(def.file));
  EXPECT_GT(fs::file_size(def.file), 10000u);
}

}  // namespace
}  // namespace edem
