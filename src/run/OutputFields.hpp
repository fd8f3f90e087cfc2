// The output columns of each named field and their values at the owned particles for a state:
// physical displacements u(X_J) = sum_I phi_I(X_J) d_I (not the generalized d_J), strains and
// Cauchy stresses from the particle gradients (SCNI: smoothed), von Mises.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"
#include "operators/MixedPressure.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

/// Exodus variable names of one field ("displacement" -> displacement_x, _y[, _z]).
std::vector<std::string> field_columns(const std::string& field, int dimension);

/// Fields with one value per background cell (Exodus element variables): cell_pressure.
bool is_cell_field(const std::string& field);
/// The scene's cell fields, in order.
std::vector<std::string> cell_columns(const std::vector<std::string>& fields);
/// The global indices of the cells this rank gives values for (the owned cells of mixed_up
/// parts), and the values of every cell column there (column after column).
std::vector<GlobalOrdinal> output_cells(const Model& model);
std::vector<std::vector<double>> cell_values(const Model& model, const MixedPressure* mixed,
                                             const Vector& d_overlap);

/// All nodal columns of the scene's output fields, in order.
std::vector<std::string> output_columns(const std::vector<std::string>& fields, int dimension);

/// Values of every output column at the owned particles (column after column), for generalized
/// displacements d, velocities v and accelerations a (overlap dofs; v and a may be null: zero).
/// Reactions are global variables per boundary condition (R_<name>_x, ...), not a nodal field.
/// `mixed`: the cell pressures of mixed_up parts (their stress is the law's deviatoric part plus
/// the particle's pressure). `nodal_volume`: the mesh's lumped nodal volumes
/// (nodal_volume_column), computed once per run by the caller (every mesh cell's Gauss volume:
/// recomputed at each record it was 7 % of a 130,896-particle explicit run of 21 records).
std::vector<std::vector<double>> state_columns(const Model& model, const SolidOperator& op,
                                               const Vector& d_overlap,
                                               const Vector* v_overlap = nullptr,
                                               const Vector* a_overlap = nullptr,
                                               const MixedPressure* mixed = nullptr,
                                               const std::vector<double>& nodal_volume = {});

/// The lumped nodal volumes of the mesh when the scene writes the nodal_volume field, else none.
std::vector<double> nodal_volume_column(const Model& model);

}  // namespace efg
