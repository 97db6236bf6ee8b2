// A file being written under a temporary name, removed unless kept (renamed into place).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace edem {

// Where `target` is written before it is renamed over it: beside it (a rename within one
// directory is atomic), named for this process, so that two runs writing the same file never
// write into, or rename away, each other's half-written temporary. `pid`: the writing process.
inline std::filesystem::path temporary_for(const std::filesystem::path& target,
                                           pid_t pid = ::getpid()) {
  return target.string() + "." + std::to_string(pid) + ".tmp";
}

class TempFile {
 public:
  explicit TempFile(const std::filesystem::path& target) : path_(temporary_for(target)) {}
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
