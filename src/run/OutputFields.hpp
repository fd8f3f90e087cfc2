// The output columns of each named field and the values of the initial (undeformed, at rest)
// state. Drivers fill the same columns from their state as they land.
#pragma once

#include <string>
#include <vector>

#include "run/Model.hpp"

namespace efg {

/// Exodus variable names of one field ("displacement" -> displacement_x, _y[, _z]).
std::vector<std::string> field_columns(const std::string& field, int dimension);

/// All columns of the scene's output fields, in order.
std::vector<std::string> output_columns(const std::vector<std::string>& fields, int dimension);

/// Owned-particle values of the initial state, column-major (column after column), for the
/// columns of output_columns(). Kinematic and stress fields are zero at rest; nodal_volume and
/// owner_rank are what the model holds.
std::vector<std::vector<double>> initial_state_columns(const Model& model, const std::vector<double>& nodal_volume);

}  // namespace efg
