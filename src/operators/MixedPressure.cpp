#include "operators/MixedPressure.hpp"

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/Errors.hpp"
#include "tensor/Tensor.hpp"

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

// The cell's volumetric measure at d and its gradient rows g (dim per entry of the cell's row):
//   small strain: m = theta_c = b_c . d,  g_I = b_cI;
//   finite strain: F_c = I + sum_I d_I (x) b_cI (the cell-smoothed deformation gradient,
//   plane strain F_33 = 1), J_c = det F_c, m = ln J_c, g_I = F_c^-T b_cI  (d ln J / d d_I),
// with U(J) = kappa/2 (ln J)^2 the volumetric energy (its small-strain limit kappa/2 theta^2).
// Returns false when J_c <= 0.
struct CellState {
  double measure = 0, J = 1;
  std::vector<double> g;
};

// The overlap dofs of cell c's particles, dim per particle (its tangent's columns).
template <class Part>
void cell_columns(const Part& p, std::size_t c, int dim, std::vector<int>& cols) {
  cols.clear();
  for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k)
    for (int j = 0; j < dim; ++j) cols.push_back(p.node[k] * dim + j);
}

template <class Part, class View>
bool cell_state(const Part& p, std::size_t c, const View& u, int dim, CellState& st) {
  const auto udim = static_cast<std::size_t>(dim);
  const auto first = p.offsets[c], last = p.offsets[c + 1];
  st.g.assign((last - first) * udim, 0.0);
  if (!p.finite) {
    st.measure = cell_dilatation(p, c, u, dim);
    st.J = 1;
    std::copy(p.bbar.begin() + static_cast<std::ptrdiff_t>(first * udim),
              p.bbar.begin() + static_cast<std::ptrdiff_t>(last * udim), st.g.begin());
    return true;
  }
  double H[3][3] = {};
  for (auto k = first; k < last; ++k) {
    const auto n = static_cast<std::size_t>(p.node[k]);
    for (std::size_t i = 0; i < udim; ++i)
      for (std::size_t j = 0; j < udim; ++j) H[i][j] += u(n * udim + i, 0) * p.bbar[k * udim + j];
  }
  double Finv[3][3] = {}, j_minus_1 = 0;
  if (dim == 2) {
    double H2[2][2] = {{H[0][0], H[0][1]}, {H[1][0], H[1][1]}}, F2[2][2], I2[2][2];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) F2[i][j] = H2[i][j] + (i == j ? 1.0 : 0.0);
    j_minus_1 = physics::determinant_of_identity_plus_minus_one<2>(H2);
    st.J = 1.0 + j_minus_1;
    if (!(st.J > 0)) return false;
    physics::inverse<2>(F2, st.J, I2);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) Finv[i][j] = I2[i][j];
  } else {
    double F[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
    j_minus_1 = physics::determinant_of_identity_plus_minus_one<3>(H);
    st.J = 1.0 + j_minus_1;
    if (!(st.J > 0)) return false;
    physics::inverse<3>(F, st.J, Finv);
  }
  st.measure = std::log1p(j_minus_1);
  for (auto k = first; k < last; ++k)
    for (std::size_t i = 0; i < udim; ++i) {
      double v = 0;
      for (std::size_t l = 0; l < udim; ++l) v += Finv[l][i] * p.bbar[k * udim + l];
      st.g[(k - first) * udim + i] = v;
    }
  return true;
}

}  // namespace

