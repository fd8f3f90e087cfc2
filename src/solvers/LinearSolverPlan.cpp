#include "solvers/LinearSolverPlan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace efg {
namespace {

using Plan = LinearSolverPlan;

// Smoothed aggregation for vector elasticity (Vanek, Mandel & Brezina 1996): the near-null space
// (rigid-body modes) is attached by the preconditioner; one aggregate per block of `dim` dofs.
// The smoother is Ifpack2's symmetric Gauss-Seidel in 3D and ILU(0) in 2D (measured, 31st
// session, docs/implicit.md): on the 3D cantilever block Gauss-Seidel needs 2x ILU(0)'s
// iterations at 10k particles but as many from 30-40k on (88 against 80 at 40,131 particles,
// dilation 1.5; 63 against 61 at 29,524, dilation 1.2), without ILU's factorization (setup
// 3.6 against 11.2 s) and its copy of the matrix (965 against 1,418 MiB), and on 2 ranks 68
// against 123 iterations (one ILU per rank); on the 2D Timoshenko beam it doubled the
// iterations (180 against 88 at 33,410 dofs). (The first session chose ILU(0) because
// Gauss-Seidel stalled on the transformation method's collocated rows; on the 3D blocks clamped
// by them it converged at every size measured.) Chebyshev took 3x the iterations on the 3D
// block. The coarse
// solve is a relaxation, never Amesos2 KLU2 (wrong answers on more than one rank in 13.2). The
// coarse levels move onto fewer ranks once they are small (Zoltan2 repartitioning below 4,000
// rows per rank): a coarse ILU on each rank's rows alone is a block-Jacobi coarse solve, which
// doubled the GMRES iterations on 2 ranks (Cook's panel at 16,641 particles 20 -> 39, the
// Timoshenko beam with subcells at 33,410 dofs 13 -> 20; with the move 13 on both).
Teuchos::ParameterList multigrid_defaults(int dimension) {
  Teuchos::ParameterList p;
  p.set("verbosity", "none");
  p.set("multigrid algorithm", "sa");
  p.set("number of equations", dimension);
  p.set("max levels", 10);
  p.set("coarse: max size", 1000);
  if (dimension == 3) {
    p.set("smoother: type", "RELAXATION");
    p.sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  } else {
    p.set("smoother: type", "RILUK");
    p.sublist("smoother: params").set("fact: iluk level-of-fill", 0);
  }
  p.set("coarse: type", "RILUK");
  p.sublist("coarse: params").set("fact: iluk level-of-fill", 1);
  p.set("aggregation: type", "uncoupled");
  p.set("repartition: enable", true);
  p.set("repartition: partitioner", "zoltan2");
  p.set("repartition: start level", 1);
  p.set("repartition: min rows per proc", 4000);
  return p;
}

// The auxiliary space's matrix is symmetric positive definite (operators/AuxiliaryStiffness: the
// constrained dofs eliminated symmetrically): Chebyshev smoothing, the textbook setting for
// elasticity, where the Jacobian's collocated rows need ILU.
Teuchos::ParameterList auxiliary_defaults(int dimension) {
  auto p = multigrid_defaults(dimension);
  p.set("smoother: type", "CHEBYSHEV");
  p.remove("smoother: params");
  return p;
}

// The scene reader has checked the names, the contradictions and the direct solver's name
// (SceneReader check_linear_solver), so `efg check` reports them; here they are known good.
Plan::Preconditioner from_type(const std::string& type) {
  if (type == "direct") return Plan::Preconditioner::direct;
  if (type == "MueLu") return Plan::Preconditioner::multigrid;
  if (type == "auxiliary") return Plan::Preconditioner::auxiliary;
  if (type == "Ifpack2") return Plan::Preconditioner::ifpack2;
  if (type == "None") return Plan::Preconditioner::none;
  throw std::logic_error("unchecked preconditioner type '" + type + "'");
}

std::string text(const Teuchos::ParameterList& list, const std::string& key,
                 const std::string& fallback) {
  return list.isParameter(key) ? list.get<std::string>(key) : fallback;
}

}  // namespace

