// A SUNDIALS linear solver over Eigen's sparse direct solvers, for KINSOL: it factors the
// SUNSparseMatrix (CSC) KINSOL fills with the tangent, in place, without copying.
//   lu:   Eigen::SparseLU (COLAMD ordering), for any tangent (non-associated flow makes it unsymmetric)
//   ldlt: Eigen::SimplicialLDLT (AMD ordering), for symmetric tangents only (elastic zones, or
//         associated flow), reading the lower triangle
//   umfpack: SuiteSparse's UMFPACK (multifrontal, BLAS) through Eigen's UmfPackSupport, for any tangent;
//            METIS ordering, no iterative refinement. Its speed is mostly the BLAS's (dgemm):
//            scripts/install-deps.sh installs OpenBLAS (libopenblas0-serial) in place of reference BLAS
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

namespace edem {

enum class EigenFactorisation { lu, ldlt, umfpack };

// The caller frees it with SUNLinSolFree. Setup returns SUNLS_PACKAGE_FAIL_REC when the matrix
// is singular (a mechanism: KINSOL then reports a failed linear setup).
SUNLinearSolver make_eigen_linear_solver(SUNContext context, EigenFactorisation kind);

}  // namespace edem