void MixedPressure::report_inverted(const Part& p, std::size_t c) const {
  const auto& cells = model_.parts[p.model_part].cells;
  std::ostringstream o;
  o << "part '" << model_.parts[p.model_part].part->name << "': mixed u-p cell " << p.cell[c] + 1
    << " at (";
  for (int d = 0; d < dim_; ++d)
    o << (d ? ", " : "")
      << cells.centroid[c * static_cast<std::size_t>(dim_) + static_cast<std::size_t>(d)];
  o << ") inverted: det F <= 0 of its smoothed deformation gradient";
  throw NumericalError(o.str());
}

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
    {
      // The iterative path's split (operators/BulkSplit.hpp, BulkTangent.hpp).
      const double mu = law.elastic.mu;
      p.kappa0 = relieved_bulk_modulus(p.kappa, mu);
      p.kappa_excess = p.kappa - p.kappa0;
      p.schur = 1.0 + p.kappa_excess / (p.kappa0 + 4.0 * mu / 3.0);
    }
    p.groups = d.cells.group;
    const auto& groups = d.pressure_cells;
    for (std::size_t g = 0; g < groups.size(); ++g)  // cells ascend within a group
      p.group_id.push_back(static_cast<long long>(
          model.mesh.global_cell(static_cast<std::size_t>(groups.cells[groups.offsets[g]]))));
    p.finite = d.part->section.formulation != Formulation::small_strain;
    if (const auto rho = model.scene.find_material(d.part->material)->density) {
      p.density = *rho;
      p.wave_speed = std::sqrt((p.kappa + 4.0 * law.elastic.mu / 3.0) / p.density);
    }
    const double thickness = dim_ == 2 ? d.part->thickness : 1.0;
    for (double v : d.cells.volume) {
      p.volume.push_back(v * thickness);
      p.length.push_back(std::pow(v, 1.0 / dim_));
    }
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
  CellState st;
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      if (!cell_state(p, c, u, dim_, st)) report_inverted(p, c);
      const double s = p.volume[c] * p.kappa * st.measure;  // V_c U'(J) J
      for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k) {
        const auto n = static_cast<std::size_t>(p.node[k]);
        const auto e = k - p.offsets[c];
        for (std::size_t i = 0; i < udim; ++i) f(n * udim + i, 0) += s * st.g[e * udim + i];
      }
    }
}

void MixedPressure::add_tangent(const Vector& d_overlap, FEMatrix& K, BulkTangent bulk) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: mixed u-p cells"));
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto local = K.getLocalMatrixDevice();
  const auto udim = static_cast<std::size_t>(dim_);
  std::vector<int> cols;
  std::vector<double> vals;
  CellState st;
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      if (!cell_state(p, c, u, dim_, st)) report_inverted(p, c);
      const auto first = p.offsets[c], last = p.offsets[c + 1];
      const double s = p.volume[c] * p.kappa;
      const double rank_one = bulk == BulkTangent::full ? s : p.volume[c] * p.kappa0;
      // d(m g_Ii)/d d_Jj = g_Ii g_Jj - m g_Ij g_Ji (finite strain: d F^-T / dF; small: 0).
      const double sm = p.finite ? s * st.measure : 0.0;
      cell_columns(p, c, dim_, cols);
      vals.resize(cols.size());
      for (auto k = first; k < last; ++k)
        for (std::size_t i = 0; i < udim; ++i) {
          const auto a = (k - first) * udim;
          for (auto l = first; l < last; ++l)
            for (std::size_t j = 0; j < udim; ++j) {
              const auto b = (l - first) * udim;
              vals[b + j] = rank_one * st.g[a + i] * st.g[b + j] - sm * st.g[a + j] * st.g[b + i];
            }
          // Sorted rows (filled graph): binary search (SolidKernels.hpp, NodalTangentKernel).
          local.sumIntoValues(p.node[k] * dim_ + static_cast<int>(i), cols.data(),
                              static_cast<int>(cols.size()), vals.data(), true, false);
        }
    }
}

bool MixedPressure::has_bulk_excess() const {
  for (const auto& p : parts_)
    if (p.kappa_excess > 0) return true;
  return false;
}

std::size_t MixedPressure::cell_count() const {
  std::size_t n = 0;
  for (const auto& p : parts_) n += p.volume.size();
  return n;
}

void MixedPressure::bulk_excess_pressures(const Vector& x_overlap, double* q) const {
  const auto x = x_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& p : parts_) {
    const auto& g = excess_rows(p);
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      double theta = 0;  // the linearized measure: b_c . x (small strain), F_c^-T b_c . x
      for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k)
        for (std::size_t i = 0; i < udim; ++i)
          theta += g[k * udim + i] * x(static_cast<std::size_t>(p.node[k]) * udim + i, 0);
      *q++ = p.volume[c] * p.kappa_excess * theta;
    }
  }
}

void MixedPressure::add_cell_forces(const double* q, Vector& y_overlap) const {
  auto y = y_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& p : parts_) {
    const auto& g = excess_rows(p);
    for (std::size_t c = 0; c < p.volume.size(); ++c, ++q)
      for (auto k = p.offsets[c]; k < p.offsets[c + 1]; ++k) {
        const auto n = static_cast<std::size_t>(p.node[k]);
        for (std::size_t i = 0; i < udim; ++i) y(n * udim + i, 0) += *q * g[k * udim + i];
      }
  }
}

