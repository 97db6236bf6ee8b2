// io/temp_file.hpp: a file is written beside its target under a name of this process's own, and
// removed unless moved into place.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/temp_file.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

TEST(TempFile, TheTemporaryIsBesideItsTargetNamedForThisProcess) {
  const fs::path temporary = temporary_for("out/case3.png");
  EXPECT_EQ(temporary.parent_path(), fs::path("out"));
  EXPECT_EQ(temporary.filename().string(), "case3.png." + std::to_string(::getpid()) + ".tmp");
}

// Two runs writing one file (two case.lua runs with the same tag in one directory) once shared
// FILE.tmp, and one renamed the other's away from under it.
TEST(TempFile, TwoProcessesWritingOneFileHaveTemporariesOfTheirOwn) {
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string name = temporary_for("picture.png").string();
    const bool written =
        ::write(pipe_ends[1], name.data(), name.size()) == static_cast<ssize_t>(name.size());
    ::_exit(written ? 0 : 1);
  }
  ::close(pipe_ends[1]);
  std::string theirs;
  char buffer[256];
  for (ssize_t n; (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
    theirs.append(buffer, static_cast<size_t>(n));
  ::close(pipe_ends[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(theirs, temporary_for("picture.png", child).string());
  EXPECT_NE(theirs, temporary_for("picture.png").string());
}

TEST(TempFile, ItIsRemovedUnlessMovedIntoPlace) {
  const fs::path dir = fs::temp_directory_path() / ("edem_temp_file_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::path dropped, kept;
  {
    TempFile file(dir / "a.txt");
    std::ofstream(file.path()) << "half";
    dropped = file.path();
  }
  EXPECT_FALSE(fs::exists(dropped));
  {
    TempFile file(dir / "b.txt");
    std::ofstream(file.path()) << "whole";
    file.move_into_place();
    kept = dir / "b.txt";
  }
  EXPECT_TRUE(fs::exists(kept));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace edem