std::string LinearSolverPlan::describe() const {
  const std::string krylov_name = text(krylov, "Solver Type", "Block GMRES");
  switch (preconditioner) {
    case Preconditioner::direct:
      return "direct (" + text(settings, "solver", "MUMPS") + " LU)";
    case Preconditioner::multigrid:
      return krylov_name + " + MueLu smoothed aggregation with rigid-body modes";
    case Preconditioner::auxiliary:
      return krylov_name + " + MueLu smoothed aggregation on the background cells' finite elements";
    case Preconditioner::bulk_split:
      return krylov_name +
             " + block triangular saddle point (mixed u-p bulk stiffness; MueLu smoothed "
             "aggregation on the rest)";
    case Preconditioner::ifpack2:
      return krylov_name + " + Ifpack2 " + text(settings, "Prec Type", "RILUK");
    case Preconditioner::none:
      break;
  }
  return krylov_name + " without preconditioner";
}

// Direct factor times measured on this machine (docs/implicit.md; MUMPS, UMFPACK up to 1.9x
// slower): 2D 0.33 s at 8.5k dofs, 1.8 s at 33k, 14 s at 132k (where multigrid did not converge
// on the beam); 3D (MUMPS, the cantilever block, supports without their zero-weight edges):
// Newton phase 1.2 s at 9.3k dofs (multigrid 1.8 s), 6.5-6.7 s at 31k (multigrid 6.9-7.2 s),
// 26.7 s at 54k (multigrid 14.7 s). Above these limits multigrid is faster where it converges.
// Nearly incompressible models (nu >= 0.49, mixed u-p or not) are factored up to 4x that in 3D
// and 2x in 2D: multigrid stalled on a mixed u-p block at nu = 0.4999 and 33,516 dofs (500
// GMRES iterations, the residual 21x its start, exit 3 after 160 s), which the direct path
// solves in 33 s (2.7 GB peak); 3D factorization memory grows about like n^(4/3) (2.7 GB at
// 54k dofs, about 8 GB at 120k on this 23 GB machine), 2D about like n^1.3 (2.9 GB at 132k,
// about 7 GB at 300k).
std::int64_t default_direct_limit(int dimension, bool nearly_incompressible) {
  const std::int64_t limit = dimension <= 2 ? 150000 : 30000;
  return nearly_incompressible ? limit * (dimension <= 2 ? 2 : 4) : limit;
}

