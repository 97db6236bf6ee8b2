// Running the model: set{} (solver settings), reset{}, cycle(), solve{}, and the callbacks
// every() and cancel().
//
// cycle() and solve() mark their call's position in Context::running, so that a callback
// failing while they run names them, and refuse to run inside a callback of another.
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <csignal>
#include <lua.hpp>

#include "callbacks.hpp"
#include "adaptor.hpp"
#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

// Most cycles one call may ask for: 1e12 cycles take eleven days at a million cycles a second, more
// than a small model runs, so a larger count is a slip (a stray digit, 2^53 + 1), not a wish.
constexpr double kMostCycles = 1e12;

const std::vector<std::string>& modes() {
  static const std::vector<std::string> names = {"static", "dynamic"};
  return names;
}

const std::vector<std::string>& dampings() {
  static const std::vector<std::string> names = {"adaptive", "local", "none"};
  return names;
}

const std::vector<std::string>& resettable() {
  static const std::vector<std::string> names = {"displacement", "velocity", "state", "joint"};
  return names;
}

Damping damping_of(const std::string& name) {
  if (name == "local") return Damping::local;
  if (name == "none") return Damping::none;
  return Damping::adaptive;
}

int run_set(lua_State*, Context& context, const Args& args) {
  if (args.values.empty())
    fail("nothing to set: give mode, damping, local_damping, step, fraction, mixed or overlap");
  Model& model = context.model();
  SolverSettings settings = model.solver_settings();
  if (args.has("mode")) {
    const bool dynamic = args.string("mode") == "dynamic";
    settings.mode = dynamic ? SolverMode::dynamic : SolverMode::static_;
    // Each mode has its own natural damping unless this call says otherwise.
    settings.damping = dynamic ? Damping::none : Damping::adaptive;
  }
  if (args.has("damping")) settings.damping = damping_of(args.string("damping"));
  if (args.has("local_damping")) settings.local_damping = args.number("local_damping");
  if (args.has("step")) settings.step = args.number("step");
  if (args.has("fraction")) settings.step_fraction = args.number("fraction");
  if (args.has("mixed")) settings.mixed = args.boolean("mixed");
  if (args.has("overlap")) settings.overlap = args.number("overlap");
  model.set_solver(settings);
  return 0;
}

int run_reset(lua_State*, Context& context, const Args& args) {
  const auto& what = args.get<std::vector<std::string>>("what");
  const auto named = [&](std::string_view name) {
    return std::find(what.begin(), what.end(), name) != what.end();
  };
  context.model().reset({.displacement = named("displacement"),
                         .velocity = named("velocity"),
                         .state = named("state"),
                         .joint = named("joint")});
  return 0;
}

// Marks the running command as cycling the model; refuses to cycle inside a callback.
void start_cycling(lua_State* L, Context& context, std::string_view name) {
  if (const Running* outer = context.cycling())
    fail("cannot cycle inside a callback while {}() at {} is cycling", outer->command,
         outer->cycling_at);
  std::string at = where(L);  // "FILE:LINE: "
  if (at.size() >= 2) at.resize(at.size() - 2);
  context.running->cycling_at = at.empty() ? fmt::format("{}()", name) : at;
  if (!context.model().cycling_started())
    if (const std::string why = context.model().unheld(); !why.empty()) warn(L, name, why);
}

// Clears the progress line when the run ends, however it ends.
struct ProgressLineCloser {
  Context& context;
  ~ProgressLineCloser() { context.close_progress_line(); }
};

// A run that SIGINT or SIGTERM stopped at the end of a cycle: the model is saved as it stands, in
// interrupted.h5 (under --out), and the script ends there.
void end_if_interrupted(Context& context, const SolveResult& result) {
  if (!result.interrupted) return;
  context.close_progress_line();
  const int signal = context.stop->load();
  const std::string name = signal == SIGTERM ? "SIGTERM" : "SIGINT";
  context.interrupted_by = signal;
  const std::string file = context.output_path("interrupted.h5");
  const long cycle = context.model().solver_info().cycle;
  try {
    context.model().save(file, {.script_path = context.script_path, .script = context.script_text});
  } catch (const Error& e) {
    fail("interrupted by {} at cycle {}; the model could not be saved: {}", name, cycle, e.what());
  }
  fail("interrupted by {} at cycle {}: the model is saved in {} (restore(\"{}\") goes on from there)", name,
       cycle, file, file);
}

