#include "operators/CellInversion.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <limits>

namespace efg {
CellInversion::CellInversion(const Model& model)
    : dim_(model.mesh.dimension), comm_(model.maps.overlap_nodes->getComm()) {
  const auto& scene = model.scene;
  const auto& overlap = *model.maps.overlap_nodes;
  if (!model.mesh.surface.empty()) return;  // a shell surface's chart: no solid cells
  reference_.assign(overlap.getNodeNumElements() * static_cast<std::size_t>(dim_), 0.0);
  std::vector<bool> known(overlap.getNodeNumElements(), false);
  std::size_t first_cell = 0;
  for (const auto& block : model.mesh.blocks) {
    const auto cells = block.cell_count();
    const int nodes = cell_node_count(block.type);
    // The solid part that integrates over this block, if its material does not erode.
    std::optional<std::size_t> part;
    for (std::size_t p = 0; p < scene.parts.size(); ++p) {
      const auto& spec = scene.parts[p];
      if (spec.shell ||
          std::find(spec.blocks.begin(), spec.blocks.end(), block.name) == spec.blocks.end())
        continue;
      const auto* material = scene.find_material(spec.material);
      if (material && material->constants.count("failure_strain") &&
          material->constants.at("failure_strain") > 0)
        continue;  // eroding: its points leave the model
      part = p;
    }
    if (part && cell_dimension(block.type) == dim_)
      for (std::size_t c = 0; c < cells; ++c) {
        Cell cell{block.type, static_cast<long long>(model.mesh.global_cell(first_cell + c)),
                  {},         {},
                  *part,      {}};
        bool here = true;
        for (int k = 0; k < nodes; ++k) {
          const auto node =
              block.connectivity[c * static_cast<std::size_t>(nodes) + static_cast<std::size_t>(k)];
          const auto id = global_node_id(model, node);
          const int lid = overlap.getLocalElement(id);
          if (lid == Teuchos::OrdinalTraits<int>::invalid()) {
            here = false;  // a cell at this rank's edge: a rank holding all its nodes checks it
            break;
          }
          cell.overlap.push_back(lid);
          cell.node.push_back(static_cast<long long>(id));
          if (!known[static_cast<std::size_t>(lid)]) {
            known[static_cast<std::size_t>(lid)] = true;
            for (int i = 0; i < dim_; ++i)
              reference_[static_cast<std::size_t>(lid * dim_ + i)] =
                  model.mesh
                      .coordinates[static_cast<std::size_t>(node) * static_cast<std::size_t>(dim_) +
                                   static_cast<std::size_t>(i)];
          }
        }
        if (!here) continue;
        // Each corner's reference Jacobian (the ratio's denominator; every corner of a valid
        // cell is positive, MeshValidation).
        cell.corner_det = cell_corner_jacobians(cell.type, corners(cell, nullptr).data());
        cells_.push_back(std::move(cell));
      }
    first_cell += cells;
  }
  for (const auto& spec : scene.parts) part_names_.push_back(spec.name);
}

std::vector<double> CellInversion::corners(const Cell& cell, const double* d) const {
  std::vector<double> x;
  for (const int node : cell.overlap)
    for (int i = 0; i < dim_; ++i) {
      const auto r = static_cast<std::size_t>(node * dim_ + i);
      x.push_back(reference_[r] + (d ? d[r] : 0.0));
    }
  return x;
}

std::optional<CellInversion::Inverted> CellInversion::most_inverted(
    const Tpetra::Vector<>& d_overlap) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  Inverted mine;
  double worst = 0;  // the smallest ratio found, <= 0
  for (const auto& cell : cells_) {
    const auto now = cell_corner_jacobians(cell.type, corners(cell, d.data()).data());
    for (std::size_t c = 0; c < now.size(); ++c) {
      const double ratio = now[c] / cell.corner_det[c];
      if (ratio > worst || (ratio == worst && mine.cell >= 0 && cell.number + 1 >= mine.cell))
        continue;
      worst = ratio;
      mine.cell = cell.number + 1;
      mine.particle = cell.node[c] + 1;
      mine.part = part_names_[cell.part];
      mine.reference_det = cell.corner_det[c];
      mine.current_det = now[c];
    }
  }
  // The smallest ratio over the ranks, then the smallest cell number with it; its lowest rank
  // tells the rest.
  double all_worst = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, mine.cell >= 0 ? worst : 1.0,
                     Teuchos::outArg(all_worst));
  if (!(all_worst <= 0)) return std::nullopt;
  const long long none = std::numeric_limits<long long>::max();
  const long long here = mine.cell >= 0 && worst == all_worst ? mine.cell : none;
  long long first = none;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, here, Teuchos::outArg(first));
  const int rank = comm_->getRank(), size = comm_->getSize();
  int holder = here == first ? rank : size, lowest = size;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, holder, Teuchos::outArg(lowest));
  double values[2] = {mine.reference_det, mine.current_det};
  long long particle = mine.particle;
  Teuchos::broadcast(*comm_, lowest, 2, values);
  Teuchos::broadcast(*comm_, lowest, Teuchos::outArg(particle));
  int part_length = static_cast<int>(mine.part.size());
  Teuchos::broadcast(*comm_, lowest, Teuchos::outArg(part_length));
  std::string part(static_cast<std::size_t>(part_length), ' ');
  if (rank == lowest) part = mine.part;
  Teuchos::broadcast(*comm_, lowest, part_length, part.data());
  Inverted result;
  result.cell = first;
  result.particle = particle;
  result.part = part;
  result.reference_det = values[0];
  result.current_det = values[1];
  return result;
}

}  // namespace efg
