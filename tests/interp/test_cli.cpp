// The edem executable: exit status, --version, --help, running scripts, reporting errors.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "cli_test.hpp"
#include "interp_test.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;
using test::Cli;
using test::contains;
using test::Outcome;
using test::slurp;
using test::starts_with;

TEST_F(Cli, Version) {
  const Outcome r = edem("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "edem " EDEM_VERSION "\n");
}

TEST_F(Cli, Help) {
  const Outcome r = edem("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(contains(r.out, "run"));
  EXPECT_TRUE(contains(r.out, "reference"));
}

TEST_F(Cli, NoScriptIsAUsageError) {
  const Outcome r = edem("");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "Usage"));
}

TEST_F(Cli, MissingScript) {
  const Outcome r = edem("run missing.lua");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "edem: cannot open 'missing.lua': No such file or directory\n");
}

TEST_F(Cli, DirectoryIsNotAScript) {
  fs::create_directories(dir_ / "sub");
  const Outcome r = edem("run sub");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "'sub' is a directory"));
}

TEST_F(Cli, RunsAScriptBothWays) {
  write("ok.lua", "block{ x = {0, 2}, y = {0, 1} }\nprint('blocks', info().blocks)\n");
  for (const char* form : {"run ok.lua", "ok.lua"}) {
    const Outcome r = edem(form);
    EXPECT_EQ(r.status, 0) << form << "\n" << r.err;
    EXPECT_EQ(r.out, "blocks\t1\n") << form;
    EXPECT_EQ(r.err, "") << form;
  }
}

TEST_F(Cli, ScriptArguments) {
  write("args.lua", "print(arg[0], arg[1], arg[2], select('#', ...))\n");
  const Outcome r = edem("run args.lua one two");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "args.lua\tone\ttwo\t2\n");
}

TEST_F(Cli, SetGivesTheScriptTypedNamedArguments) {
  write("set.lua",
        "for _, k in ipairs{'case', 'depth', 'bolts', 'flag', 'empty'} do\n"
        "  io.write(k, '=', tostring(arg[k]), ':', math.type(arg[k]) or type(arg[k]), ' ')\n"
        "end\nprint(arg[1])\n");
  for (const char* form : {"--set case=3 --set depth=158.5 --set bolts=none --set flag=true --set empty= set.lua one",
                           "run set.lua one --set case=3 --set depth=158.5 --set bolts=none --set flag=true --set empty="}) {
    const Outcome r = edem(form);
    EXPECT_EQ(r.status, 0) << form << "\n" << r.err;
    EXPECT_EQ(r.out, "case=3:integer depth=158.5:float bolts=none:string flag=true:boolean empty=:string one\n")
        << form;
  }
}

TEST_F(Cli, SetRefusesWhatIsNotKeyEqualsValue) {
  write("set.lua", "print('ran')\n");
  const std::pair<const char*, const char*> cases[] = {
      {"--set case set.lua", "--set: 'case' has no '=': give KEY=VALUE"},
      {"--set 1x=2 set.lua", "--set: '1x': the key must be a name"},
      {"--set =2 set.lua", "--set: '': the key must be a name"},
      {"--set a-b=2 set.lua", "--set: 'a-b': the key must be a name"},
      {"--set a=1 --set a=2 set.lua", "--set: 'a' is given twice"},
  };
  for (const auto& [args, message] : cases) {
    const Outcome r = edem(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "") << args;  // the script did not run
    EXPECT_TRUE(contains(r.err, message)) << args << "\n" << r.err;
  }
}

