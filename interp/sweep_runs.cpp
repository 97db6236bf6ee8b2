#include "sweep_runs.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "csv.hpp"

extern char** environ;

namespace edem {
namespace {

namespace fs = std::filesystem;

// The file that marks a folder as a run's, from the moment it starts (run.csv comes at its end).
constexpr const char* kRunMark = ".edem_sweep_run";

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Writes `text` to `file` through a temporary file, so that a reader never sees half of it.
void write_whole(const fs::path& file, const std::string& text) {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const fs::path temporary = fmt::format("{}.{}.{}.tmp", file.string(), host, ::getpid());
  {
    std::ofstream out(temporary);
    out << text;
    if (!out) fail("cannot write {}", temporary.string());
  }
  fs::rename(temporary, file);
}

// The header and first row of a result.csv, as pairs.
Settings read_result(const fs::path& file) {
  std::ifstream in(file);
  std::string header, values;
  if (!std::getline(in, header) || !std::getline(in, values)) return {};
  const auto keys = csv_fields(header);
  const auto texts = csv_fields(values);
  Settings result;
  for (size_t i = 0; i < keys.size() && i < texts.size(); ++i)
    result.emplace_back(keys[i], texts[i]);
  return result;
}

// The last non-empty line of `text`.
std::string last_line(const std::string& text) {
  const size_t end = text.find_last_not_of("\n ");
  if (end == std::string::npos) return {};
  const size_t start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1,
                     end - (start == std::string::npos ? 0 : start + 1) + 1);
}

// run.csv: one "kind,key,value" line each (setting, result; status, seconds, message).
std::string outcome_text(const RunOutcome& o) {
  std::string text;
  for (const auto& [key, value] : o.settings) text += csv_line({"setting", key, value}) + '\n';
  text += csv_line({"status", "", o.status}) + '\n';
  text += csv_line({"seconds", "", fmt::format("{:.1f}", o.seconds)}) + '\n';
  for (const auto& [key, value] : o.results) text += csv_line({"result", key, value}) + '\n';
  text += csv_line({"message", "", o.message}) + '\n';
  return text;
}

Settings run_settings_of(const SweepRow& row, const Settings& common) {
  Settings all = common;
  all.insert(all.end(), row.settings.begin(), row.settings.end());
  return all;
}

// An RAII advisory lock on a file (flock), for the gathering of tasks that end at once.
class FileLock {
 public:
  // Where flock is not supported (some network file systems) the gathering goes on unlocked:
  // each writer's temporary file is its own, and the last rename wins whole.
  explicit FileLock(const fs::path& file)
      : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
      ::close(fd_);
      fd_ = -1;
    }
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

namespace {

// How a run ended: its exit code (128 + N for signal N), or why it could not start.
struct Ended {
  int code = 0;
  std::string not_started;
};

// Starts edem with `words` in `folder` (its output in log.txt, no terminal input: a run in a
// process group of its own would stop reading one) and waits for it, passing a signal in `stop`
// on once when `pass_on` is set.
Ended spawn_and_wait(std::vector<std::string> words, const fs::path& folder, int threads,
                     const std::atomic<int>* stop, bool pass_on) {
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // The run's environment: OpenMP held to its share of the cores and bound to none of them (runs
  // side by side would be bound to the same ones).
  std::vector<std::string> environment;
  for (char** e = environ; *e != nullptr; ++e)
    if (std::strncmp(*e, "OMP_NUM_THREADS=", 16) != 0 &&
        std::strncmp(*e, "OMP_PROC_BIND=", 14) != 0 && std::strncmp(*e, "OMP_PLACES=", 11) != 0)
      environment.emplace_back(*e);
  environment.push_back(fmt::format("OMP_NUM_THREADS={}", threads));
  std::vector<char*> envp;
  for (std::string& e : environment) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, (folder / "log.txt").c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setpgroup(&attributes,
                            0);  // a terminal's Ctrl-C reaches the sweep alone, which passes it on
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0)
    return {
        .code = 0,
        .not_started = fmt::format("cannot start {}: {}", words[0],
                                   std::error_code(spawned, std::generic_category()).message())};
  bool passed_on = false;
  int status = 0;
  for (;;) {
    const pid_t waited = ::waitpid(pid, &status, WNOHANG);
    if (waited == pid) break;
    if (waited < 0)
      return {
          .code = 0,
          .not_started = fmt::format("lost the run (waitpid: {})",
                                     std::error_code(errno, std::generic_category()).message())};
    if (pass_on && stop != nullptr && stop->load() != 0 && !passed_on) {
      ::kill(pid, stop->load());
      passed_on = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return {.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
          .not_started = {}};
}

// The first line of `text`: an error's headline, without its traceback.
std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

void classify(const Ended& ended, const fs::path& folder, RunOutcome& outcome) {
  if (!ended.not_started.empty()) {
    outcome.status = "error";
    outcome.message = ended.not_started;
    return;
  }
  const int code = ended.code;
  const std::string error = first_line(read_text(folder / "error.txt"));
  if (code == 0) {
    outcome.status = "ok";
  } else if (code == 128 + SIGINT || code == 128 + SIGTERM) {
    outcome.status = "interrupted";
    outcome.message = error.empty() ? fmt::format("stopped by signal {}", code - 128) : error;
  } else if (code > 128) {
    const char* name = sigabbrev_np(code - 128);
    outcome.status = "crashed";
    outcome.message = fmt::format("killed by signal {} (SIG{}); its log: {}", code - 128,
                                  name != nullptr ? name : "?", (folder / "log.txt").string());
  } else {
    outcome.status = "error";
    outcome.message = !error.empty() ? error
                                     : fmt::format("exit status {}: {}", code,
                                                   last_line(read_text(folder / "log.txt")));
  }
}

}  // namespace

bool is_run_folder(const std::string& folder) {
  std::error_code ec;
  return !fs::exists(folder, ec) || fs::exists(fs::path(folder) / kRunMark, ec) ||
         fs::exists(fs::path(folder) / "run.csv", ec) || fs::is_empty(folder, ec);
}

RunOutcome run_row(const RunPlan& plan, const SweepRow& row, const std::atomic<int>* stop) {
  const fs::path folder = fs::path(plan.out) / row.name;
  RunOutcome outcome{.status = {},
                     .seconds = 0.0,
                     .message = {},
                     .settings = run_settings_of(row, plan.common),
                     .results = {}};
  const auto started = std::chrono::steady_clock::now();
  try {
    // A run starts afresh, so that nothing of an earlier one is read as its own (only a run's
    // folder is emptied: the sweep checks that before any run).
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / kRunMark) << "a run of edem sweep: its folder is emptied when it runs again\n";
    std::vector<std::string> words = {
        plan.edem,       "--threads",    std::to_string(plan.threads),
        "--progress",    "10",           "--out",
        folder.string(), "--error-file", (folder / "error.txt").string()};
    for (const auto& [key, value] : outcome.settings) {
      words.push_back("--set");
      words.push_back(key + "=" + value);
    }
    words.push_back("run");
    words.push_back(plan.script);
    classify(spawn_and_wait(words, folder, plan.threads, stop, plan.pass_on_signals), folder,
             outcome);
    outcome.results = read_result(folder / "result.csv");
  } catch (
      const std::exception& e) {  // a full disk, a folder that cannot be made: this run's error
    outcome.status = "error";
    outcome.message = e.what();
  }
  outcome.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  try {
    write_whole(folder / "run.csv", outcome_text(outcome));
  } catch (const std::exception& e) {
    outcome.message += fmt::format(" (its outcome could not be kept: {})", e.what());
  }
  return outcome;
}

std::optional<RunOutcome> outcome_of(const std::string& out, const SweepRow& row,
                                     const Settings& common) {
  std::ifstream in(fs::path(out) / row.name / "run.csv");
  if (!in) return std::nullopt;
  RunOutcome o;
  for (std::string line; std::getline(in, line);) {
    const auto f = csv_fields(line);
    if (f.size() != 3) return std::nullopt;
    if (f[0] == "setting")
      o.settings.emplace_back(f[1], f[2]);
    else if (f[0] == "result")
      o.results.emplace_back(f[1], f[2]);
    else if (f[0] == "status")
      o.status = f[2];
    else if (f[0] == "seconds")
      o.seconds = std::strtod(f[2].c_str(), nullptr);
    else if (f[0] == "message")
      o.message = f[2];
  }
  if (o.status.empty() || o.settings != run_settings_of(row, common)) return std::nullopt;
  return o;
}

Gathered gather(const std::string& out, const SweepTable& table, const Settings& common) {
  const FileLock lock(fs::path(out) / "sweep.lock");
  Gathered counts;
  std::vector<std::pair<const SweepRow*, RunOutcome>> ended;
  for (const SweepRow& row : table.rows) {
    auto o = outcome_of(out, row, common);
    if (!o) {
      ++counts.missing;
      continue;
    }
    ++(o->status == "ok" ? counts.ok : counts.failed);
    ended.emplace_back(&row, std::move(*o));
  }
  // The settings' columns: the table's, then those --set gave every run.
  std::vector<std::string> setting_columns = table.columns;
  for (const auto& [key, value] : common) setting_columns.push_back(key);
  std::vector<std::string> result_columns;  // in the order they first appear
  for (const auto& [row, o] : ended)
    for (const auto& [key, value] : o.results)
      if (std::find(setting_columns.begin(), setting_columns.end(), key) == setting_columns.end() &&
          std::find(result_columns.begin(), result_columns.end(), key) == result_columns.end())
        result_columns.push_back(key);
  std::vector<std::string> header = {"name"};
  header.insert(header.end(), setting_columns.begin(), setting_columns.end());
  header.insert(header.end(), {"status", "seconds"});
  header.insert(header.end(), result_columns.begin(), result_columns.end());
  header.push_back("message");
  std::string text = csv_line(header) + '\n';
  for (const auto& [row, o] : ended) {
    const auto value_of = [&](const Settings& pairs, const std::string& key) -> const std::string* {
      const auto it =
          std::find_if(pairs.begin(), pairs.end(), [&](const auto& p) { return p.first == key; });
      return it == pairs.end() ? nullptr : &it->second;
    };
    std::vector<std::string> line = {row->name};
    for (const std::string& column : setting_columns) {
      const std::string* reported = value_of(o.results, column);
      line.push_back(reported != nullptr ? *reported : *value_of(o.settings, column));
    }
    line.push_back(o.status);
    line.push_back(fmt::format("{:.1f}", o.seconds));
    for (const std::string& column : result_columns) {
      const std::string* value = value_of(o.results, column);
      line.push_back(value != nullptr ? *value : "");
    }
    line.push_back(o.message);
    text += csv_line(line) + '\n';
  }
  write_whole(fs::path(out) / "sweep.csv", text);
  return counts;
}

}  // namespace edem
