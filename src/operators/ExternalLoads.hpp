// External forces on the generalized particle dofs: tractions and pressures on side sets
// (f_I = integral of phi_I t over the side), nodal forces shared over a node set (applied at the
// node's position: f_I = phi_I(X_n) F / N), body forces (f_I = sum_q w_q phi_I(x_q) b). Values
// may be expressions of x, y, z, t (scene/ScalarField). A load constant in time is assembled once
// for a unit factor and scaled by its curve; a load varying in time keeps its points (position,
// weight, normal, shape-function row) and evaluates its expressions there at every assembly.
#pragma once

#include <Tpetra_Export.hpp>

#include <string>
#include <vector>

#include "discretization/IntegrationPoints.hpp"
#include "model/Curves.hpp"
#include "model/ExactSolutions.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

class ExternalLoads {
 public:
  /// `exact` is needed only by loads taken from the exact solution.
  ExternalLoads(const Model& model, const SolidOperator& op, const ExactSolution* exact);

  /// f_owned = sum over the loads acting in factor.stage() of factor(curve) * F_load(t =
  /// factor.time()).
  void assemble(const LoadFactor& factor, Vector& f_owned) const;
  /// Whether every load acting in `stage` is constant in time there (no curve, no expression of
  /// t): assemble then gives the same bits at every time of the stage (for a factor whose value
  /// without a curve is fixed, as the explicit driver's), and one assembly serves its steps.
  bool constant_in(const std::string& stage) const;

  /// Points of loads whose values vary in time (evaluated at every assembly); for bench/.
  std::size_t timed_point_count() const;

  /// Where a load acts: points with a weight (and a normal on surfaces) and their rows of phi_I.
  struct Points {
    std::vector<std::array<double, 3>> x, normal;
    std::vector<double> weight;
    std::vector<std::size_t> part;  ///< per point
    CsrTable rows;                  ///< phi_I(x_p), columns: overlap nodes
  };

 private:
  struct Load {
    const LoadSpec* spec;
    Teuchos::RCP<Vector> force;  // owned dofs, unit factor (loads constant in time)
    Points points;               // loads varying in time
  };
  std::vector<Load> loads_;
  const ExactSolution* exact_;
  int dim_;
  Teuchos::RCP<const Map> overlap_, owned_;
  Teuchos::RCP<const Tpetra::Export<>> to_owned_;
  Teuchos::RCP<Vector> timed_overlap_, timed_owned_;  // loads varying in time (none: null)
};

/// Index of the scene part whose blocks contain block `name`, or -1.
int part_of_block(const Scene& scene, const std::string& name);

}  // namespace efg