TEST_F(Cli, OutTakesTheFilesCommandsWrite) {
  write("out.lua",
        "block{ x = {0, 1}, y = {0, 1} }\nzone{ edge = 0.5 }\n"
        "material{ 'rock', density = 2000, young = 1e9, poisson = 0.25 }\nassign{ material = 'rock' }\n"
        "history{ name = 'one', fn = function() return 1 end }\ncycle(2)\n"
        "plot{ file = 'model.png' }\n"
        "chart{ file = 'chart.svg', series = {{ name = 'a', x = {0, 1}, y = {0, 1} }} }\n"
        "history_write('kept.csv')\n"
        "plot{ file = '" + (dir_ / "absolute.png").string() + "' }\n");
  const Outcome r = edem("--quiet --out results/run1 out.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* file : {"model.png", "chart.svg", "kept.csv"})
    EXPECT_TRUE(fs::exists(dir_ / "results" / "run1" / file)) << file;
  EXPECT_TRUE(fs::exists(dir_ / "absolute.png"));  // an absolute name stays as given
  EXPECT_FALSE(fs::exists(dir_ / "model.png"));
  // The end-of-run histories, when no history_write wrote them, go there too.
  write("end.lua", "block{ x = {0, 1}, y = {0, 1} }\nzone{ edge = 0.5 }\n"
                   "material{ 'rock', density = 2000, young = 1e9, poisson = 0.25 }\nassign{ material = 'rock' }\n"
                   "history{ 'cycle' }\ncycle(2)\n");
  const Outcome end = edem("run --out results end.lua");
  EXPECT_EQ(end.status, 0) << end.err;
  EXPECT_EQ(end.out, "history: 1 history written to results/end_history.csv\n");
  EXPECT_TRUE(fs::exists(dir_ / "results" / "end_history.csv"));
}

TEST_F(Cli, OutThatCannotBeADirectoryIsAUsageError) {
  write("out.lua", "print('ran')\n");
  write("taken", "a file\n");
  const Outcome r = edem("--out taken out.lua");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(contains(r.err, "edem: --out: cannot make the directory 'taken'")) << r.err;
}

// A run of about a third of a second (5,000 zones, 3,000 cycles) with a callback that prints; on
// one thread (two threads beside another test's two spin at their barriers: 30 s instead).
constexpr const char* kLongRun =
    "block{ x = {0, 10}, y = {0, 10} }\nzone{ edge = 0.2 }\n"
    "material{ 'rock', density = 2000, young = 1e9, poisson = 0.25 }\nassign{ material = 'rock' }\n"
    "gravity{ 0, -9.81 }\nboundary{ side = 'bottom', fix = 'y' }\n"
    "every(1500, function(c) print('callback', c) end)\ncycle(3000)\nprint('done')\n";

TEST_F(Cli, ProgressOffATerminalIsPlainLines) {
  write("long.lua", kLongRun);
  const Outcome r = edem("--threads 1 --progress 0.02 long.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, " of 3000), ratio ")) << r.out;
  EXPECT_TRUE(contains(r.out, " left\n")) << r.out;  // each line ends with the time left
  EXPECT_FALSE(contains(r.out, "\r")) << r.out;
  EXPECT_TRUE(contains(r.out, "callback\t1500\n"));
  EXPECT_TRUE(contains(r.out, "\ndone\n"));
  for (const char* quiet : {"--threads 1 --quiet --progress 0.02 long.lua", "--threads 1 --progress 0 long.lua",
                            "--threads 1 long.lua"}) {
    const Outcome q = edem(quiet);  // the default off a terminal is a line every 10 s
    EXPECT_EQ(q.status, 0) << quiet << q.err;
    EXPECT_EQ(q.out, "callback\t1500\ncallback\t3000\ndone\n") << quiet;
  }
}

TEST_F(Cli, ProgressOnATerminalIsOneLineClearedBeforeOtherOutput) {
  write("long.lua", kLongRun);
  // script(1) (util-linux, in every Debian) runs edem on a pseudo-terminal.
  const Outcome r = edem("--version >/dev/null && script -qc \"'" EDEM_EXE "' --threads 1 --progress 0.02 long.lua\" /dev/null");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "\rcycle ")) << r.out;                 // rewritten in place
  EXPECT_TRUE(contains(r.out, "\r\033[Kcallback\t1500")) << r.out;  // cleared first
  // What follows the run starts on a line of its own: after a newline, or after the line's clearing
  // when a report came after the last callback.
  const size_t done = r.out.find("done");
  ASSERT_NE(done, std::string::npos) << r.out;
  const std::string before = r.out.substr(0, done);
  EXPECT_TRUE(before.ends_with("\n") || before.ends_with("\r\033[K")) << r.out;
}

