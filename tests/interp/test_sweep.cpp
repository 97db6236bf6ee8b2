// edem sweep: a run a row of a table, locally, each in its own folder, the result rows gathered;
// bad tables refused before any run; --resume, --only, --collect; the Slurm job script.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test.hpp"
#include "core/names.hpp"
#include "csv.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;
using test::Cli;
using test::Outcome;
using test::slurp;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A block settling on a fixed base under gravity: a few hundred cycles, a result that depends on
// every setting in its last digits.
const char* const kSettling =
    "local s = settings{ height = 1, density = 2500, cycles = 200, fail = false, label = \"a\" }\n"
    "local function check() if s.fail then error(\"asked to fail\") end end\n"
    "local function go() check() end\n"
    "go()\n"
    "block{ x = {0, 2}, y = {-1, 0} }\n"
    "block{ x = {0, 2}, y = {0, s.height} }\n"
    "zone{ edge = 0.5 }\n"
    "material{ \"rock\", density = s.density, young = 1e9, poisson = 0.25 }\n"
    "assign{ material = \"rock\" }\n"
    "joint_material{ \"j\", kn = 1e10, ks = 1e10, friction = 30 }\n"
    "jassign{ material = \"j\" }\n"
    "boundary{ side = \"bottom\", fix = \"xy\" }\n"
    "gravity{ 0, -9.81 }\n"
    "cycle(s.cycles)\n"
    "result{ settlement = gp_near(1, s.height).uy, label = s.label }\n"
    "result{ cycles = s.cycles }\n";

// The rows of a CSV, each its fields, with the column `drop` (seconds: they differ) left out.
std::vector<std::vector<std::string>> rows_of(const std::string& text,
                                              const std::string& drop = "seconds") {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  long dropped = -1;
  for (std::string line; std::getline(in, line);) {
    auto fields = csv_fields(line);
    if (rows.empty()) dropped = std::find(fields.begin(), fields.end(), drop) - fields.begin();
    if (dropped < static_cast<long>(fields.size())) fields.erase(fields.begin() + dropped);
    rows.push_back(fields);
  }
  return rows;
}

class Sweep : public Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    write("settle.lua", kSettling);
  }
  std::string gathered(const std::string& out = "runs") { return slurp(dir_ / out / "sweep.csv"); }
};

TEST_F(Sweep, EveryRowIsGatheredAndAFailedOneIsARowWithItsError) {
  write("table.csv", "name,height,fail\nlow,0.5,false\nhigh,2,false\nbroken,1,true\nmid,1,false\n");
  const Outcome r = edem("sweep --jobs 2 --out runs table.csv settle.lua");
  EXPECT_EQ(r.status, 1) << r.err;  // one run failed
  EXPECT_TRUE(contains(r.out, "3 ok, 1 failed, 0 not run")) << r.out;
  const auto rows = rows_of(gathered());
  ASSERT_EQ(rows.size(), 5u) << gathered();
  // The results' columns as first reported: a call's own alphabetically.
  EXPECT_EQ(rows[0], (std::vector<std::string>{"name", "height", "fail", "status", "label",
                                               "settlement", "cycles", "message"}));
  EXPECT_EQ(rows[1][0], "low");  // the table's order, whichever ended first
  EXPECT_EQ(rows[3][0], "broken");
  EXPECT_EQ(rows[3][3], "error");
  // The error's headline, not its traceback's last line.
  EXPECT_TRUE(rows[3][7].ends_with("settle.lua:2: error: asked to fail")) << rows[3][7];
  for (int i : {1, 2, 4}) {
    EXPECT_EQ(rows[i][3], "ok");
    EXPECT_EQ(rows[i][6], "200");
    EXPECT_LT(std::stod(rows[i][5]), 0.0);  // it settled
  }
  EXPECT_TRUE(fs::exists(dir_ / "runs" / "low" / "log.txt"));
  EXPECT_TRUE(contains(slurp(dir_ / "runs" / "broken" / "log.txt"), "asked to fail"));
}

