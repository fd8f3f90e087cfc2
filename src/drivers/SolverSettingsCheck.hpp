// An implicit stage's solver maps (nonlinear_solver, linear_solver, preconditioner) checked before
// anything runs, so that `efg check` and `efg run` reject the same settings with exit 2 and no
// output touched (issue 13 item 12, issue 14 item 11). The Trilinos packages validate their own
// lists where they can:
//   linear_solver   Stratimikos checks 'Solver Type'; the other keys must be parameters of that
//                   Belos solver (its getValidParameters(), which Belos itself does not enforce);
//   nonlinear_solver NOX is built and run on a one-unknown problem (NOX::LAPACK); every key the
//                   user gave must have been read by NOX (Teuchos marks read parameters as used),
//                   so 'Line Serch' is an error instead of being ignored;
//   preconditioner  the preconditioner of the stage's plan is built on a small SPD matrix
//                   (a 1D Laplacian per displacement component): MueLu and Ifpack2 validate
//                   their lists there, a bogus 'Prec Type' fails there.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <string>

namespace efg {

/// `stage` the resolved stage, `written` the stage as written (for line numbers), `path` its key
/// path ("stages[0]"). `dofs` the model's displacement dofs and `poissons_ratio` its largest
/// (the automatic choice depends on both). Throws InputError "FILE:LINE:COL: PATH.KEY: what is
/// wrong".
void check_solver_settings(const YAML::Node& stage, const YAML::Node& written,
                           const std::string& file, const std::string& path, std::int64_t dofs,
                           int dimension, double poissons_ratio = 0.0);

}  // namespace efg
