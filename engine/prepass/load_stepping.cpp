#include "prepass/load_stepping.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/error.hpp"
#include "prepass/eigen_linear_solver.hpp"

namespace edem {
namespace {

// What KINSOL's callbacks see.
struct System {
  const Mechanics* m = nullptr;
  ImplicitProblem* p = nullptr;
  std::vector<double> r0;     // out-of-balance force at the stage's start, per unknown
  double load = 0.0;          // load factor a
  double scale = 1.0;         // force scale
  std::vector<double> u;      // per node component, the unknowns scattered in
  std::vector<double> force;  // per node component
  std::vector<Eigen::Triplet<double, int>> triplets;
  LoadStep* log = nullptr;
  std::string error;          // KINSOL's last message
  bool stop_when_stalled = false;  // this attempt gives up once it stops moving
  bool stalled = false;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  bool out_of_time = false;  // the prepass's time budget ran out during this attempt
};

// A line search that gives the same out-of-balance force, to the last bit, at this many iterations
// in a row has stopped moving the iterate: its steps have shrunk to nothing, and it would repeat
// them to the last iteration (case.lua's prepasses, Cases 1 to 3 at 158 m and Case 3 at 212 and
// 262 m: 56 of the 60 load steps that failed ended in 3 to 26 such repeats; none of the 212 that
// converged had any). Stopping sooner, at no progress over 5 iterations, cut back a step at 262 m
// whose line search would have converged 5 iterations later.
constexpr int kStallRepeats = 3;

bool stalled(const std::vector<double>& residuals) {
  const size_t n = residuals.size();
  if (n <= kStallRepeats) return false;
  for (size_t k = n - kStallRepeats; k < n; ++k)
    if (residuals[k] != residuals[k - 1]) return false;
  return true;
}

int residual(N_Vector x, N_Vector f, void* data) {
  System& s = *static_cast<System*>(data);
  scatter_unknowns(*s.p, N_VGetArrayPointer_Serial(x), s.u);
  evaluate(*s.m, *s.p, s.u, s.force);
  double* out = N_VGetArrayPointer_Serial(f);
  sum_to_unknowns(*s.p, s.force, out);
  bool finite = true;
  for (size_t k = 0; k < s.r0.size(); ++k) {
    out[k] -= (1.0 - s.load) * s.r0[k];
    finite = finite && std::isfinite(out[k]);
  }
  return finite ? 0 : 1;  // > 0: recoverable, the line search steps back
}

int jacobian(N_Vector x, N_Vector f, SUNMatrix jac, void* data, N_Vector, N_Vector) {
  System& s = *static_cast<System*>(data);
  const double* fx = N_VGetArrayPointer_Serial(f);
  const sunindextype n = N_VGetLength_Serial(f);
  double largest = 0.0;
  for (sunindextype k = 0; k < n; ++k) largest = std::max(largest, std::abs(fx[k]));
  s.log->residuals.push_back(largest / s.scale);
  if (s.stop_when_stalled && stalled(s.log->residuals)) {
    s.stalled = true;
    return -1;  // unrecoverable: KINSOL stops this attempt, and the load step is cut back
  }
  if (std::chrono::steady_clock::now() > s.deadline) {
    s.out_of_time = true;
    return -1;  // unrecoverable: KINSOL stops, and so does the prepass
  }
  scatter_unknowns(*s.p, N_VGetArrayPointer_Serial(x), s.u);
  tangent(*s.m, *s.p, s.u, s.triplets);
  Eigen::SparseMatrix<double, Eigen::ColMajor, sunindextype> k(n, n);
  k.setFromTriplets(s.triplets.begin(), s.triplets.end());
  k.makeCompressed();
  if (SUNSparseMatrix_NNZ(jac) < k.nonZeros() && SUNSparseMatrix_Reallocate(jac, k.nonZeros()) != 0) return -1;
  std::memcpy(SUNSparseMatrix_IndexPointers(jac), k.outerIndexPtr(), sizeof(sunindextype) * static_cast<size_t>(n + 1));
  std::memcpy(SUNSparseMatrix_IndexValues(jac), k.innerIndexPtr(), sizeof(sunindextype) * static_cast<size_t>(k.nonZeros()));
  std::memcpy(SUNSparseMatrix_Data(jac), k.valuePtr(), sizeof(double) * static_cast<size_t>(k.nonZeros()));
  return 0;
}

void keep_error(int, const char*, const char*, char* message, void* data) {
  static_cast<System*>(data)->error = fmt::format("KINSOL: {}", message);
}

// SUNDIALS objects of one stage, freed in any case.
struct Kinsol {
  SUNContext context = nullptr;
  void* memory = nullptr;
  N_Vector x = nullptr, ones = nullptr, fscale = nullptr;
  SUNMatrix jac = nullptr;
  SUNLinearSolver linear = nullptr;
  ~Kinsol() {
    if (memory) KINFree(&memory);
    if (linear) SUNLinSolFree(linear);
    if (jac) SUNMatDestroy(jac);
    if (x) N_VDestroy(x);
    if (ones) N_VDestroy(ones);
    if (fscale) N_VDestroy(fscale);
    if (context) SUNContext_Free(&context);
  }
};

void check(int flag, const char* what) {
  if (flag < 0) fail("{} failed (SUNDIALS flag {})", what, flag);
}

std::string flag_name(int flag) {
  char* name = KINGetReturnFlagName(flag);  // malloc'ed
  std::string out = name ? name : "?";
  std::free(name);
  return out;
}

double infinity_norm(const std::vector<double>& v) {
  double largest = 0.0;
  for (double x : v) largest = std::max(largest, std::abs(x));
  return largest;
}

// The force scale: the larger of what is released and what is applied, and, with prescribed
// displacements, the forces the whole of them gives on the free nodes. A model with none of these
// is balanced already; its released force is round-off of the zones' forces, which no Newton step
// can reduce a further 1e-8: the scale is at least a millionth of the largest zone force (stress
// times the zone's size), still far below any real load (a jointed square under a uniform 5 MPa
// with no gravity: a scale of 3.7e-9 N/m, and the present state "failed" after 1,054 iterations).
double force_scale(const Mechanics& m, ImplicitProblem& p, System& s) {
  std::vector<double> applied(s.r0.size()), out(s.r0.size());
  sum_to_unknowns(p, p.applied, applied.data());
  double driven = 0.0;
  if (!p.drive.empty()) {
    std::vector<double> u = p.u0;
    for (size_t i = 0; i < u.size(); ++i) u[i] += p.drive[i];
    evaluate(m, p, u, s.force);
    sum_to_unknowns(p, s.force, out.data());
    for (size_t j = 0; j < out.size(); ++j) driven = std::max(driven, std::abs(out[j] - s.r0[j]));
  }
  double internal = 0.0;
  for (size_t k = 0; k < p.zones.size(); ++k) {
    const Stress& t = p.stress0[k];
    const double largest = std::max({std::abs(t.xx), std::abs(t.yy), std::abs(t.xy)});
    internal = std::max(internal, largest * std::sqrt(m.geometry[static_cast<size_t>(p.zones[k])].area));
  }
  return std::max({infinity_norm(s.r0), infinity_norm(applied), driven, 1e-6 * internal, 1e-300});
}

// KINSOL set up for n unknowns: exact Newton (a fresh tangent every iteration), converged on the
// scaled force alone.
void start_kinsol(Kinsol& k, System& s, sunindextype n, size_t zones, const NewtonSettings& settings) {
  check(SUNContext_Create(nullptr, &k.context), "SUNContext_Create");
  k.x = N_VNew_Serial(n, k.context);
  k.ones = N_VNew_Serial(n, k.context);
  k.fscale = N_VNew_Serial(n, k.context);
  // Room for a full 6 x 6 block per zone: reallocated by the Jacobian if short.
  k.jac = SUNSparseMatrix(n, n, std::max<sunindextype>(1, 36 * static_cast<sunindextype>(zones)), CSC_MAT, k.context);
  switch (settings.solver) {
    case PrepassSolver::klu: k.linear = SUNLinSol_KLU(k.x, k.jac, k.context); break;
    case PrepassSolver::lu: k.linear = make_eigen_linear_solver(k.context, EigenFactorisation::lu); break;
    case PrepassSolver::ldlt: k.linear = make_eigen_linear_solver(k.context, EigenFactorisation::ldlt); break;
    case PrepassSolver::umfpack: k.linear = make_eigen_linear_solver(k.context, EigenFactorisation::umfpack); break;
  }
  if (!k.x || !k.ones || !k.fscale || !k.jac || !k.linear) fail("out of memory for {} unknowns", n);
  N_VConst(1.0, k.ones);
  N_VConst(1.0 / s.scale, k.fscale);
  k.memory = KINCreate(k.context);
  if (!k.memory) fail("KINCreate failed");
  check(KINInit(k.memory, residual, k.x), "KINInit");
  check(KINSetUserData(k.memory, &s), "KINSetUserData");
  check(KINSetErrHandlerFn(k.memory, keep_error, &s), "KINSetErrHandlerFn");
  check(KINSetLinearSolver(k.memory, k.linear, k.jac), "KINSetLinearSolver");
  check(KINSetJacFn(k.memory, jacobian), "KINSetJacFn");
  check(KINSetMaxSetupCalls(k.memory, 1), "KINSetMaxSetupCalls");
  check(KINSetFuncNormTol(k.memory, settings.tolerance), "KINSetFuncNormTol");
  check(KINSetScaledStepTol(k.memory, 1e-300), "KINSetScaledStepTol");
  check(KINSetNumMaxIters(k.memory, settings.max_iterations), "KINSetNumMaxIters");
}

// Newton from the step's start (p.u0, held components at `to` of their drive) to load factor `to`.
// Full Newton steps first: the return mapping's tangent jumps where a zone's active surface
// changes, and a line search on |F| then stalls (measured on Salencon, psi = 0: stuck at 1e-5 of
// the force scale at small load steps, where full steps converge in 4 or 5 iterations). A step
// that fails so is tried again with KINSOL's line search. Returns KINSOL's flag; s.u is the answer.
int newton(Kinsol& k, System& s, ImplicitProblem& p, double to, StageLog& log) {
  s.load = to;
  s.u = p.u0;
  if (!p.drive.empty())
    for (size_t i = 0; i < s.u.size(); ++i)
      if (p.drive[i] != 0.0) s.u[i] = p.base[i] + to * p.drive[i];
  s.error.clear();
  int flag = 0;
  for (const int strategy : {KIN_NONE, KIN_LINESEARCH}) {
    if (s.out_of_time) break;
    gather_unknowns(p, p.u0, N_VGetArrayPointer_Serial(k.x));
    s.log->residuals.clear();
    s.stop_when_stalled = strategy == KIN_LINESEARCH;  // full steps may well climb back down
    s.stalled = false;
    flag = KINSol(k.memory, k.x, strategy, k.ones, k.fscale);
    long iterations = 0;
    KINGetNumNonlinSolvIters(k.memory, &iterations);
    log.iterations += static_cast<int>(iterations);
    if (s.stalled)
      s.error = fmt::format("its line search stopped moving: the same force {} times in a row",
                            kStallRepeats + 1);
    if (flag >= 0) break;
  }
  scatter_unknowns(p, N_VGetArrayPointer_Serial(k.x), s.u);
  return flag;
}

// One attempt at the stage in `steps` load steps, from p's start; on failure log.failure says why
// and p stays at the last converged step.
StageLog solve_in_steps(const Mechanics& m, ImplicitProblem& p, const NewtonSettings& settings,
                        int steps, const std::string& stage, std::vector<std::uint8_t>& yielded,
                        const StepDone& step_done, int iterations_before,
                        std::chrono::steady_clock::time_point deadline) {
  StageLog log;
  const sunindextype n = p.unknowns;
  yielded.assign(p.zones.size(), 0);
  if (n == 0) return log;

  System s;
  s.m = &m;
  s.p = &p;
  s.u = p.u0;
  evaluate(m, p, p.u0, s.force);
  s.r0.resize(static_cast<size_t>(n));
  sum_to_unknowns(p, s.force, s.r0.data());
  s.scale = force_scale(m, p, s);
  s.deadline = deadline;
  log.scale = s.scale;
  Kinsol k;
  start_kinsol(k, s, n, p.zones.size(), settings);

  std::vector<double> out(static_cast<size_t>(n));
  double done = 0.0, size = 1.0 / steps;
  int halvings = 0;
  // Cut-backs since the load last moved on by a tenth of a step: near a limit point (a block
  // losing its support) Newton converges only in ever smaller steps, each success doubling the
  // step and the next failure halving it again, creeping on without end (a wedge over a tunnel:
  // 2,208 iterations in 36 s, from load factor 0.9663 to 0.9663). Counted across successes, they
  // end the attempt as halvings of one step do.
  int creeping = 0;
  double moved_from = 0.0;
  while (done < 1.0) {
    const double to = done + size >= 1.0 - 1e-9 ? 1.0 : done + size;  // no sliver step from rounding
    log.steps.push_back({done, to, false, {}});
    s.log = &log.steps.back();
    const int flag = newton(k, s, p, to, log);
    if (step_done) step_done(done, iterations_before + log.iterations);
    // Check the answer on its own terms: KINSOL's step-size stops are not convergence.
    evaluate(m, p, s.u, s.force);
    sum_to_unknowns(p, s.force, out.data());
    double largest = 0.0;
    for (size_t j = 0; j < out.size(); ++j) largest = std::max(largest, std::abs(out[j] - (1.0 - to) * s.r0[j]));
    if (s.out_of_time) {
      log.failure = fmt::format(
          "{}: the prepass's time budget of {:.6g} s ran out at load factor {:.6g} (this stage so far: "
          "Newton iterations {}, cut-backs {}, in {} load steps from its start); prepass{{ seconds = ... }} "
          "gives it more. A load path this slow is usually one Newton creeps along in ever smaller steps: "
          "rock yielding through, or a block or wedge near losing its support",
          stage, settings.seconds, done, iterations_before + log.iterations, log.cutbacks, steps);
      log.reached = done;
      log.out_of_time = true;
      break;
    }
    if (flag >= 0 && largest <= settings.tolerance * s.scale) {
      s.log->residuals.push_back(largest / s.scale);
      s.log->converged = true;
      commit_trial(p, s.u);
      for (size_t z = 0; z < p.zones.size(); ++z) yielded[z] |= p.state[z];
      done = to;
      halvings = 0;
      if (done - moved_from >= 0.1 / steps) creeping = 0, moved_from = done;
      size = std::min(2.0 * size, 1.0 / steps);
      continue;
    }
    ++log.cutbacks;
    ++creeping;
    if (++halvings > settings.max_cutbacks || creeping > settings.max_cutbacks) {
      std::string why = s.error.empty() ? "KINSOL: " + flag_name(flag) : s.error;
      if (why.ends_with('.')) why.pop_back();  // KINSOL's messages end in a full stop
      log.failure = fmt::format(
          "{}: no equilibrium found beyond load factor {:.6g} ({} load steps from the stage's start): the last "
          "{} cut-backs, down to a step of {:.3g}, moved the load on by {:.3g} in all; Newton's last try "
          "left a relative out-of-balance force of {:.3g} against the tolerance {:.3g} (the largest nodal "
          "force out of balance over the force scale, {:.3g} N/m; {}). A load path that stops so is "
          "usually a mechanism, a block or wedge losing its support or rock yielding through (the "
          "explicit run shows it move)",
          stage, done, steps, creeping, to - done, done - moved_from, largest / s.scale, settings.tolerance,
          s.scale, why);
      log.reached = done;
      break;
    }
    size = 0.5 * (to - done);  // of the step tried, which may have been clamped at the end
  }
  return log;
}

}  // namespace

// A stage that fails is solved again from its start in twice as many load steps, `restarts`
// times at most. Newton's failure is a property of the path as much as of the load: the state a
// coarse step converged to can be one from which no step however small converges, where a finer
// path gets through (Set M's continuum at 212 m, bench 12, in 2 steps a stage: stuck at load
// factor 0.625; in 4 or 10, complete). A stage that every path fails may be near collapse, or
// may be Newton's failure alone: the message cannot tell which.
StageLog solve_stage(const Mechanics& m, ImplicitProblem& p, const NewtonSettings& settings,
                     const std::string& stage, std::vector<std::uint8_t>& yielded, const StepDone& step_done,
                     std::chrono::steady_clock::time_point deadline) {
  const auto start = std::chrono::steady_clock::now();
  const ImplicitProblem at_start = p;
  int steps = settings.steps;
  StageLog log = solve_in_steps(m, p, settings, steps, stage, yielded, step_done, 0, deadline);
  for (int restart = 1; restart <= settings.restarts && !log.failure.empty() && !log.out_of_time; ++restart) {
    if (steps > std::numeric_limits<int>::max() / 2) break;  // no finer path to count
    p = at_start;
    steps *= 2;
    StageLog again = solve_in_steps(m, p, settings, steps, stage, yielded, step_done, log.iterations, deadline);
    again.iterations += log.iterations;
    again.cutbacks += log.cutbacks;
    again.steps.insert(again.steps.begin(), log.steps.begin(), log.steps.end());
    again.restarts = restart;
    log = std::move(again);
  }
  log.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (log.out_of_time && !settings.keep_on_failure) fail("{}", log.failure);
  if (!log.failure.empty() && !settings.keep_on_failure)
    fail("{}; if it is Newton's failure alone, more steps or a softer load path may help", log.failure);
  // keep_on_failure: p stays at the last attempt's last converged step, and the caller solves no
  // further stage.
  return log;
}

}  // namespace edem