TEST_F(Sweep, ResultsEqualThoseOfTheSameRunsMadeOneByOne) {
  write("table.csv", "height,density\n0.5,2500\n1,2700\n2,2000\n");
  const Outcome r = edem("sweep --jobs 2 --out runs table.csv settle.lua");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  for (const auto& [name, height, density] :
       std::vector<std::array<std::string, 3>>{{"height-0.5_density-2500", "0.5", "2500"},
                                               {"height-1_density-2700", "1", "2700"},
                                               {"height-2_density-2000", "2", "2000"}}) {
    fs::create_directories(dir_ / name);
    const Outcome alone = edem("--threads 1 --out " + name + " --set height=" + height +
                               " --set density=" + density + " run settle.lua");
    ASSERT_EQ(alone.status, 0) << alone.err;
    EXPECT_EQ(slurp(dir_ / "runs" / name / "result.csv"), slurp(dir_ / name / "result.csv"))
        << name;
  }
}

TEST_F(Sweep, BadTablesStopBeforeAnyRunNamingRowAndColumn) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"name,height\na,1\nb\n",
       "table.csv:3: 1 values for 2 columns (no value for column 'height')"},
      {"name,hieght\na,1\n",
       "table.csv:1: column 'hieght': settle.lua has no setting 'hieght' (did you mean 'height'?)"},
      {"name,height\na,1\na,2\n", "table.csv:3: the name 'a' is row 1's (line 2) too"},
      {"height\n1\n1\n",
       "table.csv:3: the name 'height-1' is row 1's (line 2) too: the two rows are the same run"},
      {"", "table.csv: the table is empty"},
      {"# only a comment\nname,height\n", "table.csv: the table has column names but no runs"},
      {"name,height\na,1\nb,tall\n",
       "table.csv:3: row 'b', column 'height': 'tall' is not a number (height's default is 1)"},
      {"name,fail\na,yes\n", "table.csv:2: row 'a', column 'fail': 'yes' is not true or false"},
      {"name,height\na,\n", "table.csv:2: column 'height' has no value"},
      {"name,height,height\na,1,2\n", "table.csv:1: column 'height' is named twice"},
      {"name,height\na/b,1\n", "table.csv:2: name 'a/b' cannot name a run's folder"},
      {"name,status\na,1\n", "table.csv:1: column 'status' is one the sweep writes itself"},
      {"name,height\nsweep.csv,1\n", "table.csv:2: name 'sweep.csv' cannot name a run's folder"},
      {"name,height\na,inf\n", "table.csv:2: row 'a', column 'height': 'inf' is not a number"},
      {"\xEF\xBB\xBFname,hieght\na,1\n", "table.csv:1: column 'hieght'"},
  };
  for (const auto& [table, message] : cases) {
    write("table.csv", table);
    const Outcome r = edem("sweep --out runs table.csv settle.lua");
    EXPECT_EQ(r.status, 2) << table;
    EXPECT_TRUE(contains(r.err, message)) << table << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "runs")) << table;
  }
  write("table.csv", "height\n1\n");
  const Outcome set = edem("sweep --set height=2 --out runs table.csv settle.lua");
  EXPECT_TRUE(contains(set.err, "column 'height' is set for every run too (--set height=2)"))
      << set.err;
  const Outcome unknown = edem("sweep --set densty=2 --out runs table.csv settle.lua");
  EXPECT_TRUE(contains(
      unknown.err, "--set densty=2: settle.lua has no setting 'densty' (did you mean 'density'?)"))
      << unknown.err;
  const Outcome before = edem("--set height=2 sweep --out runs table.csv settle.lua");
  EXPECT_EQ(before.status, 2);
  EXPECT_TRUE(contains(before.err, "give --set, --out and --threads after 'sweep'")) << before.err;
  write("plain.lua", "block{ x = {0, 1}, y = {0, 1} }\n");
  const Outcome undeclared = edem("sweep --out runs table.csv plain.lua");
  EXPECT_EQ(undeclared.status, 2);
  EXPECT_TRUE(contains(undeclared.err, "plain.lua:1: block comes before any settings{}"))
      << undeclared.err;
  EXPECT_FALSE(fs::exists(dir_ / "runs"));
}

