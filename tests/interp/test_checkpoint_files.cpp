// Checkpoint files as the edem program meets them: `edem info`, and restore() refusing each kind of
// damaged file with a clear message and exit status 1; a run killed while saving leaves the
// previous checkpoint readable.
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <fmt/format.h>

#include <chrono>
#include <thread>
#include <vector>

#include "cli_test.hpp"
#include "interp_test.hpp"
#include "io/temp_file.hpp"

extern char** environ;

namespace edem {
namespace {

namespace fs = std::filesystem;
using test::Cli;
using test::contains;
using test::Outcome;
using test::slurp;

// A small model with contacts, saved after a few cycles.
const char* kMake = R"(
  block{ x = {0, 4}, y = {0, 4} }
  jset{ angle = 30, spacing = 1.3 }
  zone{ edge = %EDGE% }
  material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
  assign{ material = "rock" }
  joint_material{ "j", kn = 1e9, ks = 1e9, friction = 30 }
  jassign{ material = "j" }
  gravity{ 0, -9.81 }
  boundary{ side = "bottom", fix = "xy" }
  history{ "ratio" }
  cycle(20)
  save("good.h5")
)";

std::string make_script(const std::string& edge) {
  std::string script = kMake;
  script.replace(script.find("%EDGE%"), 6, edge);
  return script;
}

class CheckpointFiles : public Cli {
 protected:
  std::string bytes(const std::string& name) { return slurp(dir_ / name); }
  void put(const std::string& name, const std::string& data) {
    std::ofstream(dir_ / name, std::ios::binary) << data;
  }
};

TEST_F(CheckpointFiles, InfoSummarisesACheckpoint) {
  write("make.lua", make_script("0.25"));
  ASSERT_EQ(edem("-q make.lua").status, 0);
  const Outcome r = edem("info good.h5");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "good.h5: EDEM checkpoint, written "));
  EXPECT_TRUE(contains(r.out, "by EDEM " EDEM_VERSION));
  EXPECT_TRUE(contains(r.out, "script: make.lua (13 lines)"));
  EXPECT_TRUE(contains(r.out, "cycle 20, stage 0"));
  EXPECT_TRUE(contains(r.out, "histories: ratio (2 samples)"));
  const Outcome with_script = edem("info good.h5 --script");
  EXPECT_TRUE(contains(with_script.out, "---- script ----\n" + make_script("0.25")));
}

// A checkpoint of a model that cannot cycle yet (not zoned, or zones without material) is still
// a good file: info summarises it.
TEST_F(CheckpointFiles, InfoOfAModelNotReadyToCycle) {
  write("plain.lua", "block{ x = {0, 1}, y = {0, 1} }\nsave('blocks.h5')\nzone{ edge = 0.5 }\nsave('zones.h5')\n");
  ASSERT_EQ(edem("-q plain.lua").status, 0);
  for (const char* file : {"blocks.h5", "zones.h5"}) {
    const Outcome r = edem(std::string("info ") + file);
    EXPECT_EQ(r.status, 0) << file << ": " << r.err;
    EXPECT_TRUE(contains(r.out, "contacts: none yet"));
  }
}

