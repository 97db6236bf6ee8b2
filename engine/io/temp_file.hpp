// A file being written under a temporary name, removed unless moved into place (renamed over its
// target).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "core/error.hpp"

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
  explicit TempFile(const std::filesystem::path& target)
      : target_(target), path_(temporary_for(target)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    std::error_code ec;
    if (!kept_) std::filesystem::remove(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  // Renames the finished temporary over its target and keeps it; throws, removing it, if it cannot.
  void move_into_place() {
    std::error_code ec;
    std::filesystem::rename(path_, target_, ec);
    if (ec) fail("cannot write '{}': {}", target_.string(), ec.message());
    kept_ = true;
  }

 private:
  std::filesystem::path target_;
  std::filesystem::path path_;
  bool kept_ = false;
};

}  // namespace edem
