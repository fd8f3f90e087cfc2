#include "operators/MixedPressure.hpp"

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cmath>
#include <stdexcept>

namespace efg {
namespace {

// theta_c = sum_I b_cI . d_I over the cell's row.
template <class Part, class View>
double cell_dilatation(const Part& p, std::size_t c, const View& u, int dim) {
  const auto udim = static_cast<std::size_t>(dim);
  double theta = 0;
  for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k) {
    const auto n = static_cast<std::size_t>(p.node[k]);
    for (std::size_t i = 0; i < udim; ++i) theta += p.bbar[k * udim + i] * u(n * udim + i, 0);
  }
  return theta;
}

}  // namespace

std::unique_ptr<MixedPressure> MixedPressure::build(const Model& model,
                                                    const SolidOperator& solid) {
  for (const auto& d : model.parts)
    if (d.part->formulation == PartFormulation::mixed_up)
      return std::make_unique<MixedPressure>(model, solid);
  return nullptr;
}

MixedPressure::MixedPressure(const Model& model, const SolidOperator& solid)
    : model_(model), dim_(model.mesh.dimension), index_(model.parts.size(), -1) {
  for (std::size_t m = 0; m < model.parts.size(); ++m) {
    const auto& d = model.parts[m];
    if (d.part->formulation != PartFormulation::mixed_up) continue;
    const auto& law = solid.history().part(m).law;
    if (!law.mixed()) throw std::logic_error("mixed_up part without a bulk modulus");
    Part p;
    p.model_part = m;
    p.kappa = law.bulk_modulus;
    if (const auto rho = model.scene.find_material(d.part->material)->density) {
      p.density = *rho;
      p.wave_speed = std::sqrt((p.kappa + 4.0 * law.elastic.mu / 3.0) / p.density);
    }
    const double thickness = dim_ == 2 ? d.part->thickness : 1.0;
    for (double v : d.cells.volume) p.volume.push_back(v * thickness);
    p.offsets = d.cells.gradients.offsets;
    p.bbar = d.cells.gradients.values;
    p.cell = d.cells.cell;
    const auto& overlap = solid.overlap_node(m);
    for (auto particle : d.cells.gradients.particles)
      p.node.push_back(overlap[static_cast<std::size_t>(particle)]);
    index_[m] = static_cast<int>(parts_.size());
    parts_.push_back(std::move(p));
  }
}

double MixedPressure::bulk_modulus(std::size_t part) const {
  return index_[part] < 0 ? 0.0 : parts_[static_cast<std::size_t>(index_[part])].kappa;
}

void MixedPressure::add_couplings(CouplingGraph& graph) const {
  for (const auto& p : parts_)
    for (std::size_t c = 0; c + 1 < p.offsets.size(); ++c)
      graph.add_clique(p.node.data() + p.offsets[c], p.offsets[c + 1] - p.offsets[c]);
}

void MixedPressure::add_internal_force(const Vector& d_overlap, Vector& f_overlap) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: mixed u-p cells"));
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      const double s = p.volume[c] * p.kappa * cell_dilatation(p, c, u, dim_);
      for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k) {
        const auto n = static_cast<std::size_t>(p.node[k]);
        for (std::size_t i = 0; i < udim; ++i) f(n * udim + i, 0) += s * p.bbar[k * udim + i];
      }
    }
}

void MixedPressure::apply(const Vector& x_overlap, Vector& y_overlap) const {
  add_internal_force(x_overlap, y_overlap);  // linear in d: K_vol x = f_vol(x)
}

void MixedPressure::add_tangent(FEMatrix& K) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: mixed u-p cells"));
  auto local = K.getLocalMatrixDevice();
  const auto udim = static_cast<std::size_t>(dim_);
  std::vector<int> cols;
  std::vector<double> vals;
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      const auto first = p.offsets[c], last = p.offsets[c + 1];
      const double s = p.volume[c] * p.kappa;
      cols.clear();
      for (auto k = first; k < last; ++k)
        for (std::size_t j = 0; j < udim; ++j)
          cols.push_back(p.node[k] * dim_ + static_cast<int>(j));
      vals.resize(cols.size());
      for (auto k = first; k < last; ++k)
        for (std::size_t i = 0; i < udim; ++i) {
          const double bi = s * p.bbar[k * udim + i];
          for (auto l = first; l < last; ++l)
            for (std::size_t j = 0; j < udim; ++j)
              vals[(l - first) * udim + j] = bi * p.bbar[l * udim + j];
          local.sumIntoValues(p.node[k] * dim_ + static_cast<int>(i), cols.data(),
                              static_cast<int>(cols.size()), vals.data(), false, false);
        }
    }
}

