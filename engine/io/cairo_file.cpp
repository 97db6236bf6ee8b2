#include "io/cairo_file.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <cctype>
#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "io/temp_file.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

// Length of the valid UTF-8 sequence at the start of `text` (no overlong forms, surrogates or
// code points above U+10FFFF), or 0.
std::size_t utf8_length(std::string_view text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned c = byte(0);
  const std::size_t n = c < 0x80                ? 1
                        : c >= 0xc2 && c < 0xe0 ? 2
                        : c >= 0xe0 && c < 0xf0 ? 3
                        : c >= 0xf0 && c < 0xf5 ? 4
                                                : 0;
  if (n == 0 || n > text.size()) return 0;
  unsigned code = n == 1 ? c : c & (0x7fu >> n);
  for (std::size_t i = 1; i < n; ++i) {
    if ((byte(i) & 0xc0) != 0x80) return 0;
    code = code << 6 | (byte(i) & 0x3fu);
  }
  const bool overlong = (n == 3 && code < 0x800) || (n == 4 && code < 0x10000);
  const bool invalid = (code >= 0xd800 && code < 0xe000) || code > 0x10ffff;
  return overlong || invalid ? 0 : n;
}

void check_cairo(cairo_status_t status, const std::string& file) {
  if (status != CAIRO_STATUS_SUCCESS) fail("cannot write '{}': {}", file, cairo_status_to_string(status));
}

SurfacePtr make_surface(PictureFormat format, const fs::path& tmp, int width, int height) {
  const double w = width, h = height;
  switch (format) {
    case PictureFormat::svg: return SurfacePtr(cairo_svg_surface_create(tmp.c_str(), w, h));
    case PictureFormat::pdf: return SurfacePtr(cairo_pdf_surface_create(tmp.c_str(), w, h));
    case PictureFormat::png: break;
  }
  return SurfacePtr(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
}

}  // namespace

PictureFormat picture_format(const std::string& file) {
  const std::string ext = fs::path(file).extension().string();
  std::string lower = ext;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == ".png") return PictureFormat::png;
  if (lower == ".svg") return PictureFormat::svg;
  if (lower == ".pdf") return PictureFormat::pdf;
  if (ext.empty()) fail("file '{}' has no extension: use .png, .svg or .pdf", file);
  fail("unsupported file type '{}': use .png, .svg or .pdf", ext);
}

void check_size(int width, int height) {
  for (const int size : {width, height})
    if (size < kPlotMinSize || size > kPlotMaxSize)
      fail("size {{{}, {}}} is out of range: width and height must be {} to {}", width, height, kPlotMinSize,
           kPlotMaxSize);
}

void check_writable(const std::string& file) {
  const fs::path parent = fs::path(file).parent_path();
  std::error_code ec;
  if (!parent.empty() && !fs::is_directory(parent, ec))
    fail("cannot write '{}': directory '{}' does not exist", file, parent.string());
  if (fs::is_directory(file, ec)) fail("cannot write '{}': it is a directory", file);
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  while (!text.empty()) {
    const std::size_t n = utf8_length(text);
    if (n == 0)
      out += '?';
    else if (n == 1 && (static_cast<unsigned char>(text[0]) < 0x20 || text[0] == 0x7f))
      out += ' ';
    else
      out.append(text.substr(0, n));
    text.remove_prefix(std::max<std::size_t>(n, 1));
  }
  return out;
}

void write_picture(const std::string& file, int width, int height, std::string_view title,
                   const std::function<void(cairo_t*)>& draw) {
  const PictureFormat format = picture_format(file);
  TempFile tmp(file);
  SurfacePtr surface = make_surface(format, tmp.path(), width, height);
  check_cairo(cairo_surface_status(surface.get()), file);
  if (format == PictureFormat::pdf) {
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, printable(title).c_str());
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "EDEM");
  }
  {
    ContextPtr cr(cairo_create(surface.get()));
    draw(cr.get());
    const cairo_status_t status = cairo_status(cr.get());
    if (status != CAIRO_STATUS_SUCCESS) fail("cannot draw '{}': {}", file, cairo_status_to_string(status));
  }
  if (format == PictureFormat::png) {
    check_cairo(cairo_surface_write_to_png(surface.get(), tmp.path().c_str()), file);
  } else {
    cairo_surface_finish(surface.get());
    check_cairo(cairo_surface_status(surface.get()), file);
  }
  surface.reset();

  tmp.move_into_place();
}

}  // namespace edem
