// Writing a cairo picture to a file, shared by plot() and chart(): PNG, SVG or PDF chosen by the
// file's extension and of a checked size, drawn to FILE.PID.tmp and renamed over FILE only once
// complete, so a failed picture never leaves a half-written file behind (and keeps the previous
// one).
#pragma once

#include <functional>
#include <string>
#include <string_view>

// cairo's own declaration of its context: callers that only check a file need no cairo headers.
typedef struct _cairo cairo_t;

namespace edem {

// Smallest and largest accepted width or height of a picture [px].
inline constexpr int kPlotMinSize = 64;
inline constexpr int kPlotMaxSize = 16384;

enum class PictureFormat { png, svg, pdf };

// The format of `file` by its extension (any case). Throws edem::Error for another or none.
PictureFormat picture_format(const std::string& file);

// Throws edem::Error when width or height is out of range.
void check_size(int width, int height);

// Throws edem::Error when `file`'s directory does not exist or `file` is a directory.
void check_writable(const std::string& file);

// Text cairo accepts: invalid UTF-8 (names may be any bytes) becomes '?' and control characters
// spaces; cairo would otherwise stop drawing altogether.
std::string printable(std::string_view text);

// A width x height surface of `file`'s format (PDF titled `title`), drawn by `draw`, written to
// FILE.PID.tmp and renamed over `file`. Throws edem::Error, leaving no file, if cairo or the file
// system fails.
void write_picture(const std::string& file, int width, int height, std::string_view title,
                   const std::function<void(cairo_t*)>& draw);

}  // namespace edem
