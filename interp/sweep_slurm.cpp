#include "sweep_slurm.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.hpp"

extern char** environ;

namespace edem {
namespace {

namespace fs = std::filesystem;

std::string shell_quoted(const std::string& word) {
  if (!word.empty() &&
      word.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=./:,@") ==
          std::string::npos)
    return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// "0-3,7": the array indices of the tasks whose chunks hold `rows`.
std::string array_indices(const SweepTable& table, const std::vector<const SweepRow*>& rows,
                          int chunk) {
  std::vector<long> tasks;
  for (const SweepRow* row : rows) tasks.push_back((row - table.rows.data()) / chunk);
  tasks.erase(std::unique(tasks.begin(), tasks.end()), tasks.end());
  std::string text;
  for (size_t i = 0; i < tasks.size();) {
    size_t j = i;
    while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
    if (!text.empty()) text += ',';
    text += j == i ? fmt::format("{}", tasks[i]) : fmt::format("{}-{}", tasks[i], tasks[j]);
    i = j + 1;
  }
  return text;
}

// Runs `words` and returns what it printed on stdout, with its exit status.
std::pair<int, std::string> capture(const std::vector<std::string>& words) {
  int pipe_ends[2];
  if (::pipe(pipe_ends) != 0) fail("cannot make a pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], 1);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  std::vector<std::string> copy = words;
  std::vector<char*> argv;
  for (std::string& w : copy) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_ends[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<size_t>(n));
  ::close(pipe_ends[0]);
  if (spawned != 0)
    fail("cannot run {}: {}", words[0],
         std::error_code(spawned, std::generic_category()).message());
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), text};
}

}  // namespace

int submit_to_slurm(const SweepOptions& options, const SweepTable& table,
                    const std::vector<const SweepRow*>& rows, const RunPlan& plan) {
  const fs::path logs = fs::path(plan.out) / "slurm";
  fs::create_directories(logs);
  // The tasks read the table when they start, maybe hours later: a copy of it as submitted, so
  // that an edit of the original meanwhile cannot shift their rows.
  const fs::path table_copy =
      fs::path(plan.out) / ("sweep_table" + fs::path(table.path).extension().string());
  if (!fs::exists(table_copy) || !fs::equivalent(table_copy, table.path))
    fs::copy_file(table.path, table_copy, fs::copy_options::overwrite_existing);
  std::vector<std::string> call = {plan.edem,   "sweep",
                                   "--task",    "${SLURM_ARRAY_TASK_ID}",
                                   "--chunk",   std::to_string(options.chunk),
                                   "--threads", std::to_string(plan.threads),
                                   "--out",     plan.out};
  for (const auto& [key, value] : options.common) {
    call.push_back("--set");
    call.push_back(key + "=" + value);
  }
  if (options.resume) call.push_back("--resume");
  if (!options.only.empty()) {
    call.push_back("--only");
    call.push_back(options.only);
  }
  call.push_back(table_copy.string());
  call.push_back(plan.script);
  std::string line = "exec";
  for (const std::string& word : call)
    line +=
        ' ' + (word == "${SLURM_ARRAY_TASK_ID}" ? "\"$SLURM_ARRAY_TASK_ID\"" : shell_quoted(word));
  std::string text =
      "#!/bin/sh\n# edem sweep's job array: task K runs the table's rows K*chunk ... (its "
      "chunk).\n";
  text += fmt::format("#SBATCH --job-name={}\n",
                      shell_quoted("edem-" + fs::path(table.path).stem().string()));
  text += fmt::format("#SBATCH --array={}\n", array_indices(table, rows, options.chunk));
  text += fmt::format("#SBATCH --cpus-per-task={}\n#SBATCH --ntasks=1\n", plan.threads);
  text += fmt::format("#SBATCH --output={}\n", shell_quoted((logs / "%A_%a.out").string()));
  if (!options.partition.empty())
    text += fmt::format("#SBATCH --partition={}\n", shell_quoted(options.partition));
  if (!options.time.empty()) text += fmt::format("#SBATCH --time={}\n", shell_quoted(options.time));
  text += line + "\n";
  const fs::path job = fs::path(plan.out) / "sweep.sbatch";
  std::ofstream(job) << text;
  if (!options.submit) {
    fmt::print("sweep: {} written ({} run{}); submit it with sbatch\n", job.string(), rows.size(),
               rows.size() == 1 ? "" : "s");
    return 0;
  }
  const auto [status, printed] = capture({"sbatch", "--parsable", job.string()});
  if (status != 0) {
    fmt::print(stderr, "edem: sweep: sbatch {} failed (exit status {}): {}\n", job.string(), status,
               printed);
    return 1;
  }
  const std::string id = printed.substr(0, printed.find_first_of(";\n"));
  fmt::print(
      "sweep: submitted job {} ({} run{}, {} a task); each task gathers {} as it ends; "
      "`edem sweep --collect` says what is done\n",
      id, rows.size(), rows.size() == 1 ? "" : "s", options.chunk,
      (fs::path(plan.out) / "sweep.csv").string());
  std::ofstream(fs::path(plan.out) / "slurm" / "job_id") << id << '\n';
  return 0;
}

}  // namespace edem