// Each damaged file, and what the message must say. `edem info` and a script's restore() both
// exit 1 with it, naming the file; neither crashes.
TEST_F(CheckpointFiles, DamagedFilesAreRefusedClearly) {
  write("make.lua", make_script("0.25"));
  ASSERT_EQ(edem("-q make.lua").status, 0);
  const std::string good = bytes("good.h5");
  const size_t n = good.size();
  ASSERT_GT(n, 20000u);
  struct Case {
    std::string name, data, message;
  };
  const auto truncated = [&](size_t size) { return good.substr(0, size); };
  const auto flipped = [&](size_t at) {
    std::string data = good;
    data[at] = static_cast<char>(data[at] ^ 0x10);
    return data;
  };
  const auto header_edit = [&](const std::string& from, const std::string& to) {
    std::string data = good;
    const size_t at = data.find(from);
    data.replace(at, from.size(), to);
    data.resize(n);
    return data;
  };
  const std::string checksum = "its content does not match the checksum it was written with";
  const std::string header = "its header is unreadable";
  const size_t schema_at = good.find("\nschema ") + 1;  // the line as this EDEM writes it
  const std::string schema = good.substr(schema_at, good.find('\n', schema_at) + 1 - schema_at);
  std::vector<Case> cases = {
      {"empty.h5", "", "is empty, not a checkpoint"},
      {"cut10.h5", truncated(10), "is not an EDEM checkpoint"},
      {"cut300.h5", truncated(300), "is truncated: 300 bytes, less than its 512-byte header"},
      {"cut512.h5", truncated(512), "is truncated: 512 of its"},
      {"cut2000.h5", truncated(2000), "is truncated: 2000 of its"},
      {"cut_half.h5", truncated(n / 2), "is truncated: " + std::to_string(n / 2) + " of its"},
      {"cut_last.h5", truncated(n - 1), "is truncated: " + std::to_string(n - 1) + " of its"},
      {"flip_magic.h5", flipped(2), "is not an EDEM checkpoint"},
      {"flip_version.h5", flipped(good.find("version") + 9), checksum},
      {"flip_padding.h5", flipped(400), header},
      {"flip_513.h5", flipped(513), checksum},
      {"flip_4000.h5", flipped(4000), checksum},
      {"flip_third.h5", flipped(n / 3), checksum},
      {"flip_half.h5", flipped(n / 2), checksum},
      {"flip_last.h5", flipped(n - 1), checksum},
      {"text.h5", "just some text\n", "is not an EDEM checkpoint"},
      {"png.h5", "\x89PNG\r\n\x1a\n" + good.substr(8, 100), "is not an EDEM checkpoint"},
      {"foreign.h5", std::string(512, '\0') + good.substr(512), "is not an EDEM checkpoint"},
      {"hdf5_only.h5", good.substr(512), "is an HDF5 file but not an EDEM checkpoint"},
      {"future.h5", header_edit(schema, "schema 7\n"), "was written by a newer EDEM"},
      {"schema0.h5", header_edit(schema, "schema 0\n"), header},
      {"bytes_lie.h5", header_edit("bytes ", "bytes 9"), "is truncated"},
      {"longer.h5", good + std::string(100, 'x'), "bytes where " + std::to_string(n) + " were written"},
      {"crc_not_hex.h5", header_edit("crc32 ", "crc32 zz"), header},
  };
  for (const Case& c : cases) put(c.name, c.data);
  fs::create_directory(dir_ / "folder.h5");
  cases.push_back({"folder.h5", "", "it is a directory"});
  cases.push_back({"missing.h5", "", "no such file"});
  ASSERT_GE(cases.size(), 20u);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Outcome info = edem("info " + c.name);
    EXPECT_EQ(info.status, 1);
    EXPECT_TRUE(contains(info.err, "edem: "));
    EXPECT_TRUE(contains(info.err, "'" + c.name + "'"));
    EXPECT_TRUE(contains(info.err, c.message));
    write("load.lua", "block{ x = {0, 1}, y = {0, 1} }\nrestore(\"" + c.name + "\")\n");
    const Outcome run = edem("load.lua");
    EXPECT_EQ(run.status, 1);
    EXPECT_TRUE(contains(run.err, "load.lua:2: restore: "));
    EXPECT_TRUE(contains(run.err, c.message));
  }
}

// A file altered after it was written and given a matching checksum (forged, or written by a
// broken EDEM): restoring it may succeed with the altered values or fail with a message, but must
// never crash. One bit flipped at each of 80 places spread over the file, its header's CRC-32
// recomputed.
TEST_F(CheckpointFiles, ForgedChecksumsNeverCrash) {
  write("make.lua", make_script("0.25"));
  ASSERT_EQ(edem("-q make.lua").status, 0);
  const std::string good = bytes("good.h5");
  const std::string body = good.substr(0, good.find("crc32 "));
  int refused = 0;
  for (int i = 0; i < 80; ++i) {
    std::string data = good;
    const size_t at = 512 + (data.size() - 512) * static_cast<size_t>(i) / 80 + static_cast<size_t>(i % 7);
    data[at] = static_cast<char>(data[at] ^ (1 << (i % 8)));
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()));
    crc = crc32(crc, reinterpret_cast<const Bytef*>(data.data() + 512), static_cast<uInt>(data.size() - 512));
    std::string header = body + fmt::format("crc32 {:08x}\n", crc);
    header.resize(512, '\0');
    data.replace(0, 512, header);
    put("forged.h5", data);
    const Outcome r = edem("info forged.h5");
    EXPECT_TRUE(r.status == 0 || r.status == 1) << "byte " << at << ": status " << r.status << "\n" << r.err;
    refused += r.status == 1;
  }
  EXPECT_GT(refused, 0);  // some flips land where they are noticed
}