int run_cycle(lua_State* L, Context& context, const Args& args) {
  start_cycling(L, context, "cycle");
  SolveResult result;
  {
    const ProgressLineCloser closer{context};
    result = context.model().cycle(static_cast<long>(args.integer("n")));
  }
  end_if_interrupted(context, result);
  return 0;
}

int run_solve(lua_State* L, Context& context, const Args& args) {
  start_cycling(L, context, "solve");
  SolveDef def;
  def.ratio = args.number("ratio");
  def.max_cycles = static_cast<long>(args.integer("max_cycles"));
  def.stall = static_cast<long>(args.integer("stall"));
  def.settle = args.number("settle");
  def.balance = args.number("balance");
  const SolveResult result = [&] {
    const ProgressLineCloser closer{context};
    return context.model().solve(def);
  }();
  end_if_interrupted(context, result);
  if (!context.quiet) {
    // With judging on equilibrium states: the judgments and what they broke.
    const auto plural = [](int n) { return n == 1 ? "" : "s"; };
    std::string rounds;
    if (result.judgments > 0)
      rounds = fmt::format("; {} section{} broke in {} judgment{} at equilibrium", result.broke,
                           plural(result.broke), result.judgments, plural(result.judgments));
    // Short of the ratio after breaks: they found no new equilibrium; short of it with sections
    // intact and none broken: the last state was not judged.
    std::string why;
    if (result.stalled)
      why = fmt::format(": the ratio has not fallen a tenth below its lowest in the last {} cycles (stall): the "
                        "rock keeps moving without nearing an equilibrium{}",
                        def.stall, result.unjudged ? "; its state was not judged" : "");
    else if (result.broke > 0)
      why = ": the breaks of the last judgment found no new equilibrium in the cycles given (is the "
            "rock collapsing?); the state is kept as it is";
    else if (result.unjudged)
      why = "; its state is not an equilibrium and was not judged";
    if (!result.converged && def.balance > 0.0 && result.body_share > def.balance)
      why += fmt::format("; the rock of block {} at ({:.6g}, {:.6g}) stayed {:.3g} % out of balance (balance {:.3g})",
                         result.body_block + 1, result.body_at.x, result.body_at.y, 100.0 * result.body_share,
                         def.balance);
    if (result.converged)
      fmt::print("solve: {} cycles, ratio {:.3g}{}\n", result.cycles, result.ratio, rounds);
    else
      fmt::print("solve: stopped after {} cycles at ratio {:.3g} (not converged to {:.3g}{}){}{}\n",
                 result.cycles, result.ratio, def.ratio,
                 def.settle > 0.0 ? fmt::format(" and settled to {:.3g}", def.settle) : "", rounds, why);
    // The ratio is a sum over the whole model: a block's unbalanced force can hide in it.
    if (result.converged && result.body_share > kBodyOutOfBalance)
      fmt::print("solve: the rock of block {} at ({:.6g}, {:.6g}) is out of balance: {:.3g} % of the forces on it "
                 "are unbalanced, which the ratio over the whole model hides; it has not settled yet (a lower "
                 "ratio settles it) or has no equilibrium near (under local damping it creeps; adaptive damping "
                 "lets it move, or support it)\n",
                 result.body_block + 1, result.body_at.x, result.body_at.y, 100.0 * result.body_share);
    std::fflush(stdout);
  }
  lua_createtable(L, 0, 10);
  set_field(L, "cycles", static_cast<long long>(result.cycles));
  set_field(L, "ratio", result.ratio);
  lua_pushboolean(L, result.converged);
  lua_setfield(L, -2, "converged");
  lua_pushboolean(L, result.stalled);
  lua_setfield(L, -2, "stalled");
  set_field(L, "judgments", static_cast<long long>(result.judgments));
  set_field(L, "broke", static_cast<long long>(result.broke));
  set_field(L, "body_share", result.body_share);
  set_field(L, "body_block", static_cast<long long>(result.body_block) + 1);
  set_field(L, "body_x", result.body_at.x);
  set_field(L, "body_y", result.body_at.y);
  return 1;
}

