// A file being written under a temporary name, removed unless kept (renamed into place).
#pragma once

#include <filesystem>
#include <system_error>
#include <utility>

namespace edem {

class TempFile {
 public:
  explicit TempFile(std::filesystem::path path) : path_(std::move(path)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    std::error_code ec;
    if (!kept_) std::filesystem::remove(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  void keep() { kept_ = true; }

 private:
  std::filesystem::path path_;
  bool kept_ = false;
};

}  // namespace edem
