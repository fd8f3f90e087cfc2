#include "operators/AuxiliaryStiffness.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <algorithm>
#include <utility>

#include "model/MaterialLaws.hpp"
#include "operators/CellStiffness.hpp"

namespace efg {
namespace {

using GO = Tpetra::CrsMatrix<>::global_ordinal_type;
using Entries = std::vector<std::pair<GO, double>>;  // (column gid, value), one row

// Sorts a row by column and sums repeated columns.
void merge(Entries& row) {
  std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t out = 0;
  for (std::size_t k = 0; k < row.size(); ++k) {
    if (out > 0 && row[out - 1].first == row[k].first)
      row[out - 1].second += row[k].second;
    else
      row[out++] = row[k];
  }
  row.resize(out);
}

}  // namespace

std::string auxiliary_space_misfit(const Scene& scene) {
  const auto impossible = auxiliary_space_impossible(scene);
  if (!impossible.empty()) return impossible;
  for (const auto& part : scene.parts) {
    const auto integration = part.section.integration;
    if (integration != Integration::gauss && integration != Integration::scni_subcells)
      return "part '" + part.name + "' is integrated by " +
             (integration == Integration::scni ? "scni" : "nodal") +
             " (only gauss and scni_subcells are free of spurious low-energy modes)";
  }
  return "";
}

std::string auxiliary_space_impossible(const Scene& scene) {
  for (const auto& part : scene.parts) {
    if (part.shell) return "part '" + part.name + "' is a shell";
    if (part.formulation != PartFormulation::displacement)
      return "part '" + part.name + "' is mixed u-p";
    const auto* material = scene.find_material(part.material);
    if (!material || !material->constants.count("youngs_modulus") ||
        !material->constants.count("poissons_ratio"))
      return "part '" + part.name + "' has no elastic moduli";
  }
  for (const auto& bc : scene.boundary_conditions)
    if (!bc.method.empty() && bc.method != "transformation")
      return "condition '" + bc.name + "' is imposed by " + bc.method;
  if (!scene.contacts.empty()) return "the scene has contacts";
  if (!scene.rigid_walls.empty()) return "the scene has rigid walls";
  return "";
}

Teuchos::RCP<Tpetra::CrsMatrix<>> auxiliary_stiffness(const Model& model,
                                                      const Tpetra::CrsMatrix<>& K,
                                                      const std::vector<int>& copied_rows) {
  const auto& mesh = model.mesh;
  const int dim = mesh.dimension;
  const auto& rows = *model.maps.owned_dofs;
  const auto n_rows = rows.getNodeNumElements();
  const int rank = model.partition.rank;
  std::vector<Entries> entries(n_rows);
  std::vector<double> x, ke;
  // Each rank assembles the owned rows of every cell that has an owned node (the mesh is on
  // every rank): no communication.
  for (const auto& part : model.scene.parts) {
    const auto law = material_law(model.scene, part, dim);
    const double scale = dim == 2 ? part.thickness : 1.0;
    for (const auto& name : part.blocks) {
      const auto* block = mesh.find_block(name);
      if (!block) continue;
      const auto n = static_cast<std::size_t>(cell_node_count(block->type));
      const auto size = n * static_cast<std::size_t>(dim);
      for (std::size_t c = 0; c < block->cell_count(); ++c) {
        const auto* nodes = &block->connectivity[c * n];
        bool mine = false;
        for (std::size_t a = 0; a < n; ++a)
          mine = mine || model.partition.owner[static_cast<std::size_t>(nodes[a])] == rank;
        if (!mine) continue;
        x.clear();
        for (std::size_t a = 0; a < n; ++a)
          for (int d = 0; d < dim; ++d)
            x.push_back(mesh.coordinates[static_cast<std::size_t>(nodes[a] * dim + d)]);
        cell_stiffness(block->type, x.data(), law.elastic.lambda, law.elastic.mu, scale, ke);
        for (std::size_t a = 0; a < n; ++a) {
          if (model.partition.owner[static_cast<std::size_t>(nodes[a])] != rank) continue;
          for (int i = 0; i < dim; ++i) {
            const auto row = rows.getLocalElement(
                static_cast<GO>(mesh.global_node(static_cast<std::size_t>(nodes[a]))) * dim + i);
            if (row == Teuchos::OrdinalTraits<int>::invalid()) continue;  // not a particle
            auto& out = entries[static_cast<std::size_t>(row)];
            const auto* k =
                &ke[(a * static_cast<std::size_t>(dim) + static_cast<std::size_t>(i)) * size];
            for (std::size_t b = 0; b < n; ++b)
              for (int j = 0; j < dim; ++j)
                out.emplace_back(
                    static_cast<GO>(mesh.global_node(static_cast<std::size_t>(nodes[b]))) * dim + j,
                    k[b * static_cast<std::size_t>(dim) + static_cast<std::size_t>(j)]);
          }
        }
      }
    }
  }
  // The constrained dofs are eliminated symmetrically: their rows and columns dropped, the
  // diagonal K's (the constraint row's own coefficient), so the matrix stays symmetric positive
  // definite and smoothed aggregation with Chebyshev smoothing applies as to any elasticity
  // matrix (copying K's collocated rows instead made it nonsymmetric and the multigrid a poor
  // inverse: 185 -> 500+ GMRES iterations on the cantilever block from 1,575 to 9,963 dofs,
  // against 19-22 with the exact inverse of this matrix). Rows no cell reached take K's row.
  std::vector<char> constrained(n_rows, 0);
  for (int r : copied_rows) constrained[static_cast<std::size_t>(r)] = 1;
  std::vector<GO> constrained_ids;
  for (std::size_t r = 0; r < n_rows; ++r)
    if (constrained[r]) constrained_ids.push_back(rows.getGlobalElement(static_cast<int>(r)));
  // every rank's constrained dofs: a column may belong to another rank's constrained row
  {
    const auto comm = rows.getComm();
    int mine = static_cast<int>(constrained_ids.size());
    std::vector<int> counts(static_cast<std::size_t>(comm->getSize()));
    Teuchos::gatherAll(*comm, 1, &mine, comm->getSize(), counts.data());
    std::vector<GO> all;
    for (int p = 0; p < comm->getSize(); ++p) {
      std::vector<GO> part(static_cast<std::size_t>(counts[static_cast<std::size_t>(p)]));
      if (p == comm->getRank()) part = constrained_ids;
      if (!part.empty()) Teuchos::broadcast(*comm, p, static_cast<int>(part.size()), part.data());
      all.insert(all.end(), part.begin(), part.end());
    }
    std::sort(all.begin(), all.end());
    constrained_ids.swap(all);
  }
  const auto is_constrained = [&](GO id) {
    return std::binary_search(constrained_ids.begin(), constrained_ids.end(), id);
  };
  const auto& k_columns = *K.getColMap();
  Tpetra::CrsMatrix<>::local_inds_host_view_type k_cols;
  Tpetra::CrsMatrix<>::values_host_view_type k_vals;
  for (std::size_t r = 0; r < n_rows; ++r) {
    const GO id = rows.getGlobalElement(static_cast<int>(r));
    const auto k_row = K.getRowMap()->getLocalElement(id);
    if (constrained[r] || entries[r].empty()) {
      K.getLocalRowView(k_row, k_cols, k_vals);
      entries[r].clear();
      for (std::size_t e = 0; e < k_cols.extent(0); ++e) {
        const GO column = k_columns.getGlobalElement(k_cols(e));
        if (!constrained[r] || column == id) entries[r].emplace_back(column, k_vals(e));
      }
      continue;
    }
    entries[r].erase(std::remove_if(entries[r].begin(), entries[r].end(),
                                    [&](const auto& e) { return is_constrained(e.first); }),
                     entries[r].end());
  }
  // Column map: the owned dofs first (as the row map), then the others ascending.
  std::vector<GO> others;
  for (auto& row : entries) {
    merge(row);
    for (const auto& e : row)
      if (!rows.isNodeGlobalElement(e.first)) others.push_back(e.first);
  }
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  std::vector<GO> column_ids(rows.getNodeElementList().begin(), rows.getNodeElementList().end());
  column_ids.insert(column_ids.end(), others.begin(), others.end());
  auto column_map = Teuchos::rcp(new Tpetra::Map<>(
      Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), column_ids, 0, rows.getComm()));
  std::size_t nnz = 0;
  for (const auto& row : entries) nnz += row.size();
  Teuchos::ArrayRCP<std::size_t> pointers(n_rows + 1);
  Teuchos::ArrayRCP<int> columns(nnz);
  Teuchos::ArrayRCP<double> values(nnz);
  std::size_t at = 0;
  pointers[0] = 0;
  for (std::size_t r = 0; r < n_rows; ++r) {
    std::vector<std::pair<int, double>> local;
    local.reserve(entries[r].size());
    for (const auto& e : entries[r])
      local.emplace_back(column_map->getLocalElement(e.first), e.second);
    std::sort(local.begin(), local.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& e : local) {
      columns[at] = e.first;
      values[at++] = e.second;
    }
    pointers[r + 1] = at;
    Entries().swap(entries[r]);
  }
  auto A = Teuchos::rcp(
      new Tpetra::CrsMatrix<>(model.maps.owned_dofs, column_map, pointers, columns, values));
  A->fillComplete(model.maps.owned_dofs, model.maps.owned_dofs);
  return A;
}

}  // namespace efg
