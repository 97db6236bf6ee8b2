// prepass{}: the implicit elastoplastic prepass (engine/prepass), its result as a Lua table.
#include <lua.hpp>

#include <cmath>
#include <numbers>

#include "commands.hpp"
#include "context.hpp"
#include "core/error.hpp"
#include "lua_util.hpp"

namespace edem {
namespace {

const std::vector<std::string>& solvers() {
  static const std::vector<std::string> names{"lu", "ldlt", "klu", "umfpack"};
  return names;
}

const std::vector<std::string>& failure_modes() {
  static const std::vector<std::string> names{"error", "keep"};
  return names;
}

const char* state_name(std::uint8_t bits) {
  if (bits & kExcavatedInPrepass) return "excavated";
  const bool shear = bits & kShearNow, tension = bits & kTensionNow;
  if (shear && tension) return "shear+tension";
  if (shear) return "shear";
  if (tension) return "tension";
  return "none";
}

// The state over all stages: shear and tension if it ever yielded so, else none.
std::uint8_t overall(const std::vector<std::uint8_t>& per_stage) {
  std::uint8_t bits = 0;
  for (std::uint8_t s : per_stage) bits |= static_cast<std::uint8_t>(s & (kShearNow | kTensionNow));
  return bits;
}

void push_stages(lua_State* L, const PrepassResult& r) {
  lua_createtable(L, static_cast<int>(r.stages.size()), 0);
  for (size_t i = 0; i < r.stages.size(); ++i) {
    const PrepassStage& s = r.stages[i];
    lua_createtable(L, 0, 6);
    set_field(L, "name", std::string_view(s.name));
    set_field(L, "iterations", s.log.iterations);
    set_field(L, "cutbacks", s.log.cutbacks);
    set_field(L, "restarts", s.log.restarts);
    set_field(L, "seconds", s.log.seconds);
    set_field(L, "force_scale", s.log.scale);
    set_field(L, "reached", s.log.reached);
    if (!s.log.failure.empty()) set_field(L, "failure", std::string_view(s.log.failure));
    lua_createtable(L, static_cast<int>(s.log.steps.size()), 0);
    for (size_t j = 0; j < s.log.steps.size(); ++j) {
      const LoadStep& step = s.log.steps[j];
      lua_createtable(L, 0, 4);
      set_field(L, "from", step.from);
      set_field(L, "to", step.to);
      lua_pushboolean(L, step.converged);
      lua_setfield(L, -2, "converged");
      lua_createtable(L, static_cast<int>(step.residuals.size()), 0);
      for (size_t k = 0; k < step.residuals.size(); ++k) {
        lua_pushnumber(L, step.residuals[k]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
      }
      lua_setfield(L, -2, "residuals");
      lua_rawseti(L, -2, static_cast<lua_Integer>(j + 1));
    }
    lua_setfield(L, -2, "steps");
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "stages");
}

void push_zones(lua_State* L, const PrepassResult& r) {
  lua_createtable(L, static_cast<int>(r.zones.size()), 0);
  for (size_t k = 0; k < r.zones.size(); ++k) {
    const Stress& s = r.stress[k];
    const Principal p = in_plane_principal(s);
    // Direction of the most compressive principal stress, from +x, in (-90, 90] degrees.
    double angle = 0.5 * std::atan2(2.0 * s.xy, s.xx - s.yy) * 180.0 / std::numbers::pi + 90.0;
    if (angle > 90.0) angle -= 180.0;
    lua_createtable(L, 0, 9);
    set_field(L, "id", static_cast<long long>(r.zones[k]) + 1);
    set_field(L, "x", r.centroid[k].x);
    set_field(L, "y", r.centroid[k].y);
    set_field(L, "state", std::string_view(state_name(overall(r.state[k]))));
    lua_createtable(L, static_cast<int>(r.state[k].size()), 0);
    for (size_t i = 0; i < r.state[k].size(); ++i) {
      lua_pushstring(L, state_name(r.state[k][i]));
      lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
    lua_setfield(L, -2, "states");
    set_field(L, "sxx", s.xx);
    set_field(L, "syy", s.yy);
    set_field(L, "sxy", s.xy);
    set_field(L, "szz", s.zz);
    set_field(L, "s1", p.s1);
    set_field(L, "s3", p.s3);
    set_field(L, "angle", angle);
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  lua_setfield(L, -2, "zones");
}

void push_gridpoints(lua_State* L, const PrepassResult& r) {
  lua_createtable(L, static_cast<int>(r.gridpoint_u.size()), 0);
  for (size_t g = 0; g < r.gridpoint_u.size(); ++g) {
    lua_createtable(L, 0, 3);
    set_field(L, "id", static_cast<long long>(g) + 1);
    set_field(L, "ux", r.gridpoint_u[g].x);
    set_field(L, "uy", r.gridpoint_u[g].y);
    lua_rawseti(L, -2, static_cast<lua_Integer>(g + 1));
  }
  lua_setfield(L, -2, "gridpoints");
}

// The table prepass{} returns.
void push_result(lua_State* L, const PrepassResult& r) {
  lua_createtable(L, 0, 5);
  set_field(L, "seconds", r.seconds);
  if (!r.stages.empty() && !r.stages.back().log.failure.empty())
    set_field(L, "failure", std::string_view(r.stages.back().log.failure));
  push_stages(L, r);
  push_zones(L, r);
  push_gridpoints(L, r);
}

int run_prepass(lua_State* L, Context& context, const Args& args) {
  PrepassDef def;
  if (args.has("stages")) def.stages = args.get<std::vector<RegionRef>>("stages");
  def.newton.steps = static_cast<int>(args.integer("steps"));
  def.newton.tolerance = args.number("tolerance");
  def.newton.max_iterations = static_cast<int>(args.integer("iterations"));
  def.newton.restarts = static_cast<int>(args.integer("restarts"));
  const std::string solver = args.string("solver");
  def.newton.solver = solver == "klu"       ? PrepassSolver::klu
                      : solver == "ldlt"    ? PrepassSolver::ldlt
                      : solver == "lu"      ? PrepassSolver::lu
                                            : PrepassSolver::umfpack;
  def.joints = args.boolean("joints");
  def.duration = args.number("duration");
  def.newton.keep_on_failure = args.string("on_failure") == "keep";
  def.newton.seconds = args.number("seconds");
  const PrepassResult r = [&] {
    struct Closer {  // the progress line ends with the prepass, however it ends
      Context& context;
      ~Closer() { context.close_progress_line(); }
    } closer{context};
    return context.model().prepass(def);
  }();
  if (!context.quiet) {
    int iterations = 0;
    for (const PrepassStage& s : r.stages) iterations += s.log.iterations;
    fmt::print("prepass: {} stage(s), {} Newton iterations, {:.3g} s\n", r.stages.size(), iterations, r.seconds);
    if (!r.stages.empty() && !r.stages.back().log.failure.empty())
      fmt::print("prepass: stopped short, kept to load factor {:.4g} of the last stage: {}\n",
                 r.stages.back().log.reached, r.stages.back().log.failure);
    std::fflush(stdout);
  }
  push_result(L, r);
  return 1;
}

int run_prepass_result(lua_State* L, Context& context, const Args&) {
  const auto& last = context.model().last_prepass();
  if (last)
    push_result(L, *last);
  else
    lua_pushnil(L);
  return 1;
}

}  // namespace

const Command& prepass_command() {
  static const Command command{
      .name = "prepass",
      .help =
          "The implicit elastoplastic prepass: solves the model statically from its present state (plain "
          "triangles, small strain, plane strain; elastic and Mohr-Coulomb zones), then excavates each of "
          "`stages` in turn and solves again, with KINSOL's Newton method and line search on the consistent "
          "tangent. Each stage's out-of-balance force is applied in `steps` load steps, a step that fails is "
          "halved (up to 10 times), and a stage whose step still fails is solved again from "
          "its start in twice as many steps (`restarts` times) before it fails with a message "
          "naming it (on_failure = \"keep\": the prepass ends there instead and returns what it "
          "found up to that stage's last converged step, with failure set: near collapse, where "
          "the continuum has no static state, or where Newton fails on every path tried; the "
          "message cannot tell which). The model is left as it "
          "was. Returns a table: failure (only when it stopped short: the message), stages (name, iterations, "
          "cutbacks, restarts, seconds, reached (load factor of the last converged step: 1 unless "
          "it stopped short), "
          "failure (the stage that stopped short), steps with each Newton iterate's residual), zones (id, x, y, state over all stages and states per stage: none, shear, "
          "tension, shear+tension, excavated; stresses, principal s1 (most compressive) and s3, angle of "
          "s1 from +x in degrees) and gridpoints (id, ux, uy: displacement the prepass adds). Joints are "
          "zero-thickness interface elements between node pairs across them (the zoning puts the two faces' "
          "gridpoints at the same places): kn, ks, Coulomb slip and no tension once open or slipped, from the "
          "stress beside them; constant kn only. A block that comes loose has no static equilibrium, and the "
          "stage fails saying so.",
      .keys =
          {
              {"stages", Type::regions, "", any_value, kOptional,
               "regions excavated in turn (names or polygons)", "none"},
              {"steps", Type::integer, "", ge(1), "10", "load steps per stage"},
              {"tolerance", Type::number, "-", any_value, "1e-8",
               "converged when every out-of-balance force component is at most this times the stage's force scale"},
              {"iterations", Type::integer, "", ge(1), "30", "Newton iterations per load step before it is halved"},
              {"restarts", Type::integer, "", ge(0), "2",
               "a stage that fails after its cut-backs is solved again from its start in twice "
               "as many load steps, at most this many times: Newton's failure depends on the load "
               "path as well as on the load"},
              {"solver", Type::string, "", any_value, "\"umfpack\"",
               "sparse direct solver (measured in tests/bench/RESULTS.md): umfpack (SuiteSparse's UMFPACK, the "
               "fastest; its dense kernels come from OpenBLAS, which picks them for the CPU, so its last bits, and "
               "through the cracks placed from them a whole run, can differ from one machine to another), lu "
               "(Eigen's SparseLU: the same answer on any x86-64 machine), ldlt (Eigen's SimplicialLDLT: "
               "symmetric tangents only, elastic or associated flow) or klu (SuiteSparse's KLU through SUNDIALS)",
               "", solvers},
              {"duration", Type::number, "s", ge(0), "0",
               "held gridpoints with a velocity (boundary{ xvel, yvel }) move by velocity x duration in the first "
               "stage, in its load steps (static mode: velocities are per cycle, so this is cycles)"},
              {"seconds", Type::number, "s", gt(0), "600",
               "the whole prepass's time budget: past it the prepass stops at the Newton iteration running, "
               "as a stage that fails does (on_failure decides what follows), naming the stage and the load "
               "factor it reached"},
              {"on_failure", Type::string, "", any_value, "\"error\"",
               "a stage whose Newton iterations do not converge: error stops the script; keep ends the prepass "
               "there and returns the result so far (its failure says why)",
               "", failure_modes},
              {"joints", Type::boolean, "", any_value, "true",
               "joints as interface elements; false: each joint's faces tied together (the rock mass as one "
               "continuum)"},
          },
      .run = run_prepass,
      .returns = "a table: stages, zones, gridpoints, seconds",
      .usage = "local pre = prepass{ stages = { \"heading\", \"bench\" }, steps = 10 }",
  };
  return command;
}

const Command& prepass_result_command() {
  static const Command command{
      .name = "prepass_result",
      .help =
          "The result of the last prepass{} on the present zones, the same table prepass{} returned; kept in "
          "checkpoints, so a restored script can place crackseed{ auto } from it. nil when there is none.",
      .form = Form::call,
      .run = run_prepass_result,
      .returns = "a table as prepass{} returns, or nil",
      .usage = "local pre = prepass_result()",
  };
  return command;
}

}  // namespace edem
