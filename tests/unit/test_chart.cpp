// chart{}: a picture of each file type, read back to check its size and that it shows the
// series, and bad input rejected without leaving a file behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/chart.hpp"
#include "io/temp_file.hpp"
#include "picture_files.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

// Error against run time, log-log, as a speed-against-accuracy study draws it.
ChartDef speed_chart(const std::string& file) {
  ChartDef def;
  def.file = file;
  def.title = "Salencon, psi = 0";
  def.x_label = "run time [s]";
  def.y_label = "relative error of wall displacement";
  def.log_x = def.log_y = true;
  def.series = {{"implicit", {0.5, 2, 9}, {0.02, 0.005, 0.001}},
                {"explicit", {3, 20, 90}, {0.03, 0.01, 0.004}}};
  return def;
}

std::string message_of(const ChartDef& def) {
  try {
    chart(def);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

using test::Picture;
using test::read_all;
using test::read_png;

// Full 5 x 5 squares of `colour`: a marker is a disc 10 px across of its series' colour, which
// holds some; a line 1.8 px wide holds none.
int squares(const Picture& p, std::uint32_t colour) {
  int count = 0;
  for (int y = 0; y + 5 <= p.height; ++y)
    for (int x = 0; x + 5 <= p.width; ++x) {
      bool full = true;
      for (int dy = 0; dy < 5 && full; ++dy)
        for (int dx = 0; dx < 5 && full; ++dx)
          full = p.pixels[static_cast<size_t>((y + dy) * p.width + x + dx)] == colour;
      count += full;
    }
  return count;
}

class ChartTest : public test::PictureDir {};

TEST_F(ChartTest, WritesPngOfTheRequestedSizeShowingEverySeries) {
  ChartDef def = speed_chart(file("speed.png"));
  def.width = 640;
  def.height = 480;
  chart(def);
  EXPECT_FALSE(fs::exists(temporary_for(def.file)));
  const Picture picture = read_png(def.file);
  EXPECT_EQ(picture.width, 640);
  EXPECT_EQ(picture.height, 480);
  const std::set<std::uint32_t> colours(picture.pixels.begin(), picture.pixels.end());
  EXPECT_GT(colours.size(), 20u) << "a blank or nearly blank picture";
  EXPECT_TRUE(picture.has(0xffffff));  // the background
  // The markers' insides are the series' own colours, unblended.
  EXPECT_TRUE(picture.has(0x1f77b4)) << "the first series is not drawn";
  EXPECT_TRUE(picture.has(0xff7f0e)) << "the second series is not drawn";
}

// A history's stages are marked with dashed lines where they were dug (those within the x range);
// a dense series is a line alone, without a marker at every sample.
TEST_F(ChartTest, MarksAreDrawnAndDenseSeriesHaveNoMarkers) {
  ChartDef def;
  def.series = {{"roof", {}, {}}};
  for (int i = 0; i <= 200; ++i) {
    def.series[0].x.push_back(10.0 * i);
    def.series[0].y.push_back(-1e-3 * std::sqrt(i));
  }
  def.file = file("plain.png");
  chart(def);
  def.file = file("marked.png");
  def.marks = {{500.0, "stage 1"}, {1200.0, "stage 2"}, {5000.0, "beyond the axis"}};
  chart(def);
  const Picture plain = read_png(file("plain.png")), marked = read_png(file("marked.png"));
  ASSERT_EQ(plain.pixels.size(), marked.pixels.size());
  EXPECT_GT(marked.inked(), plain.inked() + 0.001) << "the marks are not drawn";
  EXPECT_EQ(squares(plain, 0x1f77b4), 0) << "markers on a 201-point series";
  def.series[0].x.resize(20);
  def.series[0].y.resize(20);
  def.file = file("sparse.png");
  chart(def);
  EXPECT_GT(squares(read_png(def.file), 0x1f77b4), 0) << "no markers on a 20-point series";
}

// Data in every corner of the frame: the legend stands above the frame instead of on a point. A
// chart with the series named shows every marker the unnamed one does, and the legend's own.
TEST_F(ChartTest, ALegendThatEveryCornerWouldHideGoesAboveTheFrame) {
  ChartDef def;
  def.series = {{"", {0, 1, 1, 0}, {0, 0, 1, 1}}};
  def.file = file("unnamed.png");
  chart(def);
  def.series[0].name = "corners";
  def.file = file("named.png");
  chart(def);
  const int unnamed = squares(read_png(file("unnamed.png")), 0x1f77b4),
            named = squares(read_png(file("named.png")), 0x1f77b4);
  ASSERT_GT(unnamed, 0);
  // Four discs, and five with the legend's: a legend on a corner would leave four.
  EXPECT_GT(named, unnamed + unnamed / 8) << "the legend hides a point";
}

TEST_F(ChartTest, WritesSvg) {
  const ChartDef def = speed_chart(file("speed.svg"));
  chart(def);
  const std::string data = read_all(def.file);
  ASSERT_FALSE(data.empty());
  EXPECT_TRUE(data.rfind("<?xml", 0) == 0 || data.rfind("<svg", 0) == 0) << data.substr(0, 40);
  EXPECT_NE(data.find("</svg>"), std::string::npos);
}

TEST_F(ChartTest, WritesPdf) {
  const ChartDef def = speed_chart(file("speed.pdf"));
  chart(def);
  const std::string data = read_all(def.file);
  ASSERT_FALSE(data.empty());
  EXPECT_EQ(data.substr(0, 4), "%PDF");
  EXPECT_NE(data.find("%%EOF"), std::string::npos);
}

TEST_F(ChartTest, ExtensionIsCaseInsensitive) {
  const ChartDef def = speed_chart(file("SPEED.PNG"));
  chart(def);
  EXPECT_EQ(read_png(def.file).width, 1200);
}

TEST_F(ChartTest, OverwritesAnExistingFile) {
  const ChartDef def = speed_chart(file("speed.png"));
  std::ofstream(def.file) << "old";
  chart(def);
  EXPECT_EQ(read_all(def.file).substr(1, 3), "PNG");
}

// Ranges that need care: one point, equal values, zero, negative, tiny and huge spans, many
// decades, less than a decade, linear and logarithmic, with and without names and labels.
TEST_F(ChartTest, AwkwardRangesAllDraw) {
  const std::vector<std::vector<ChartSeries>> cases{
      {{"one point", {3}, {7}}},
      {{"zero", {0}, {0}}},
      {{"flat", {1, 2, 3}, {5, 5, 5}}},
      {{"vertical", {2, 2}, {1, 4}}},
      {{"negative", {-3, -1, 4}, {-1e-6, 2e-6, -3e-7}}},
      {{"large", {1e6, 2e6, 3.5e6}, {1e12, 1.5e12, 1.2e12}}},
      {{"near one", {1, 1 + 1e-12}, {1, 1 + 1e-13}}},
      {{"", {1, 2}, {3, 4}}, {"named", {1, 2}, {4, 3}}},
      {{"a", {1}, {1}},
       {"b", {1}, {1}},
       {"c", {1}, {1}},
       {"d", {1}, {1}},
       {"e", {1}, {1}},
       {"f", {1}, {1}},
       {"g", {1}, {1}},
       {"h", {1}, {1}},
       {"i", {1}, {1}}}};
  int n = 0;
  for (const bool log : {false, true})
    for (const auto& series : cases) {
      ChartDef def;
      def.file = file("awkward" + std::to_string(n++) + ".png");
      def.series = series;
      def.log_x = def.log_y = log;
      bool positive = true;
      for (const ChartSeries& s : series)
        for (const auto* values : {&s.x, &s.y})
          for (const double v : *values) positive = positive && v > 0;
      if (log && !positive) continue;
      EXPECT_NO_THROW(chart(def)) << series[0].name << (log ? " (log)" : "");
      EXPECT_TRUE(fs::exists(def.file)) << series[0].name;
    }
  for (const auto& [lo, hi] : {std::pair{1e-300, 1e300}, std::pair{3.1e-3, 3.4e-3},
                               std::pair{0.8, 12.0}, std::pair{1e-9, 1e-8}}) {
    ChartDef def = speed_chart(file("decades.png"));
    def.series = {{"span", {lo, hi}, {hi, lo}}};
    EXPECT_NO_THROW(chart(def)) << lo << " to " << hi;
  }
}

TEST_F(ChartTest, SmallestAndOddSizesWork) {
  for (const auto& [w, h] :
       {std::pair{kPlotMinSize, kPlotMinSize}, std::pair{2000, 100}, std::pair{100, 1500}}) {
    ChartDef def = speed_chart(file("small.png"));
    def.width = w;
    def.height = h;
    EXPECT_NO_THROW(chart(def)) << w << "x" << h;
    EXPECT_EQ(read_png(def.file).height, h);
  }
}

// Names may be any bytes; cairo refuses invalid UTF-8, which must not stop the picture.
TEST_F(ChartTest, TextInAnyBytes) {
  for (const std::string& text : {std::string("Kaverne \xe2\x80\x93 Stufe 1, \xc3\xa4"),
                                  std::string("bad \xff\xfe\xc0\x80 \xed\xa0\x80 text\n\t")}) {
    ChartDef def = speed_chart(file("names.pdf"));
    def.title = def.x_label = def.y_label = def.series[0].name = text;
    EXPECT_NO_THROW(chart(def)) << text;
    def.file = file("names.png");
    EXPECT_NO_THROW(chart(def)) << text;
  }
}

TEST_F(ChartTest, BadExtensionThrowsAndLeavesNoFile) {
  ChartDef def = speed_chart(file("speed.jpg"));
  EXPECT_EQ(message_of(def), "unsupported file type '.jpg': use .png, .svg or .pdf");
  def.file = file("speed");
  EXPECT_NE(message_of(def).find("no extension"), std::string::npos);
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(ChartTest, BadSeriesThrowNamingTheSeries) {
  ChartDef def = speed_chart(file("speed.png"));
  def.series.clear();
  EXPECT_NE(message_of(def).find("no series to draw"), std::string::npos) << message_of(def);

  def = speed_chart(file("speed.png"));
  def.series[1].x.clear();
  def.series[1].y.clear();
  EXPECT_EQ(message_of(def), "series 'explicit' has no points");

  def = speed_chart(file("speed.png"));
  def.series[1].y.pop_back();
  EXPECT_EQ(message_of(def), "series 'explicit': x has 3 values but y has 2");

  def = speed_chart(file("speed.png"));
  def.series[0].name.clear();
  def.series[0].y[1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of(def), "series 1: y[2] must be finite, got inf");
  def.series[0].y[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message_of(def), "series 1: y[2] must be finite, got nan");

  def = speed_chart(file("speed.png"));
  def.series[1].x[2] = -4;
  EXPECT_EQ(message_of(def),
            "series 'explicit': x[3] = -4 cannot be drawn on the logarithmic x axis: values must "
            "be > 0");
  def.series[1].x[2] = 0;
  EXPECT_NE(message_of(def).find("x[3] = 0 cannot be drawn"), std::string::npos);
  def.log_x = false;  // fine on a linear axis
  EXPECT_NO_THROW(chart(def));
  EXPECT_TRUE(fs::remove(def.file));
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(ChartTest, SizeOutOfRangeThrows) {
  ChartDef def = speed_chart(file("speed.png"));
  def.width = 10;
  EXPECT_NE(message_of(def).find("size {10, 900} is out of range"), std::string::npos);
  def.width = 800;
  def.height = kPlotMaxSize + 1;
  EXPECT_THROW(chart(def), Error);
  EXPECT_TRUE(dir_is_empty());
}

TEST_F(ChartTest, UnwritablePathThrowsNamingTheFile) {
  for (const char* ext : {".png", ".svg", ".pdf"}) {
    const ChartDef def = speed_chart(file(std::string("missing/speed") + ext));
    const std::string message = message_of(def);
    EXPECT_NE(message.find("cannot write '" + def.file + "'"), std::string::npos) << message;
  }
  const ChartDef def = speed_chart(file("adir.png"));
  fs::create_directory(def.file);
  EXPECT_NE(message_of(def).find("cannot write"), std::string::npos);
}

TEST_F(ChartTest, FailedChartKeepsThePreviousFile) {
  ChartDef def = speed_chart(file("speed.png"));
  std::ofstream(def.file) << "previous picture";
  def.series[0].y[0] = -1;
  EXPECT_THROW(chart(def), Error);
  EXPECT_EQ(read_all(def.file), "previous picture");
  EXPECT_FALSE(fs::exists(temporary_for(def.file)));
}

}  // namespace
}  // namespace edem
