// Errors of a discrete solution against an exact one, integrated with a Gauss rule of order 5 on
// every background cell (independent of the scheme that integrated the weak form):
//   relative L2 displacement error  ||u^h - u|| / ||u||
//   relative energy-norm error      sqrt(a(u^h - u, u^h - u) / a(u, u)), a(v, v) = integral eps(v) : C : eps(v)
// with u^h = sum_I phi_I d_I and its direct gradient. Small-strain materials only (the energy
// norm of the linear elasticity tensor). Mixed u-p parts (operators/MixedPressure) measure the
// energy of their two fields, 2 mu dev e : dev e + (p^h - p)^2 / kappa, with p^h = -kappa theta_c
// the cell's pressure and p = -kappa div u the exact one (Brezzi & Fortin 1991: the norm that
// stays bounded as kappa grows), and the pressure's own relative L2 error.
#pragma once

#include "model/ExactSolutions.hpp"
#include "operators/MixedPressure.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

struct ErrorNorms {
  double l2_relative = 0;
  double energy_relative = 0;
  double max_nodal = 0;  ///< largest |u^h(X_J) - u(X_J)| over the particles
  /// ||p^h - p|| / ||p|| over the mixed u-p parts; negative when the model has none.
  double pressure_relative = -1;
};

/// Collective. `d_overlap`: generalized displacements on the overlap dofs.
ErrorNorms error_norms(const Model& model, const SolidOperator& op, const MixedPressure* mixed,
                       const Vector& d_overlap, const ExactSolution& exact);

/// u^h at a point inside part `part` (collective: every rank passes the same point; the owner of
/// the nearest particle answers).
std::array<double, 3> displacement_at(const Model& model, const SolidOperator& op,
                                      const Vector& d_overlap, const double* point);

}  // namespace efg