int run_every(lua_State* L, Context& context, const Args& args) {
  auto callback = lua_callback(L, args.get<FunctionArg>("fn").index);
  const int handle =
      context.model().add_callback(static_cast<long>(args.integer("n")), std::move(callback));
  lua_pushinteger(L, handle);
  return 1;
}

int run_cancel(lua_State*, Context& context, const Args& args) {
  const std::int64_t handle = args.integer("handle");
  if (handle < std::numeric_limits<int>::min() || handle > std::numeric_limits<int>::max())
    fail("no callback with handle {}", handle);
  context.model().cancel_callback(static_cast<int>(handle));
  return 0;
}

}  // namespace

const Command& set_command() {
  static const Command command{
      .name = "set",
      .help =
          "Changes solver settings; keys left out keep their current value. `mode = "
          "\"dynamic\"` also turns damping off and `mode = \"static\"` makes it adaptive, "
          "unless the same call gives `damping`.",
      .keys =
          {
              {"mode", Type::string, "", any_value, kOptional,
               "static: damped to equilibrium; dynamic: real time, real masses",
               "unchanged (initially static)", modes},
              {"damping", Type::string, "", any_value, kOptional,
               "adaptive: viscous damping 2 omega, omega from the Rayleigh quotient of the "
               "displacement so far (adaptive dynamic relaxation); local: Itasca's local "
               "damping with a fixed coefficient; none",
               "unchanged (initially adaptive)", dampings},
              {"local_damping", Type::number, "-", from_below(0, 1), kOptional,
               "coefficient of local damping", "unchanged (initially 0.8)"},
              {"step", Type::number, "s", ge(0), kOptional,
               "forced time step (dynamic mode); 0: automatic", "unchanged (initially 0)"},
              {"fraction", Type::number, "-", above_upto(0, 1), kOptional,
               "automatic time step as a fraction of the critical one",
               "unchanged (initially 0.9)"},
              {"mixed", Type::boolean, "", any_value, kOptional,
               "mixed discretisation: the volumetric strain of pairs of neighbouring zones "
               "averaged, as FLAC's quadrilaterals: no volumetric locking. Use it for "
               "near-incompressible or associated plastic flow (footings, psi = phi); the "
               "plain triangles stay nearer the closed form for non-associated rock "
               "(Salencon, psi = 0), measured in engine/solver/cycle.cpp",
               "unchanged (initially false)"},
              {"overlap", Type::number, "m", ge(0), kOptional,
               "the overlap watchdog's limit: a gridpoint further than this inside another block (beyond "
               "its contact's prestress; behind the edge's line and, at the edge's convex corners, "
               "behind the lines of the free faces beside it: a gridpoint beside a corner is not in "
               "the block, one behind a glued face is in the rock glued there) stops the run; 0: half "
               "the median length of the blocks' touchable edges, UDEC's rounding of a kind, plus the largest closure over which a "
               "joint law follows its measured curve (kn_law \"seed-cubic\": 1.03 mm times its "
               "closure_scale; a gridpoint sunk that far is the law at work)",
               "unchanged (initially 0)"},
          },
      .run = run_set,
      .usage = "set{ mode = \"dynamic\" }\nset{ damping = \"local\", local_damping = 0.8 }",
  };
  return command;
}

const Command& reset_command() {
  static const Command command{
      .name = "reset",
      .help =
          "Sets to zero the gridpoint displacements or velocities, clears the zones' "
          "plastic state flags and plastic work, or (\"joint\", UDEC's RESET JDISP) zeroes the contacts' shear "
          "displacement and slip records, of the whole model (stresses and contact forces are "
          "kept).",
      .positional =
          {
              {"what",
               Type::strings,
               "",
               any_value,
               kRequired,
               "what to reset",
               {},
               resettable,
               true},
          },
      .run = run_reset,
      .usage = "reset{ \"displacement\", \"velocity\", \"joint\" }",
  };
  return command;
}

const Command& cycle_command() {
  static const Command command{
      .name = "cycle",
      .help =
          "Runs a number of solver cycles (steps), whatever the unbalanced force. Callbacks "
          "and histories run between cycles.",
      .form = Form::call,
      .positional =
          {
              {"n", Type::integer, "", between(1, kMostCycles), kRequired,
               "number of cycles (at most 1e12: eleven days at a million cycles a second)"},
          },
      .run = run_cycle,
      .usage = "cycle(1000)",
  };
  return command;
}

