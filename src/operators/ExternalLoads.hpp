// External forces on the generalized particle dofs: tractions and pressures on side sets
// (f_I = integral of phi_I t over the side), nodal forces shared over a node set (applied at the
// node's position: f_I = phi_I(X_n) F / N), body forces (f_I = sum_q w_q phi_I(x_q) b). Each
// load is assembled once for a unit factor; a stage scales it by its curve.
#pragma once

#include <string>
#include <vector>

#include "operators/SolidOperator.hpp"
#include "model/Curves.hpp"
#include "model/ExactSolutions.hpp"

namespace efg {

class ExternalLoads {
 public:
  /// `exact` is needed only by loads taken from the exact solution.
  ExternalLoads(const Model& model, const SolidOperator& op, const ExactSolution* exact);

  /// f_owned = sum over loads of factor(curve) * F_load.
  void assemble(const LoadFactor& factor, Vector& f_owned) const;

 private:
  struct Load {
    std::string curve;
    Teuchos::RCP<Vector> force;  // owned dofs, unit factor
  };
  std::vector<Load> loads_;
};

/// Index of the scene part whose blocks contain block `name`, or -1.
int part_of_block(const Scene& scene, const std::string& name);

}  // namespace efg
