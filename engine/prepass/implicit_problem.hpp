// The static elastoplastic problem the prepass (prepass.hpp) solves, on the solver's arrays: the
// live zones as the explicit cycle sees them (plain constant-strain triangles, small strain, plane
// strain), their materials, the model's weight and boundary loads, its supports. The unknowns are
// the free displacement components. A load step integrates each zone's stress from the step's
// start in one increment, through the same kernels as the cycle (constitutive/mohr_coulomb.hpp):
// backward Euler, whose tangent (differentiated numerically) is the consistent one.
#pragma once

#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "prepass/interfaces.hpp"
#include "state/mechanics.hpp"

namespace edem {

struct ImplicitProblem {
  std::vector<int> zones;        // mesh zones in the problem
  // Per node component: its unknown, or -1 (held, or in no zone). Several components may share
  // one unknown: nodes tied together (the two faces of a joint, with joints = false).
  std::vector<int> free_of;
  int unknowns = 0;
  std::vector<double> applied;   // per node component: weight + boundary loads [N/m]
  std::vector<double> base;      // per node component: u when the problem was made; unknowns add to it [m]
  // Per node component (empty: none): a held component's prescribed displacement over the stage,
  // applied in proportion to the load factor [m].
  std::vector<double> drive;
  // The state at the start of the load step.
  std::vector<Stress> stress0;   // per problem zone [Pa]
  std::vector<double> u0;        // per node component [m]
  // The trial at the last evaluated displacement.
  std::vector<Stress> stress;    // per problem zone [Pa]
  std::vector<std::uint8_t> state;  // per problem zone: kShearNow | kTensionNow of the trial
  // Joints (prepass/interfaces.hpp): the pairs between rock in the problem, their state at the
  // step's start and their trial.
  std::vector<InterfacePair> pairs;
  std::vector<int> pair_index;  // per pair: its index in the prepass's list
  std::vector<InterfaceState> pair_state0, pair_state;
};

// The problem over `zones` (mesh zones with a material that is not null), starting from the
// stresses `stress` (per mesh zone) and displacements `u` (per node component). Nodes with no zone
// in the problem are held. `tie` (per node; empty: none) maps each node to the node it moves
// with; a group is held in x (y) if any of its nodes is.
ImplicitProblem make_problem(const Mechanics& m, const std::vector<int>& zones, const std::vector<Stress>& stress,
                             const std::vector<double>& u, const std::vector<int>& tie);

// Adds the joint pairs whose two nodes are in the problem, with their state now.
void add_interfaces(const Mechanics& m, ImplicitProblem& p, const std::vector<InterfacePair>& pairs,
                    const std::vector<InterfaceState>& state);

// The trial becomes the step's start (a load step converged).
void commit_trial(ImplicitProblem& p, const std::vector<double>& u);

// The unknowns (displacements since `base`) from per-component displacements (the first component
// of each), and back.
void gather_unknowns(const ImplicitProblem& p, const std::vector<double>& u, double* unknowns);
void scatter_unknowns(const ImplicitProblem& p, const double* unknowns, std::vector<double>& u);
// Per unknown, the sum of `force` over its components.
void sum_to_unknowns(const ImplicitProblem& p, const std::vector<double>& force, double* out);

// Trial stresses at displacement u (per node component) from the step's start, and the
// out-of-balance force (applied + zone forces) per node component.
void evaluate(const Mechanics& m, ImplicitProblem& p, const std::vector<double>& u, std::vector<double>& force);

// d force / d u over the unknowns at u (the last evaluate()'s trial), as triplets.
void tangent(const Mechanics& m, const ImplicitProblem& p, const std::vector<double>& u,
             std::vector<Eigen::Triplet<double, int>>& out);

}  // namespace edem