TEST_F(Sweep, YadesBatchTableIsReadToo) {
  write("runs.table",
        "# YADE's batch table: blanks between columns, = for the value above\n"
        "description  height  label\n"
        "first        0.5     x     # a comment\n"
        "second       =       y\n");
  const Outcome r = edem("sweep --jobs 1 runs.table settle.lua");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const auto rows = rows_of(gathered("runs_sweep"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][0], "first");
  EXPECT_EQ(rows[2][0], "second");
  EXPECT_EQ(rows[2][1], "0.5");
  EXPECT_EQ(rows[2][2], "y");  // label: the script's own report fills the table's column
}

TEST_F(Sweep, ResumeAfterAKillRunsOnlyTheRowsWithoutAResult) {
  std::string table = "name,cycles\n";
  for (int k = 1; k <= 6; ++k) table += fmt::format("r{},40000\n", k);
  write("table.csv", table);
  // Killed once the first row is gathered: the run going is stopped, the rest never start.
  write("kill.sh", "'" EDEM_EXE
                   "' sweep --jobs 1 --out runs table.csv settle.lua > first.txt 2>&1 & pid=$!\n"
                   "for i in $(seq 1200); do grep -q ',ok,' runs/sweep.csv 2>/dev/null && break; "
                   "sleep 0.05; done\n"
                   "kill -TERM $pid; wait $pid; echo \"status $?\"\n");
  const int raw = std::system(("cd '" + dir_.string() + "' && bash kill.sh > killed.txt").c_str());
  ASSERT_EQ(raw, 0);
  EXPECT_EQ(slurp(dir_ / "killed.txt"), "status 143\n") << slurp(dir_ / "first.txt");
  const auto before = rows_of(gathered());
  int ok = 0;
  for (size_t i = 1; i < before.size(); ++i) ok += before[i][2] == "ok";
  ASSERT_GE(ok, 1);
  ASSERT_LT(ok, 6) << "the sweep ended before it was killed: make the runs longer";
  const Outcome resumed = edem("sweep --jobs 2 --resume --out runs table.csv settle.lua");
  ASSERT_EQ(resumed.status, 0) << resumed.out << resumed.err;
  EXPECT_TRUE(contains(resumed.out, "sweep: " + std::to_string(6 - ok) + " run")) << resumed.out;
  for (size_t i = 1; i < before.size(); ++i) {
    if (before[i][2] == "ok") {
      EXPECT_FALSE(contains(resumed.out, "sweep: " + before[i][0] + " ")) << resumed.out;
    } else {  // the run going when the sweep was killed: stopped, its model saved, run again
      EXPECT_EQ(before[i][2], "interrupted");
      EXPECT_TRUE(contains(resumed.out, "sweep: " + before[i][0] + " ok")) << resumed.out;
    }
  }
  const auto after = rows_of(gathered());
  ASSERT_EQ(after.size(), 7u);
  for (size_t i = 1; i < after.size(); ++i) EXPECT_EQ(after[i][2], "ok") << after[i][0];
  const Outcome nothing = edem("sweep --resume --out runs table.csv settle.lua");
  EXPECT_EQ(nothing.status, 0);
  EXPECT_TRUE(contains(nothing.out, "every run has its outcome already")) << nothing.out;
}

TEST_F(Sweep, ASettingForEveryRunIsAColumnToo) {
  write("table.csv", "name,height\na,1\n");
  const Outcome r = edem("sweep --set cycles=100 --out runs table.csv settle.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = rows_of(gathered());
  EXPECT_EQ(rows[0][2], "cycles");
  EXPECT_EQ(rows[1][2], "100");
}

TEST_F(Sweep, AFolderThatIsNotARunsIsNeverEmptied) {
  write("table.csv", "name,height\nsrc,1\n");
  fs::create_directories(dir_ / "runs" / "src");
  write("runs/src/keep.txt", "mine");
  const Outcome r = edem("sweep --out runs table.csv settle.lua");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "row 'src' would run in")) << r.err;
  EXPECT_EQ(slurp(dir_ / "runs" / "src" / "keep.txt"), "mine");
}

