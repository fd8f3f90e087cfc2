#include "run/OutputFields.hpp"

#include <stdexcept>

#include "io/ExodusWriter.hpp"

namespace efg {

std::vector<std::string> field_columns(const std::string& field, int dimension) {
  if (field == "displacement" || field == "velocity" || field == "acceleration" || field == "reaction")
    return vector_component_names(field, dimension);
  if (field == "stress" || field == "strain") {
    // Symmetric tensors; zz is kept in 2D (plane strain stress, plane stress strain).
    if (dimension == 2) return {field + "_xx", field + "_yy", field + "_zz", field + "_xy"};
    return {field + "_xx", field + "_yy", field + "_zz", field + "_xy", field + "_yz", field + "_zx"};
  }
  if (field == "von_mises" || field == "nodal_volume" || field == "owner_rank") return {field};
  throw std::logic_error("no output columns for field '" + field + "'");
}

std::vector<std::string> output_columns(const std::vector<std::string>& fields, int dimension) {
  std::vector<std::string> columns;
  for (const auto& f : fields) {
    const auto c = field_columns(f, dimension);
    columns.insert(columns.end(), c.begin(), c.end());
  }
  return columns;
}

std::vector<std::vector<double>> initial_state_columns(const Model& model, const std::vector<double>& nodal_volume) {
  const auto& owned = model.partition.owned;
  std::vector<std::vector<double>> columns;
  for (const auto& field : model.scene.output.fields)
    for (std::size_t c = 0; c < field_columns(field, model.mesh.dimension).size(); ++c) {
      std::vector<double> values(owned.size(), 0.0);
      for (std::size_t i = 0; i < owned.size(); ++i) {
        const auto node = static_cast<std::size_t>(owned[i]);
        if (field == "nodal_volume") values[i] = nodal_volume[node];
        if (field == "owner_rank") values[i] = model.partition.rank;
      }
      columns.push_back(std::move(values));
    }
  return columns;
}

}  // namespace efg
