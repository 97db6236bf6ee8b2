// For tests of the pictures EDEM writes (plot, chart): a directory of its own for each test, a
// file's bytes, and a PNG read back with cairo.
#pragma once

#include <cairo/cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace edem::test {

// Each test writes into a fresh directory of its own (ctest runs tests side by side), removed after.
class PictureDir : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("edem_") + info->test_suite_name() + "_" + info->name() + "_" +
            std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  bool dir_is_empty() const { return std::filesystem::is_empty(dir_); }

  std::filesystem::path dir_;
};

inline std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Its size and every pixel's colour (0xRRGGBB); empty when the file is not a readable PNG.
struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels;
  bool has(std::uint32_t colour) const {
    return std::find(pixels.begin(), pixels.end(), colour) != pixels.end();
  }
  // The fraction of its pixels that are not white.
  double inked() const {
    if (pixels.empty()) return 0.0;
    const auto white = std::count(pixels.begin(), pixels.end(), 0xffffffu);
    return 1.0 - static_cast<double>(white) / static_cast<double>(pixels.size());
  }
};

inline Picture read_png(const std::string& file) {
  struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  };
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(cairo_image_surface_create_from_png(file.c_str()));
  Picture picture;
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return picture;
  cairo_surface_flush(surface.get());
  picture.width = cairo_image_surface_get_width(surface.get());
  picture.height = cairo_image_surface_get_height(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  for (int y = 0; y < picture.height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
    for (int x = 0; x < picture.width; ++x) picture.pixels.push_back(row[x] & 0xffffffu);
  }
  return picture;
}

}  // namespace edem::test