void MixedPressure::bulk_state(const Vector& d_overlap) const {
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  CellState st;
  for (const auto& p : parts_) {
    if (!p.finite) continue;  // small strain: b_c itself
    p.excess_g.resize(p.bbar.size());
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      if (!cell_state(p, c, u, dim_, st)) report_inverted(p, c);
      std::copy(st.g.begin(), st.g.end(),
                p.excess_g.begin() + static_cast<std::ptrdiff_t>(p.offsets[c] * udim));
    }
  }
}

void MixedPressure::bulk_weights(double* w) const {
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) *w++ = p.volume[c] * p.kappa_excess;
}

void MixedPressure::bulk_schur_diagonal(double* s) const {
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) *s++ = p.schur;
}

void MixedPressure::add_bulk_viscosity(const Vector& v_overlap, double linear, double quadratic,
                                       Vector& f_overlap) const {
  const auto v = v_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& p : parts_) {
    for (std::size_t c = 0; c < p.volume.size(); ++c) {
      const double rate = cell_dilatation(p, c, v, dim_);
      if (!(rate < 0)) continue;  // expanding cells carry none
      const double l = p.length[c];
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
  CellState st;
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c)
      if (cell_state(p, c, u, dim_, st))  // an inverted cell stores none (the force reports it)
        total += 0.5 * p.volume[c] * p.kappa * st.measure * st.measure;
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

std::vector<double> MixedPressure::cell_pressures(std::size_t part, const Vector& d_overlap) const {
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& p = parts_.at(static_cast<std::size_t>(index_.at(part)));
  std::vector<double> pressure(p.volume.size(), 0.0);
  CellState st;
  for (std::size_t c = 0; c < pressure.size(); ++c)
    if (cell_state(p, c, u, dim_, st)) pressure[c] = -p.kappa * st.measure / st.J;  // -U'(J)
  return pressure;
}

std::vector<double> MixedPressure::particle_pressures(const Vector& d_overlap) const {
  const auto& maps = model_.maps;
  // Columns: sum of V_c p_c and of V_c over the cells around each node, summed on the owners.
  Tpetra::MultiVector<> overlap(maps.overlap_nodes, 2), owned(maps.owned_nodes, 2);
  {
    auto o = overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto& mesh = model_.mesh;
    std::vector<LocalIndex> nodes;
    for (const auto& p : parts_) {
      const auto pressure = cell_pressures(p.model_part, d_overlap);
      const auto& groups = model_.parts[p.model_part].pressure_cells;
      const auto& cells = model_.parts[p.model_part].cells;
      for (std::size_t c = 0; c < pressure.size(); ++c) {
        // The nodes of the pressure cell's background cells, each once.
        nodes.clear();
        const auto g = cells.group[c];
        for (auto k = groups.offsets[g]; k < groups.offsets[g + 1]; ++k) {
          const auto [block, local] = mesh.locate_cell(groups.cells[k]);
          const auto npc = static_cast<std::size_t>(cell_node_count(block->type));
          nodes.insert(nodes.end(), &block->connectivity[local * npc],
                       &block->connectivity[local * npc] + npc);
        }
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        for (const auto node : nodes) {
          const auto lid = maps.overlap_nodes->getLocalElement(
              static_cast<GlobalOrdinal>(mesh.global_node(static_cast<std::size_t>(node))));
          if (lid == Teuchos::OrdinalTraits<int>::invalid())
            throw std::logic_error("mixed u-p: a cell's node is missing from the overlap map");
          o(static_cast<std::size_t>(lid), 0) += pressure[c] * p.volume[c];
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

namespace efg {

void MixedPressure::bulk_group_ids(long long* gid) const {
  for (const auto& p : parts_)
    for (std::size_t c = 0; c < p.volume.size(); ++c) *gid++ = p.group_id[p.groups[c]];
}

long long MixedPressure::bulk_group_id(std::size_t part, std::size_t group) const {
  return parts_[static_cast<std::size_t>(index_[part])].group_id[group];
}

double MixedPressure::bulk_reference(std::size_t part) const {
  return index_[part] < 0 ? 0.0 : parts_[static_cast<std::size_t>(index_[part])].kappa0;
}

}  // namespace efg
