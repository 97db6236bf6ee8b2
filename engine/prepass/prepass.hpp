// The implicit elastoplastic prepass (the seed paper's prior analysis, its §2.2): the model solved
// statically, implicitly, from its present state through excavation stages, to find where the
// rock yields and how the principal stresses point, before the explicit run (which it leaves
// untouched).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "constitutive/mohr_coulomb.hpp"
#include "core/vec2.hpp"
#include "core/defs.hpp"

namespace edem {

enum class PrepassSolver { klu, lu, ldlt, umfpack };  // KLU; Eigen's SparseLU / SimplicialLDLT; UMFPACK

struct NewtonSettings {
  int steps = 10;                // load steps per stage
  double tolerance = 1e-8;       // converged: |out-of-balance force| <= tolerance x force scale, per component
  int max_iterations = 30;       // Newton iterations per load step before it is cut back
  int max_cutbacks = 10;         // halvings of one step before the stage's attempt fails
  int restarts = 2;              // a failed stage solved again from its start in twice the steps
  PrepassSolver solver = PrepassSolver::umfpack;
  bool keep_on_failure = false;  // a stage that fails ends the prepass there instead of throwing
  double seconds = 600.0;        // the whole prepass's time budget [s]; past it, it fails as a stage does
};

struct LoadStep {
  double from = 0.0, to = 0.0;   // load factor
  bool converged = false;
  std::vector<double> residuals;  // |force|_inf / scale at each Newton iterate, the last one converged
};

struct StageLog {
  std::vector<LoadStep> steps;    // every attempt, cut-back ones included
  int iterations = 0;             // Newton iterations, all attempts
  int cutbacks = 0;
  int restarts = 0;               // times the stage was solved again from its start (solve_stage)
  double scale = 0.0;             // force scale [N/m]
  double seconds = 0.0;
  std::string failure;            // keep_on_failure: why the stage stopped short of its full load
  double reached = 1.0;           // the load factor of its last converged step
  bool out_of_time = false;       // stopped by the prepass's time budget
};


struct PrepassDef {
  std::vector<RegionRef> stages;  // excavated in turn after the present state is solved
  NewtonSettings newton;
  bool joints = true;             // joints as interface elements (false: the rock mass as one continuum)
  // Held components with a velocity (boundary{ xvel, yvel }) move by velocity x duration during
  // the first stage, the present state [s; cycles in static mode, where velocities are per cycle].
  double duration = 0.0;
};

struct PrepassStage {
  std::string name;               // "present state", or the stage's region
  StageLog log;
};

struct PrepassResult {
  std::vector<PrepassStage> stages;   // the present state first
  std::vector<int> zones;             // mesh zones solved (not null at the start)
  // Per zone of `zones`, per stage: the state bits (kShearNow | kTensionNow) the zone reached in a
  // converged load step of that stage; kExcavated once it is excavated.
  std::vector<std::vector<std::uint8_t>> state;
  std::vector<Vec2> centroid;         // per zone [m]
  std::vector<Stress> stress;         // per zone at the end [Pa] (zero once excavated)
  std::vector<Vec2> gridpoint_u;      // per mesh gridpoint at the end [m]
  double seconds = 0.0;
};

inline constexpr std::uint8_t kExcavatedInPrepass = 16;

}  // namespace edem
