// The output columns of each named field and their values at the owned particles for a state:
// physical displacements u(X_J) = sum_I phi_I(X_J) d_I (not the generalized d_J), strains and
// Cauchy stresses from the particle gradients (SCNI: smoothed), von Mises, reactions.
#pragma once

#include <string>
#include <vector>

#include "operators/SolidOperator.hpp"
#include "run/Model.hpp"

namespace efg {

/// Exodus variable names of one field ("displacement" -> displacement_x, _y[, _z]).
std::vector<std::string> field_columns(const std::string& field, int dimension);

/// All columns of the scene's output fields, in order.
std::vector<std::string> output_columns(const std::vector<std::string>& fields, int dimension);

/// Values of every output column at the owned particles (column after column), for generalized
/// displacements d (overlap dofs) and constraint forces (owned dofs; null: zero). Velocities and
/// accelerations are zero in a static state.
std::vector<std::vector<double>> state_columns(const Model& model, const SolidOperator& op, const Vector& d_overlap,
                                               const Vector* reaction_owned);

}  // namespace efg