LinearSolverPlan plan_linear_solver(const std::string& solver, std::int64_t direct_limit,
                                    const Teuchos::ParameterList& linear_solver,
                                    const Teuchos::ParameterList& preconditioner,
                                    std::int64_t global_dofs, int dimension, int ranks,
                                    double poissons_ratio, const std::string& auxiliary_misfit,
                                    const std::string& auxiliary_impossible, bool bulk_split_fits) {
  Plan plan;
  const bool typed = preconditioner.isParameter("Type");
  const std::string type = typed ? preconditioner.get<std::string>("Type") : "";
  const bool incompressible = poissons_ratio >= kNearlyIncompressible;
  const std::int64_t limit =
      direct_limit > 0 ? direct_limit : default_direct_limit(dimension, incompressible);
  const std::string why_limit =
      direct_limit <= 0 && incompressible
          ? " (nearly incompressible, nu = " + std::to_string(poissons_ratio).substr(0, 8) +
                ": multigrid stalls there)"
          : "";
  if (typed) {
    plan.preconditioner = from_type(type);
    plan.reason = "preconditioner.Type: " + type;
    if (plan.preconditioner == Plan::Preconditioner::auxiliary && !auxiliary_impossible.empty()) {
      // The finite elements would lack the boundary terms or contacts that hold the model.
      plan.preconditioner = Plan::Preconditioner::multigrid;
      plan.reason +=
          ", which cannot stand in here (" + auxiliary_impossible + "): multigrid on the Jacobian";
    }
  } else if (solver == "direct") {
    plan.preconditioner = Plan::Preconditioner::direct;
    plan.reason = "solver: direct";
  } else if (solver == "iterative") {
    plan.preconditioner = Plan::Preconditioner::multigrid;
    plan.reason = "solver: iterative";
  } else if (global_dofs <= limit) {
    plan.automatic = true;
    plan.preconditioner = Plan::Preconditioner::direct;
    plan.reason =
        "auto: " + std::to_string(global_dofs) + " dofs <= " + std::to_string(limit) + why_limit;
  } else {
    plan.automatic = true;
    plan.preconditioner = Plan::Preconditioner::multigrid;
    plan.reason =
        "auto: " + std::to_string(global_dofs) + " dofs > " + std::to_string(limit) + why_limit;
  }
  // Mixed u-p parts with nu above 1/4: the saddle point of their bulk stiffness above nu = 1/4's,
  // multigrid on the rest (operators/BulkSplit.hpp; docs/mixed.md): GMRES on the Jacobian alone
  // stalls as nu -> 1/2 (its near kernel is every divergence-free field). Multigrid on the
  // relieved Jacobian itself, also in 3D.
  if (!typed && plan.preconditioner == Plan::Preconditioner::multigrid && bulk_split_fits) {
    plan.preconditioner = Plan::Preconditioner::bulk_split;
    plan.reason += "; the mixed u-p parts' bulk stiffness above nu = 1/4 as a saddle point";
  }
  // In 3D the iterative path's multigrid goes on the background cells' finite elements where
  // they fit (docs/implicit.md, "Auxiliary space": cantilever block at 30,927 dofs, subcells,
  // 46 iterations and a 3.0 s Newton phase against 21 and 5.7 s on the Jacobian, flat under
  // refinement). In 2D the Jacobian's own multigrid took 11-15 iterations on the beam to the
  // auxiliary space's 66-77 in the same time: it stays there.
  if (!typed && plan.preconditioner == Plan::Preconditioner::multigrid && dimension == 3) {
    if (auxiliary_misfit.empty()) {
      plan.preconditioner = Plan::Preconditioner::auxiliary;
      plan.reason += "; multigrid on the background cells' finite elements";
    } else {
      plan.reason += "; multigrid on the Jacobian: " + auxiliary_misfit;
    }
  }
  // Krylov method: GMRES (the transformation method makes the Jacobian nonsymmetric). With the
  // direct preconditioner it converges in one iteration; otherwise the iteration count is
  // bounded so that a hopeless solve stops with a message instead of running for hours.
  // The bulk split's preconditioner is a solver (its inner GMRES reaches the outer tolerance):
  // the outer iteration adds its result unscaled (fixed point, x += M^-1 r). Flexible GMRES's
  // one-iteration least-squares coefficient came from products with K, whose round-off at
  // kappa / mu = 5e5 scaled the whole solution by 1 +- 1e-10, differently on 1 and 2 ranks
  // (Lame's cylinder at nu = 0.499999: 1 vs 2 ranks 1.8e-10, 6.5e-15 once that scale was
  // taken out; with the fixed point 1.7e-14).
  const std::string method =
      text(linear_solver, "Solver Type",
           plan.preconditioner == Plan::Preconditioner::bulk_split ? "Fixed Point" : "Block GMRES");
  plan.krylov.set("Solver Type", method);
  auto& chosen = plan.krylov.sublist("Solver Types").sublist(method);
  double tolerance = 1e-10;
  plan.max_iterations = plan.preconditioner == Plan::Preconditioner::direct ? 20 : 500;
  if (plan.preconditioner == Plan::Preconditioner::bulk_split) {
    // The round-off floor of the condensed system, whose entries grow with kappa / mu =
    // 2 (1 + nu) / (3 (1 - 2 nu)): measured 15 eps kappa / mu at nu = 0.499999 on 1,122 dofs
    // (the direct solver's too), 26 eps kappa / mu at 0.4999 on 66,306 dofs: it grows with
    // the model. The inner solve goes below 100 eps kappa / mu by 100 sqrt(kappa / mu): a
    // residual of its pressure rows (scaled by D^1/2, operators/BulkSplit.hpp) reaches the
    // condensed residual multiplied by 11-14 sqrt(kappa / mu) (measured on Lame's cylinder,
    // 16 x 32 to 64 x 128 cells, nu = 0.4999 and 0.499999). The outer fixed point asks 10x
    // less, so that the floor's growth does not make it apply the inner solve again and again
    // for nothing (at 66,306 dofs and 100 eps kappa / mu it stagnated at 1.3e-10 against
    // 1.1e-10); it stops after 2 applications whatever: where the floor lies above even that
    // (the cantilever block of input/block.yaml, 20 x 4 x 4 cells, mixed, nu = 0.4999: 2.4e-8
    // after one, 2.2e-9 after two, 2.3e-9 and 2.2e-9 after three and five) more applications
    // gain nothing, and Newton's own test judges the residual (there: converged).
    const double nu = std::min(poissons_ratio, 0.4999999);
    const double kappa_over_mu = 2 * (1 + nu) / (3 * (1 - 2 * nu));
    const double floor = 100 * std::numeric_limits<double>::epsilon() * kappa_over_mu;
    plan.saddle_tolerance = std::max(tolerance, floor) / (100 * std::sqrt(kappa_over_mu));
    tolerance = std::max(tolerance, 10 * floor);
    if (method == "Fixed Point") plan.max_iterations = 2;
  }
  chosen.set("Convergence Tolerance", tolerance);
  chosen.set("Maximum Iterations", plan.max_iterations);
  if (method == "Block GMRES" || method == "Pseudo Block GMRES") chosen.set("Num Blocks", 100);
  // Named instead: the saddle point's inner GMRES is a preconditioner that changes from one
  // application to the next (it stops at a tolerance): flexible GMRES keeps the preconditioned
  // vectors, which also saves the application that forms the update.
  if (method == "Block GMRES" && plan.preconditioner == Plan::Preconditioner::bulk_split)
    chosen.set("Flexible Gmres", true);
  chosen.set("Verbosity", 1);  // errors only
  for (auto it = linear_solver.begin(); it != linear_solver.end(); ++it)
    if (linear_solver.name(it) != "Solver Type")
      chosen.setEntry(linear_solver.name(it), linear_solver.entry(it));
  plan.max_iterations = chosen.get<int>("Maximum Iterations");
  plan.tolerance = chosen.get<double>("Convergence Tolerance");

  switch (plan.preconditioner) {
    case Plan::Preconditioner::direct:
      // UMFPACK 1.3-1.9x and KLU2 2-20x slower here; Tacho crashed (measured, docs/implicit.md).
      plan.settings.set("solver", "MUMPS");
      break;
    case Plan::Preconditioner::multigrid:
    case Plan::Preconditioner::bulk_split:
      plan.settings = multigrid_defaults(dimension);
      break;
    case Plan::Preconditioner::auxiliary:
      plan.settings = auxiliary_defaults(dimension);
      break;
    case Plan::Preconditioner::ifpack2:
      plan.settings.set("Prec Type", "RILUK");
      plan.settings.set("fact: iluk level-of-fill", 2);
      break;
    case Plan::Preconditioner::none:
      break;
  }
  // Parameters of a default method go with it: a user who picks another smoother or Ifpack2
  // type must not inherit ILU's fill level (Ifpack2 rejects it; MueLu's Chebyshev crashed on it).
  const auto replaced = [&](const char* key) {
    return preconditioner.isParameter(key) &&
           preconditioner.get<std::string>(key) != plan.settings.get<std::string>(key);
  };
  if (plan.preconditioner == Plan::Preconditioner::multigrid ||
      plan.preconditioner == Plan::Preconditioner::auxiliary ||
      plan.preconditioner == Plan::Preconditioner::bulk_split) {
    if (replaced("smoother: type")) plan.settings.remove("smoother: params");
    if (replaced("coarse: type")) plan.settings.remove("coarse: params");
  }
  if (plan.preconditioner == Plan::Preconditioner::ifpack2 && replaced("Prec Type"))
    plan.settings.remove("fact: iluk level-of-fill");
  for (auto it = preconditioner.begin(); it != preconditioner.end(); ++it)
    if (preconditioner.name(it) != "Type")
      plan.settings.setEntry(preconditioner.name(it), preconditioner.entry(it));
  if (plan.preconditioner == Plan::Preconditioner::direct && ranks > 1 &&
      text(plan.settings, "solver", "MUMPS") != "MUMPS")
    plan.reason += ", gathered and factored on rank 0";
  return plan;
}

}  // namespace efg