TEST_F(Cli, ScriptErrorExitsOneWithFileAndLine) {
  write("bad.lua", "print('before')\njset{ angle = 30, spacing = -2 }\nprint('after')\n");
  const Outcome r = edem("run bad.lua");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "before\n");
  EXPECT_EQ(r.err, "bad.lua:2: jset: spacing must be > 0, got -2\n");
}

TEST_F(Cli, PathAsGiven) {
  fs::create_directories(dir_ / "deep" / "er");
  write("deep/er/bad.lua", "zone{ edge = 1 }\n");
  const Outcome r = edem("run ./deep/er/bad.lua");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(starts_with(r.err, "./deep/er/bad.lua:1: zone: "));
}

TEST_F(Cli, ModulesNextToTheScript) {
  fs::create_directories(dir_ / "lib");
  write("lib/helper.lua", "return { answer = 42 }\n");
  write("lib/main.lua", "print(require('helper').answer)\n");
  const Outcome r = edem("run lib/main.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "42\n");
}

TEST_F(Cli, StdlibComesFirstOnThePath) {
  write("path.lua", "local stdlib = package.path:find('" EDEM_SOURCE_DIR
                    "/stdlib/?.lua', 1, true)\n"
                    "local here = package.path:find('./?.lua', 1, true)\n"
                    "print(stdlib ~= nil and here ~= nil and stdlib < here)\n");
  const Outcome r = edem("run path.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "true\n");
}

TEST_F(Cli, Reference) {
  for (const char* form : {"reference", "--reference"}) {
    const Outcome r = edem(form);
    EXPECT_EQ(r.status, 0) << form;
    EXPECT_TRUE(starts_with(r.out, "## Language reference")) << form;
    EXPECT_TRUE(contains(r.out, "### `jset`")) << form;
  }
}

TEST_F(Cli, ReferenceUpdatesAReadme) {
  write("README.md", "# Title\n\nText.\n");
  EXPECT_EQ(edem("reference --update README.md").status, 0);
  const std::string once = slurp(dir_ / "README.md");
  EXPECT_TRUE(starts_with(once, "# Title\n\nText.\n"));
  EXPECT_TRUE(contains(once, "<!-- reference:begin -->\n## Language reference"));
  EXPECT_EQ(edem("reference --update README.md").status, 0);
  EXPECT_EQ(slurp(dir_ / "README.md"), once) << "updating twice changes nothing";
}

// A zoned elastic square on a fixed base, under gravity.
constexpr const char* kLoaded =
    "block{ x = {0, 4}, y = {0, 4} }\nzone{ edge = 1 }\n"
    "material{ 'rock', density = 2000, young = 1e9, poisson = 0.2 }\nassign{ material = 'rock' }\n"
    "boundary{ side = 'bottom', fix = 'xy' }\ngravity{ 0, -9.81 }\n";

TEST_F(Cli, ThreadsBeforeOrAfterRun) {
  write("ok.lua", std::string(kLoaded) + "cycle(10)\n");
  for (const char* form :
       {"--threads 2 run ok.lua", "run --threads 2 ok.lua", "--threads=1 ok.lua"}) {
    const Outcome r = edem(form);
    EXPECT_EQ(r.status, 0) << form << "\n" << r.err;
  }
  const Outcome zero = edem("--threads 0 run ok.lua");
  EXPECT_EQ(zero.status, 2);
  EXPECT_TRUE(contains(zero.err, "--threads")) << zero.err;
  EXPECT_EQ(edem("run --threads two ok.lua").status, 2);
}

TEST_F(Cli, QuietSilencesProgress) {
  write("solve.lua", std::string(kLoaded) + "solve()\nprint('done')\n");
  const Outcome loud = edem("run solve.lua");
  EXPECT_EQ(loud.status, 0) << loud.err;
  EXPECT_TRUE(starts_with(loud.out, "solve: ")) << loud.out;
  for (const char* form : {"-q run solve.lua", "run -q solve.lua", "--quiet solve.lua"}) {
    const Outcome quiet = edem(form);
    EXPECT_EQ(quiet.status, 0) << form << "\n" << quiet.err;
    EXPECT_EQ(quiet.out, "done\n") << form;
  }
}

TEST_F(Cli, HistoriesNobodyWroteAreWrittenAtTheEnd) {
  write("sag.lua", std::string(kLoaded) + "history{ 'uy', at = {2, 4} }\ncycle(30)\n");
  const Outcome r = edem("run sag.lua");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "history: 1 history written to sag_history.csv\n");
  EXPECT_TRUE(starts_with(slurp(dir_ / "sag_history.csv"), "cycle,uy@(2 4) [m]\n10,"));
  fs::remove(dir_ / "sag_history.csv");
  EXPECT_EQ(edem("run -q sag.lua").out, "");
  EXPECT_TRUE(fs::exists(dir_ / "sag_history.csv")) << "quiet still writes";
}

TEST_F(Cli, HistoriesAreNotWrittenTwiceNorAfterAnError) {
  write("own.lua",
        std::string(kLoaded) + "history{ 'ratio' }\ncycle(10)\nhistory_write('mine.csv')\n");
  const Outcome own = edem("run own.lua");
  EXPECT_EQ(own.status, 0) << own.err;
  EXPECT_EQ(own.out, "");
  EXPECT_TRUE(fs::exists(dir_ / "mine.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "own_history.csv"));
  write("fails.lua", std::string(kLoaded) + "history{ 'ratio' }\ncycle(10)\nerror('stop')\n");
  EXPECT_EQ(edem("run fails.lua").status, 1);
  EXPECT_FALSE(fs::exists(dir_ / "fails_history.csv"));
}

TEST_F(Cli, ACallbackErrorIsOneLineAndATraceback) {
  write("cb.lua", std::string(kLoaded) +  // 6 lines
                      "every(5, function(c)\n"
                      "  if c == 10 then error('too far') end\n"
                      "end)\n"
                      "cycle(20)\n");
  const Outcome r = edem("run cb.lua");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "cb.lua:8: every: error in the callback (while cycle() at cb.lua:10 was running): "
            "too far\ntraceback:\n  cb.lua:8: in function <cb.lua:7>\n  cb.lua:10: in main "
            "chunk\n");
}

// SIGINT (Ctrl-C) or SIGTERM stops a run at the end of a cycle: the model is saved in
// interrupted.h5, the script ends with the status a shell expects, and a restore goes on from
// there bit for bit as the run would have.
TEST_F(Cli, AnInterruptedRunIsSavedAndGoesOnFromThere) {
  const std::string model = R"(model{ title = "long" }
block{ x = {0, 4}, y = {0, 4} }
zone{ edge = 0.5 }
material{ "rock", density = 2500, young = 1e9, poisson = 0.25 }
assign{ material = "rock" }
gravity{ 0, -9.81 }
boundary{ side = "bottom", fix = "xy" }
)";
  write("long.lua", model + "cycle(2000000000)\n");
  for (const auto& [signal, status] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const std::string command = "cd '" + dir_.string() + "' && { '" EDEM_EXE "' --quiet run long.lua 2>signalled.txt & "
                                "p=$!; sleep 1; kill -" + signal + " $p; wait $p; }";
    const int raw = std::system(command.c_str());
    const std::string err = slurp(dir_ / "signalled.txt");
    EXPECT_EQ(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, status) << err;
    EXPECT_TRUE(contains(err, std::string("long.lua:8: cycle: interrupted by SIG") + signal + " at cycle "));
    EXPECT_TRUE(contains(err, "the model is saved in interrupted.h5 (restore(\"interrupted.h5\") goes on from there)"));
  }
  const std::string message = slurp(dir_ / "signalled.txt");
  const auto at = message.find("at cycle ");
  ASSERT_NE(at, std::string::npos) << message;
  const long cycle = std::stol(message.substr(at + 9));
  ASSERT_GT(cycle, 0);
  const std::string probe = R"(local g = gp_near(2, 4)
print(("%.17g %.17g"):format(g.ux, g.uy))
)";
  write("whole.lua", model + "cycle(" + std::to_string(cycle + 300) + ")\n" + probe);
  write("after.lua", "restore(\"interrupted.h5\")\ncycle(300)\n" + probe);
  const Outcome whole = edem("--quiet run whole.lua"), after = edem("--quiet run after.lua");
  ASSERT_EQ(whole.status, 0) << whole.err;
  ASSERT_EQ(after.status, 0) << after.err;
  EXPECT_EQ(after.out, whole.out);
}

}  // namespace
}  // namespace edem
