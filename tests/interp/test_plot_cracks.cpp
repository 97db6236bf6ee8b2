// plot{ show = {"cracks"} }: the new cracks (broken potential-crack sections) drawn by mode,
// tension red and shear blue, checked on the pixels of the PNG.
//
// The PNG is read back with cairo, which the engine library links (include path: its system
// headers' folder, so <cairo/cairo.h>).
#include <cairo/cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "interp_test.hpp"
#include "model/model.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;
using test::expect_runs;

// plot.cpp's pens for new cracks: tension (kCrack) and shear (kShearCrack).
constexpr std::uint32_t kTensionRgb = 0xd62728;
constexpr std::uint32_t kShearRgb = 0x1a35d4;

// The seed's tension bar pulled at its top, with one potential crack (spacing 10) or three
// (spacing 0.25).
std::string bar(const std::string& spacing) {
  return test::seed_bar(spacing) + R"(
boundary{ side = "bottom", fix = "y" }
boundary{ side = "top", yvel = 2e-7 }
)";
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// How many pixels of the PNG have exactly the colour `rgb` (0xRRGGBB).
int pixels_of(const fs::path& png, std::uint32_t rgb) {
  const std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> image(
      cairo_image_surface_create_from_png(png.c_str()), cairo_surface_destroy);
  EXPECT_EQ(cairo_surface_status(image.get()), CAIRO_STATUS_SUCCESS) << png;
  if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS) return -1;
  cairo_surface_flush(image.get());
  const unsigned char* data = cairo_image_surface_get_data(image.get());
  const int width = cairo_image_surface_get_width(image.get());
  const int height = cairo_image_surface_get_height(image.get());
  const int stride = cairo_image_surface_get_stride(image.get());
  int count = 0;
  for (int y = 0; y < height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
    for (int x = 0; x < width; ++x) count += (row[x] & 0xffffffu) == rgb;
  }
  return count;
}

// A legend swatch is 26 x 3 px; a crack across the bar, drawn about 170 px long, has more.
constexpr int kMoreThanASwatch = 150;

class PlotCracks : public testing::Test {
 protected:
  void SetUp() override {
    interpreter_.context().quiet = true;
    dir_ = fs::temp_directory_path() /
           ("edem_plot_cracks_" + std::to_string(::getpid()) + "_" +
            std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Plots the model to NAME.png with the layers `show` (a Lua list) and returns the path.
  fs::path plot(const std::string& name, const std::string& show) {
    const fs::path file = dir_ / (name + ".png");
    expect_runs(interpreter_, "plot{ file = '" + file.string() + "', show = " + show + " }");
    return file;
  }

  int cracks(CrackMode mode) {
    const Model& model = interpreter_.context().model();
    int n = 0;
    for (int id = 0; id < model.crack_count(); ++id) n += model.crack(id).mode == mode;
    return n;
  }

  Interpreter interpreter_;
  fs::path dir_;
};

// Pulled apart, the bar breaks in tension along its potential crack.
TEST_F(PlotCracks, TensionCracksAreRed) {
  expect_runs(interpreter_, bar("10") + "cycle(3000)");
  ASSERT_GT(cracks(CrackMode::tension), 0);
  EXPECT_EQ(cracks(CrackMode::shear), 0);
  const fs::path with = plot("with", R"({"blocks", "cracks"})");
  const fs::path without = plot("without", R"({"blocks"})");
  EXPECT_NE(read_all(with), read_all(without));
  EXPECT_GT(pixels_of(with, kTensionRgb), kMoreThanASwatch);
  EXPECT_EQ(pixels_of(with, kShearRgb), 0);
  EXPECT_EQ(pixels_of(without, kTensionRgb), 0);
}

// A criterion breaks the lower crack in tension and the left half of the upper one in shear.
TEST_F(PlotCracks, ShearAndTensionAreToldApart) {
  expect_runs(interpreter_, bar("0.25") + R"(
    judge{ every = 10, criterion = function(s)
      if s.y < 0.4 then return "tension" end
      if s.y > 0.6 and s.x < 0 then return "shear" end
    end }
    cycle(10)
  )");
  ASSERT_GT(cracks(CrackMode::tension), 0);
  ASSERT_GT(cracks(CrackMode::shear), 0);
  for (const char* show : {R"({"blocks", "cracks"})", R"({"cracks"})", R"({"joints", "cracks"})"}) {
    const fs::path file = plot("both", show);
    EXPECT_GT(pixels_of(file, kTensionRgb), kMoreThanASwatch) << show;
    EXPECT_GT(pixels_of(file, kShearRgb), kMoreThanASwatch / 2) << show;  // half the bar
  }
  const fs::path joints = plot("joints", R"({"blocks", "joints"})");
  EXPECT_EQ(pixels_of(joints, kTensionRgb), 0);
  EXPECT_EQ(pixels_of(joints, kShearRgb), 0);
}

// No crack yet: the layer adds nothing, not even a legend entry.
TEST_F(PlotCracks, NoCracksDrawNothingExtra) {
  expect_runs(interpreter_, bar("0.25"));
  ASSERT_EQ(interpreter_.context().model().crack_count(), 0);
  const fs::path with = plot("with", R"({"blocks", "cracks"})");
  const fs::path without = plot("without", R"({"blocks"})");
  EXPECT_EQ(read_all(with), read_all(without));
  EXPECT_NO_FATAL_FAILURE(plot("alone", R"({"cracks"})"));
}

}  // namespace
}  // namespace edem
