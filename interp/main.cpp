// The edem program: runs a script, prints the language reference, or says its version.
//
//   edem [-q] [--threads N] run FILE.lua [ARGS...]     (or: edem FILE.lua [ARGS...];
//                                                     the options may follow `run` too)
//   edem reference [--update README.md]
//   edem --version | --help
//
// Exit status: 0 on success, 1 when the script stops on an error (the message on stderr),
// 2 for a wrong command line.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interpreter.hpp"
#include "reference.hpp"

namespace {

namespace fs = std::filesystem;

struct Options {
  std::string script;
  std::vector<std::string> script_args;
  bool quiet = false;
  int threads = 0;  // 0: OpenMP's default
  bool reference = false;
  std::string update;  // README to rewrite with the reference
};

// An installed edem finds its stdlib next to itself: PREFIX/bin/edem, PREFIX/share/edem/stdlib.
std::vector<std::string> stdlib_near_executable() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path dir = exe.parent_path().parent_path() / "share" / "edem" / "stdlib";
  if (!fs::is_directory(dir, ec)) return {};
  return {dir.string()};
}

int run_script(const Options& options) {
  edem::Interpreter interpreter({.quiet = options.quiet,
                                 .threads = options.threads,
                                 .stdlib_dirs = stdlib_near_executable()});
  const auto error = interpreter.run_file(options.script, options.script_args);
  if (!error) return 0;
  std::fflush(stdout);  // what the script printed comes before the error
  fmt::print(stderr, "{}\n", *error);
  return 1;
}

int print_reference(const Options& options) {
  const std::string reference = edem::reference_markdown();
  if (options.update.empty()) {
    fmt::print("{}", reference);
    return 0;
  }
  std::ifstream in(options.update);
  std::stringstream text;
  if (in) text << in.rdbuf();  // a missing README is created with just the reference
  std::ofstream out(options.update);
  out << edem::with_reference(text.str(), reference);
  if (!out) {
    fmt::print(stderr, "edem: cannot write '{}'\n", options.update);
    return 1;
  }
  fmt::print("edem: updated the language reference in {}\n", options.update);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"EDEM: a scriptable 2D distinct element code for jointed rock.", "edem"};
  app.set_version_flag("--version", "edem " EDEM_VERSION);
  app.fallthrough();
  app.add_flag("-q,--quiet", options.quiet, "print no progress while running");
  app.add_option("--threads", options.threads,
                 "threads for cycling the model (default: OpenMP's, e.g. OMP_NUM_THREADS); at "
                 "most one per 1000 zones, which a smaller model could not keep busy")
      ->check(CLI::Range(1, 4096));
  app.add_flag("--reference", options.reference,
               "print the language reference (markdown) and exit");
  app.add_option("script", options.script, "Lua script to run (same as 'edem run SCRIPT')");
  app.add_option("args", options.script_args, "arguments for the script: arg[1], ...");

  auto* run = app.add_subcommand("run", "run a Lua script");
  run->add_option("script", options.script, "Lua script to run")->required();
  run->add_option("args", options.script_args, "arguments for the script: arg[1], ...");

  auto* reference = app.add_subcommand("reference", "print the language reference (markdown)");
  reference->add_option("--update", options.update,
                        "rewrite the reference section of this file (README.md) instead");
  app.require_subcommand(0, 1);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (options.reference || reference->parsed()) return print_reference(options);
  if (options.script.empty()) {
    fmt::print(stderr, "{}", app.help());
    return 2;
  }
  return run_script(options);
}
