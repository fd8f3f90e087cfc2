// Which linear solver an implicit stage uses (docs/implicit.md, "Linear solvers"):
//
//   direct     - a sparse LU factorization (MUMPS, all ranks together; UMFPACK or Amesos2 KLU2
//                on request, gathered and factored on rank 0: UMFPACK is a one-process library,
//                Amesos2 KLU2 in Trilinos 13.2 returns wrong solutions for distributed matrices)
//                of the whole Jacobian, used as the preconditioner of GMRES, which then
//                converges in one iteration.
//   iterative  - GMRES preconditioned by smoothed-aggregation multigrid (MueLu) with the
//                rigid-body modes as near-null space, built on the finite elements of the
//                background cells where they fit the model (auxiliary space:
//                operators/AuxiliaryStiffness.hpp), else on the Jacobian; or by the
//                preconditioner the stage names.
//   auto       - direct up to `direct_limit` dofs, iterative above.
//
// Plain data: resolving the plan needs the stage settings, the dof count and the rank count.
#pragma once

#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <string>

namespace efg {

struct LinearSolverPlan {
  enum class Preconditioner { direct, multigrid, auxiliary, bulk_split, ifpack2, none };
  Preconditioner preconditioner = Preconditioner::direct;
  std::string reason;               ///< why this one (for the log)
  bool automatic = false;           ///< chosen by `solver: auto` (not named by the stage)
  Teuchos::ParameterList krylov;    ///< the Belos list for the chosen method
  Teuchos::ParameterList settings;  ///< the preconditioner's own list (MueLu, Ifpack2, Amesos2)
  int max_iterations = 0;
  /// The Krylov solve's relative residual tolerance (Belos' "Convergence Tolerance" after the
  /// stage's linear_solver map); NOX hands it to every solve (NewtonSolver).
  double tolerance = 1e-10;
  /// bulk_split: the inner saddle-point GMRES's tolerance (relative).
  double saddle_tolerance = 0;

  /// A short name for messages: "direct (MUMPS LU)", "GMRES + MueLu SA-AMG", ...
  std::string describe() const;
};

/// From this Poisson's ratio on, a model counts as nearly incompressible for the automatic
/// choice: multigrid on the displacement (or condensed mixed u-p) Jacobian stalls there.
inline constexpr double kNearlyIncompressible = 0.49;

/// Largest number of dofs the automatic choice factors directly on one rank, per dimension
/// (measured on this machine: docs/implicit.md); 4x in 3D and 2x in 2D for a nearly
/// incompressible model, where the iterative path has nothing that works.
std::int64_t default_direct_limit(int dimension, bool nearly_incompressible = false);

/// `solver` is the stage's `solver` key (auto, direct, iterative), `direct_limit` its key of that
/// name (<= 0: the default), `linear_solver` and `preconditioner` its pass-through maps, as the
/// scene reader checked them. `poissons_ratio`: the model's largest (nearly incompressible from
/// kNearlyIncompressible on). `auxiliary_misfit`: empty when the auxiliary space fits the model
/// (the iterative path then uses it in 3D), else why not; `auxiliary_impossible`: empty when it
/// can stand in at all (a stage's `Type: auxiliary` falls back to multigrid on the Jacobian
/// otherwise). `bulk_split_fits`: a mixed u-p part's bulk modulus exceeds nu = 1/4's, so the
/// iterative path splits it off (operators/BulkSplit.hpp) unless a `Type` is named.
LinearSolverPlan plan_linear_solver(const std::string& solver, std::int64_t direct_limit,
                                    const Teuchos::ParameterList& linear_solver,
                                    const Teuchos::ParameterList& preconditioner,
                                    std::int64_t global_dofs, int dimension, int ranks,
                                    double poissons_ratio = 0.0,
                                    const std::string& auxiliary_misfit = "no model",
                                    const std::string& auxiliary_impossible = "no model",
                                    bool bulk_split_fits = false);

}  // namespace efg