void MixedPressure::add_bulk_viscosity(const Vector& v_overlap, double linear, double quadratic,
                                       Vector& f_overlap) const {
  const auto v = v_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& p : parts_) {
    const double thickness = dim_ == 2 ? model_.parts[p.model_part].part->thickness : 1.0;
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      const double rate = cell_dilatation(p, c, v, dim_);
      if (!(rate < 0)) continue;  // expanding cells carry none
      const double l = std::pow(p.volume[c] / thickness, 1.0 / dim_);
      const double q = p.density * l * (quadratic * l * rate * rate - linear * p.wave_speed * rate);
      const double s = -p.volume[c] * q;
      for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k) {
        const auto n = static_cast<std::size_t>(p.node[k]);
        for (std::size_t i = 0; i < udim; ++i) f(n * udim + i, 0) += s * p.bbar[k * udim + i];
      }
    }
  }
}

double MixedPressure::strain_energy(const Vector& d_overlap) const {
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double total = 0;
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      const double theta = cell_dilatation(p, c, u, dim_);
      total += 0.5 * p.volume[c] * p.kappa * theta * theta;
    }
  return total;
}

std::vector<double> MixedPressure::cell_dilatations(std::size_t part,
                                                    const Vector& d_overlap) const {
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& p = parts_.at(static_cast<std::size_t>(index_.at(part)));
  std::vector<double> theta(p.volume.size());
  for (std::size_t c = 0; c < theta.size(); ++c) theta[c] = cell_dilatation(p, c, u, dim_);
  return theta;
}

std::vector<double> MixedPressure::particle_pressures(const Vector& d_overlap) const {
  const auto& maps = model_.maps;
  // Columns: sum of V_c p_c and of V_c over the cells around each node, summed on the owners.
  Tpetra::MultiVector<> overlap(maps.overlap_nodes, 2), owned(maps.owned_nodes, 2);
  {
    auto o = overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto& mesh = model_.mesh;
    for (const auto& p : parts_) {
      const auto theta = cell_dilatations(p.model_part, d_overlap);
      for (std::size_t c = 0; c < theta.size(); ++c) {
        const auto [block, local] = mesh.locate_cell(p.cell[c]);
        const auto npc = static_cast<std::size_t>(cell_node_count(block->type));
        for (std::size_t a = 0; a < npc; ++a) {
          const auto gid = static_cast<GlobalOrdinal>(block->connectivity[local * npc + a]);
          const auto lid = maps.overlap_nodes->getLocalElement(gid);
          if (lid == Teuchos::OrdinalTraits<int>::invalid())
            throw std::logic_error("mixed u-p: a cell's node is missing from the overlap map");
          o(static_cast<std::size_t>(lid), 0) += -p.kappa * theta[c] * p.volume[c];
          o(static_cast<std::size_t>(lid), 1) += p.volume[c];
        }
      }
    }
  }
  Tpetra::Export<> exporter(maps.overlap_nodes, maps.owned_nodes);
  owned.doExport(overlap, exporter, Tpetra::ADD);
  const auto w = owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> pressure(w.extent(0), 0.0);
  for (std::size_t n = 0; n < pressure.size(); ++n)
    if (w(n, 1) > 0) pressure[n] = w(n, 0) / w(n, 1);
  return pressure;
}

std::vector<double> MixedPressure::overlap_pressures(const Vector& d_overlap) const {
  const auto& maps = model_.maps;
  const auto owned_values = particle_pressures(d_overlap);
  Tpetra::Vector<> owned(maps.owned_nodes), overlap(maps.overlap_nodes);
  {
    auto o = owned.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t n = 0; n < owned_values.size(); ++n) o(n, 0) = owned_values[n];
  }
  overlap.doImport(owned, Tpetra::Import<>(maps.owned_nodes, maps.overlap_nodes), Tpetra::INSERT);
  const auto v = overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  return std::vector<double>(v.data(), v.data() + v.extent(0));
}

}  // namespace efg