const Command& solve_command() {
  static const Command command{
      .name = "solve",
      .help =
          "Cycles until the unbalanced-force ratio is at most `ratio`, or `max_cycles` have "
          "run, and prints one line saying which (not with --quiet). With judge{ at = "
          "\"equilibrium\" } each state at the ratio is judged, and cycling goes on after a "
          "judgment that broke sections until one breaks none; max_cycles counts them all.",
      .keys =
          {
              {"ratio", Type::number, "-", above_below(0, 1), "1e-5",
               "unbalanced-force ratio to reach: total unbalanced force over total applied and "
               "zone forces"},
              {"max_cycles", Type::integer, "", between(1, kMostCycles), "100000",
               "stop after this many cycles (at most 1e12)"},
              {"stall", Type::integer, "", between(0, kMostCycles), "0",
               "stop after this many cycles in which the ratio has not fallen a tenth below its lowest "
               "since the load came off or sections last broke: rock that keeps sliding or creeping, "
               "with no equilibrium near, ends its solve there instead of at max_cycles; 0: never"},
              {"settle", Type::number, "-", between(0, 1), "0",
               "below ratio: a state at the ratio is solved on to this one under adaptive damping "
               "before it counts or, judged at equilibrium, is judged; after a judgment that broke "
               "sections the next state is approached under the set damping again, which the solve "
               "gives back at its end. Local damping brings rock that can slide to an equilibrium "
               "safely, but on soft joints it can take tens of thousands of cycles over the last "
               "decades, which adaptive damping may take in a few thousand (tests/bench/RESULTS.md, "
               "\"One step from the in-situ state\"). 0: not"},
              {"balance", Type::number, "-", from_below(0, 1), "0",
               "a state at the ratio counts (is converged, or judged at equilibrium) only once no body "
               "(rock its zones and intact sections join) has more than this share of the forces on it "
               "unbalanced: the ratio, a sum over the whole model, can hide a few blocks with no "
               "equilibrium, which the damping holds creeping (tests/verification/unbalanced_body.lua). "
               "A body further out of balance than this, at a state at the ratio, moves undamped while "
               "the solve goes on, until it is back within it: it slides or falls as friction and its "
               "contacts let it, not as far as the cycles let it creep. 0: not asked"},
          },
      .run = run_solve,
      .returns = "a table: cycles (run by this call), ratio (reached), converged (true or false), stalled "
                 "(true: stopped by stall), judgments (with judge{ at = \"equilibrium\"}: the states judged) and "
                 "broke (the sections they broke); body_share, body_block, body_x, body_y: the body (rock its zones "
                 "and intact sections join) whose net unbalanced force is the largest share of the forces on it "
                 "(its weight, contacts and loads), one of its blocks and where that block is: above 0.01 in a "
                 "state the ratio calls converged, solve prints that the rock there is out of balance",
      .usage = "solve{ ratio = 1e-5 }\nsolve()",
      .bare_call = true,
  };
  return command;
}

const Command& every_command() {
  static const Command command{
      .name = "every",
      .help =
          "Calls a function after every n-th cycle (cycle numbers that are multiples of n), "
          "with the cycle number as its argument. An error inside it stops the run at that "
          "cycle and names its line and the cycle() or solve() that was running.",
      .form = Form::call,
      .positional =
          {
              {"n", Type::integer, "", ge(1), kRequired, "cycles between calls"},
              {"fn", Type::function, "", any_value, kRequired, "the function, fn(cycle)"},
          },
      .run = run_every,
      .returns = "a handle for `cancel`",
      .usage = "local h = every(100, function(cycle) print(cycle, info().ratio) end)",
  };
  return command;
}

const Command& cancel_command() {
  static const Command command{
      .name = "cancel",
      .help = "Stops calling a function registered with `every`.",
      .form = Form::call,
      .positional =
          {
              {"handle", Type::integer, "", any_value, kRequired, "what `every` returned"},
          },
      .run = run_cancel,
      .usage = "cancel(h)",
  };
  return command;
}

}  // namespace edem