// A run killed (SIGKILL) while it writes a checkpoint over an older one: the older one is still
// whole. The script saves over and over; each kill lands while its temporary is being written.
TEST_F(CheckpointFiles, KillDuringSaveLeavesThePreviousCheckpoint) {
  write("again.lua", make_script("0.03") + "for i = 1, 100000 do save(\"good.h5\") end\n");
  for (int attempt = 0; attempt < 3; ++attempt) {
    fs::remove(dir_ / "good.h5");
    pid_t pid = 0;
    const std::string script = (dir_ / "again.lua").string();
    const std::string out_dir = dir_.string();
    std::vector<char*> argv = {const_cast<char*>(EDEM_EXE), const_cast<char*>("-q"),
                               const_cast<char*>("--threads"), const_cast<char*>("1"),
                               const_cast<char*>(script.c_str()), nullptr};
    const std::string old_dir = fs::current_path().string();
    fs::current_path(dir_);
    ASSERT_EQ(posix_spawn(&pid, EDEM_EXE, nullptr, nullptr, argv.data(), environ), 0);
    fs::current_path(old_dir);
    // Wait for a first complete checkpoint, then for a later save in progress (the child's
    // temporary).
    const fs::path temporary = temporary_for(dir_ / "good.h5", pid);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    bool caught = false;
    while (std::chrono::steady_clock::now() < deadline && !caught) {
      caught = fs::exists(dir_ / "good.h5") && fs::exists(temporary);
      if (!caught) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(attempt * 3));  // different points of the write
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(caught) << "no save in progress was seen";
    EXPECT_TRUE(WIFSIGNALED(status));
    const Outcome info = edem("info good.h5");
    EXPECT_EQ(info.status, 0) << "attempt " << attempt << ": " << info.err;
    EXPECT_TRUE(contains(info.out, "cycle 20"));
  }
}

// A pipe (or a device) named as a checkpoint is refused at once: reading one would wait forever.
TEST_F(CheckpointFiles, APipeIsRefusedNotWaitedOn) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe.h5").c_str(), 0644), 0);
  write("r.lua", "restore(\"pipe.h5\")\n");
  for (const std::string& args : {std::string("info pipe.h5"), std::string("run r.lua")}) {
    const std::string command = "cd '" + dir_.string() + "' && timeout 20 '" EDEM_EXE "' " + args +
                                " > out.txt 2> err.txt";
    const int raw = std::system(command.c_str());
    EXPECT_EQ(WEXITSTATUS(raw), 1) << args << " (124: it hung)";
    EXPECT_TRUE(contains(slurp(dir_ / "err.txt"),
                         "cannot read checkpoint 'pipe.h5': it is not a regular file"))
        << args << ": " << slurp(dir_ / "err.txt");
  }
}

// The pid of a process that has ended.
pid_t a_dead_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

// A save removes the temporaries that killed writers left beside its file, and only those: a
// live writer's, or one written to in the last minute, stay.
TEST_F(CheckpointFiles, StaleTemporariesOfDeadWritersAreRemoved) {
  const fs::path stale = temporary_for(dir_ / "good.h5", a_dead_pid());
  const fs::path fresh = temporary_for(dir_ / "good.h5", a_dead_pid());
  const fs::path alive = temporary_for(dir_ / "good.h5", ::getpid());
  for (const fs::path& file : {stale, fresh, alive}) std::ofstream(file) << "half a checkpoint";
  const auto old = fs::file_time_type::clock::now() - std::chrono::minutes(5);
  fs::last_write_time(stale, old);
  fs::last_write_time(alive, old);
  write("make.lua", make_script("0.5"));
  const Outcome r = edem("-q run make.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(fresh));
  EXPECT_TRUE(fs::exists(alive));
}

}  // namespace
}  // namespace edem