TEST_F(Sweep, OnlyOneRowAndCollect) {
  write("table.csv", "name,height\na,1\nb,2\n");
  const Outcome one = edem("sweep --only b --out runs table.csv settle.lua");
  EXPECT_EQ(one.status, 0) << one.err;
  EXPECT_FALSE(fs::exists(dir_ / "runs" / "a"));
  const Outcome collected = edem("sweep --collect --out runs table.csv settle.lua");
  EXPECT_EQ(collected.status, 1);  // a is missing
  EXPECT_TRUE(contains(collected.out, "1 ok, 0 failed, 1 without an outcome")) << collected.out;
  EXPECT_TRUE(contains(collected.out, "not run (or still running): a")) << collected.out;
  const Outcome typo = edem("sweep --only c --out runs table.csv settle.lua");
  EXPECT_EQ(typo.status, 2);
  EXPECT_TRUE(contains(typo.err, "--only c: table.csv has no row of that name")) << typo.err;
}

TEST_F(Sweep, NeverAsksForMoreThreadsThanCores) {
  write("table.csv", "height\n1\n2\n");
  const Outcome r = edem("sweep --jobs 4096 --threads 1 --out runs table.csv settle.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "--jobs 4096 of 1 thread would ask for more than the")) << r.out;
}

TEST_F(Sweep, SlurmJobScriptHasATaskPerChunkOfTheRowsLeft) {
  write("table.csv", "name,height\na,1\nb,2\nc,3\nd,4\ne,5\n");
  const Outcome r = edem(
      "sweep --slurm --no-submit --chunk 2 --threads 2 --partition short --time 0:10:00 "
      "--out runs table.csv settle.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string job = slurp(dir_ / "runs" / "sweep.sbatch");
  EXPECT_TRUE(contains(job, "#SBATCH --array=0-2\n")) << job;
  EXPECT_TRUE(contains(job, "#SBATCH --cpus-per-task=2\n"));
  EXPECT_TRUE(contains(job, "#SBATCH --partition=short\n"));
  EXPECT_TRUE(contains(job, "#SBATCH --time=0:10:00\n"));
  EXPECT_TRUE(contains(job, "sweep --task \"$SLURM_ARRAY_TASK_ID\" --chunk 2 --threads 2")) << job;
  // What a task runs: its chunk (task 1: rows c and d).
  const Outcome task = edem("sweep --task 1 --chunk 2 --out runs table.csv settle.lua");
  ASSERT_EQ(task.status, 0) << task.err;
  EXPECT_TRUE(fs::exists(dir_ / "runs" / "c" / "run.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "runs" / "d" / "run.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "runs" / "a"));
  // Resumed: only the tasks of the chunks with rows left.
  const Outcome resumed =
      edem("sweep --slurm --no-submit --resume --chunk 2 --out runs table.csv settle.lua");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_TRUE(contains(slurp(dir_ / "runs" / "sweep.sbatch"), "#SBATCH --array=0,2\n"));
}

TEST_F(Cli, ResultWritesItsRowAndLaterCallsAddOrReplace) {
  write("r.lua", "result{ b = 2, a = 1.5 }\nresult{ c = 'x', a = 7 }\n");
  const Outcome r = edem("--out o run r.lua");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "o" / "result.csv"), "a,b,c\n7,2,x\n");
  write("bad.lua", "result{ a = {} }\n");
  const Outcome bad = edem("run bad.lua");
  EXPECT_EQ(bad.status, 1);
  EXPECT_TRUE(contains(bad.err, "bad.lua:1: result: a must be a number, a string or a boolean"))
      << bad.err;
  write("own.lua", "result{ seconds = 3 }\n");
  const Outcome own = edem("run own.lua");
  EXPECT_TRUE(
      contains(own.err, "own.lua:1: result: 'seconds' is a column edem sweep writes itself"))
      << own.err;
}

TEST(Names, ASwapOfNeighbouringLettersIsOneEdit) {
  EXPECT_EQ(edit_distance("widht", "width"), 1);
  EXPECT_EQ(edit_distance("blok", "block"), 1);
  EXPECT_EQ(edit_distance("abc", "cba"), 2);
  EXPECT_EQ(closest_name("hieght", {"height", "density"}), "height");
}

}  // namespace
}  // namespace edem
