// A file being written under a temporary name, removed unless moved into place (renamed over its
// target).
#pragma once

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>

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

// Removes the temporaries of `target` that a killed writer left: FILE.PID.tmp whose process is
// gone from this machine and which nothing has written to for a minute (a writer on another
// machine of a shared folder keeps its file fresh while it writes).
inline void remove_stale_temporaries(const std::filesystem::path& target) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const std::string prefix = target.filename().string() + ".";
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!name.starts_with(prefix) || !name.ends_with(".tmp")) continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code age;
    const auto written = fs::last_write_time(it->path(), age);
    if (age || fs::file_time_type::clock::now() - written < std::chrono::minutes(1)) continue;
    fs::remove(it->path(), age);
  }
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
