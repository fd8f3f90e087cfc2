#include "operators/EssentialConditions.hpp"

#include "model/GradedMaterials.hpp"
#include "model/Model.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "discretization/SmoothingFacets.hpp"
#include "mesh/SideMeasures.hpp"
#include "operators/BoundaryCellPressure.hpp"
#include "operators/SideQuadrature.hpp"

namespace efg {
namespace {

int method_of(const std::string& m) {
  return m == "transformation" ? 0 : m == "nitsche" ? 1 : 2;
}

// The particle spacing h of an owned particle of a part (support over dilation, largest direction).
double spacing_of(const PartDiscretization& d, std::size_t particle) {
  double h = 0;
  const auto& dil = d.part->section.dilation;
  for (int k = 0; k < d.cloud.dimension; ++k)
    h = std::max(
        h, d.cloud.a(particle)[k] / (dil.size() == 1 ? dil[0] : dil[static_cast<std::size_t>(k)]));
  return h;
}

}  // namespace

EssentialConditions::EssentialConditions(const Model& model, const SolidOperator& op,
                                         const ExactSolution* exact, Selection selection,
                                         const std::string& stage)
    : dim_(model.mesh.dimension),
      conditions_(model.scene.boundary_conditions.size()),
      overlap_dofs_(model.maps.overlap_dofs) {
  timed_.resize(conditions_);
  states_ = &op.history();
  double largest_modulus = 0;
  for (const auto& m : model.scene.materials)
    largest_modulus = std::max(largest_modulus, m.constants.at("youngs_modulus"));
  // A mixed part's traction carries kappa theta: the penalties and scales follow the stiffer of E
  // and 3 kappa = E / (1 - 2 nu) there (Nitsche's stability needs beta above it).
  for (std::size_t p = 0; p < model.parts.size(); ++p)
    largest_modulus = std::max(largest_modulus, 3 * op.history().part(p).law.bulk_modulus);
  row_modulus_ = largest_modulus;
  for (std::size_t c = 0; c < model.scene.boundary_conditions.size(); ++c) {
    const auto& bc = model.scene.boundary_conditions[c];
    if (bc.type != "displacement") continue;   // velocity conditions belong to the explicit driver
    if (!bc.stages.includes(stage)) continue;  // not active in this stage: no terms, no reaction
    Setup setup;
    setup.index = c;
    setup.bc = &bc;
    setup.method = method_of(bc.method);
    if (selection == Selection::weak_only && setup.method == 0) continue;
    if (selection == Selection::transformation_only && setup.method != 0) continue;
    setup.beta_factor = bc.penalty.value_or(setup.method == 1 ? 100.0 : 1e4) * largest_modulus;
    setup.modulus = largest_modulus;
    for (std::size_t k = 0; k < 3; ++k)
      setup.mask[k] = bc.components[k].has_value() || bc.from_exact[k];
    setup.prescribed = [&bc, exact](const double* X, std::size_t k, double t) {
      if (!bc.from_exact[k]) return bc.components[k] ? bc.components[k]->at(X, t) : 0.0;
      double u[3] = {0, 0, 0};
      exact->displacement(X, u);
      return u[k];
    };
    for (const auto& component : bc.components)
      if (component && component->uses_time()) timed_[c] = setup.prescribed;
    if (setup.method == 0 && selection == Selection::all) add_collocated_nodes(model, op, setup);
    const std::size_t history_begin = committed_.size();
    long long sides_found = 0;  // over the ranks: each integrates its own
    Teuchos::reduceAll(*model.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM,
                       add_boundary_points(model, op, setup), Teuchos::outArg(sides_found));
    if (committed_.size() > history_begin)
      history_ranges_.push_back({c, history_begin, committed_.size()});
    if (setup.method != 0 && sides_found == 0)
      throw InputError(model.scene.file + ": boundary condition '" + bc.name + "': node set '" +
                       bc.node_set + "' covers no side of a meshfree part, which method " +
                       bc.method +
                       " integrates over; use method transformation for point constraints");
  }
  build_reaction_weights(model);
  shared_ = &op.history();
  load_history();
}

void EssentialConditions::load_history() {
  for (const auto& [c, begin, end] : history_ranges_) {
    auto& stored = shared_->boundary_points(c);
    const auto b = committed_.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto e = committed_.begin() + static_cast<std::ptrdiff_t>(end);
    if (stored.size() == end - begin)
      std::copy(stored.begin(), stored.end(), b);
    else
      stored.assign(b, e);  // the first set of conditions to see c: the initial state
  }
  trial_ = committed_;
}

void EssentialConditions::commit_history() {
  committed_ = trial_;
  for (const auto& [c, begin, end] : history_ranges_)
    shared_->boundary_points(c).assign(committed_.begin() + static_cast<std::ptrdiff_t>(begin),
                                       committed_.begin() + static_cast<std::ptrdiff_t>(end));
}

// Transformation: one collocated constraint per owned node of the set and component.
void EssentialConditions::add_collocated_nodes(const Model& model, const SolidOperator& op,
                                               const Setup& setup) {
  const auto& bc = *setup.bc;
  const auto owned_rows = model.maps.owned_dofs;
  for (auto node : model.mesh.find_node_set(bc.node_set)->nodes) {
    if (model.partition.owner[static_cast<std::size_t>(node)] != model.partition.rank) continue;
    bool found = false;
    for (std::size_t p = 0; p < model.parts.size() && !found; ++p) {
      const auto& d = model.parts[p];
      const auto end = d.cloud.mesh_node.begin() + static_cast<std::ptrdiff_t>(d.cloud.owned_count);
      const auto it = std::find(d.cloud.mesh_node.begin(), end, node);
      if (it == end) continue;
      found = true;
      const auto row = static_cast<std::size_t>(it - d.cloud.mesh_node.begin());
      const double s = setup.modulus * std::pow(spacing_of(d, row), dim_ - 2) *
                       (dim_ == 2 ? d.part->thickness : 1.0);
      for (int i = 0; i < dim_; ++i) {
        if (!setup.mask[static_cast<std::size_t>(i)]) continue;
        NodeConstraint nc;
        nc.condition = setup.index;
        nc.owned_row = owned_rows->getLocalElement(global_node_id(model, node) * dim_ + i);
        nc.component = i;
        nc.scale = s;
        for (int k = 0; k < dim_; ++k) nc.X[static_cast<std::size_t>(k)] = d.cloud.x(row)[k];
        nc.base = setup.prescribed(nc.X.data(), static_cast<std::size_t>(i), 0.0);
        nc.curve = bc.curve;
        for (auto k = d.particle_values().offsets[row]; k < d.particle_values().offsets[row + 1];
             ++k) {
          nc.nodes.push_back(
              op.overlap_node(p)[static_cast<std::size_t>(d.particle_values().particles[k])]);
          nc.phi.push_back(d.particle_values().values[k]);
        }
        nodes_.push_back(std::move(nc));
      }
    }
    if (!found)
      throw InputError(model.scene.file + ": boundary condition '" + bc.name + "': node " +
                       std::to_string(model.mesh.global_node(static_cast<std::size_t>(node)) + 1) +
                       " of node set '" + bc.node_set + "' is not a particle of any meshfree part");
  }
}

// Boundary points on the part sides the node set covers (all of a side's nodes in the set);
// returns how many such sides there are over all parts and ranks' cells.
long long EssentialConditions::add_boundary_points(const Model& model, const SolidOperator& op,
                                                   const Setup& setup) {
  const auto& mesh = model.mesh;
  const auto& bc = *setup.bc;
  const auto udim = static_cast<std::size_t>(dim_);
  std::vector<char> in_set(mesh.node_count(), 0);
  for (auto n : mesh.find_node_set(bc.node_set)->nodes) in_set[static_cast<std::size_t>(n)] = 1;
  long long sides_found = 0;
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& d = model.parts[p];
    const double thickness = dim_ == 2 ? d.part->thickness : 1.0;
    std::vector<SidePoint> pts;
    std::vector<double> beta;
    std::vector<std::size_t> cell_of;
    // mixed parts: the rows of the pressure cells of the points' cells
    std::map<std::size_t, CellAverages> cell_rows;
    const auto sides =
        node_set_sides(mesh, d.part->blocks, in_set, model.partition.owner, model.partition.rank);
    sides_found += static_cast<long long>(sides.here.size());
    for (const auto& [cell, side] : sides.here) {
      const double h = side_longest_edge(mesh, mesh.side_node_indices(cell, side));
      for (const auto& q : side_quadrature(mesh, cell, side)) {
        pts.push_back(q);
        beta.push_back(setup.beta_factor / h);
        cell_of.push_back(cell);
      }
    }
    if (pts.empty()) continue;
    std::vector<double> x;
    for (const auto& q : pts)
      x.insert(x.end(), q.x.begin(), q.x.begin() + static_cast<std::ptrdiff_t>(udim));
    const auto v =
        evaluate_shape_functions(d.cloud, x.data(), pts.size(), true, [&](std::size_t q) {
          return "boundary point " + std::to_string(q) + " of condition '" + bc.name + "'";
        });
    const MaterialLaw& law = op.history().part(p).law;
    const auto scale = modulus_scale(*model.scene.find_material(d.part->material), x.data(),
                                     pts.size(), dim_);  // graded material: E(x)/E_ref
    for (std::size_t q = 0; q < pts.size(); ++q) {
      BoundaryPoint b;
      b.condition = setup.index;
      for (std::size_t k = 0; k < 3; ++k)
        b.weighted_normal[k] = pts[q].normal[k] * pts[q].weight * thickness;
      b.area = pts[q].weight * thickness;
      b.constrained = setup.mask;
      for (std::size_t k = 0; k < udim; ++k) b.X[k] = pts[q].x[k];
      for (std::size_t k = 0; k < udim; ++k)
        if (setup.mask[k]) b.base[k] = setup.prescribed(b.X.data(), k, 0.0);
      b.curve = bc.curve;
      b.method = setup.method;
      b.beta = beta[q];
      b.law = law;
      if (!scale.empty()) b.law.elastic = physics::with_moduli_scaled(law.elastic, scale[q]);
      if (law.plastic) {
        b.history = committed_.size();
        double initial[physics::j2_state::count];
        law.initial_state(initial);
        committed_.insert(committed_.end(), initial, initial + physics::j2_state::count);
        trial_.insert(trial_.end(), initial, initial + physics::j2_state::count);
      }
      for (auto k = v.neighbors.offsets[q]; k < v.neighbors.offsets[q + 1]; ++k) {
        b.nodes.push_back(op.overlap_node(p)[static_cast<std::size_t>(v.neighbors.particles[k])]);
        b.phi.push_back(v.phi[k]);
        b.grad.insert(b.grad.end(), v.grad.begin() + static_cast<std::ptrdiff_t>(k * udim),
                      v.grad.begin() + static_cast<std::ptrdiff_t>((k + 1) * udim));
      }
      if (law.mixed()) {  // each pressure cell's row once, for all its boundary points
        const std::size_t group = d.pressure_cells.group[cell_of[q]];
        auto row = cell_rows.find(group);
        if (row == cell_rows.end())
          row = cell_rows.emplace(group, cell_averages(mesh, d.cloud, d.pressure_cells, {group}))
                    .first;
        b.cell_pressure =
            attach_cell_pressure(row->second, d, op.overlap_node(p), law, b.nodes, b.phi, b.grad);
        b.cell_pressure.part = p;
        b.cell_pressure.group = group;
        b.cell_pressure.volume = row->second.volume[0] * thickness;
      }
      points_.push_back(std::move(b));
    }
  }
  return sides_found;
}

void EssentialConditions::add_couplings(CouplingGraph& graph) const {
  for (const auto& c : nodes_)
    graph.add_row(c.owned_row / dim_, c.nodes.data(),
                  c.nodes.size());  // owned nodes lead the overlap order
  for (const auto& p : points_) graph.add_clique(p.nodes.data(), p.nodes.size());
}

void EssentialConditions::set_factor(const LoadFactor& factor) {
  const double t = factor.time();
  // An expression of t is the value at that time: no default ramp without a curve.
  auto scale = [&](std::size_t condition, const std::string& curve) {
    return timed_[condition] && curve.empty() ? 1.0 : factor(curve);
  };
  for (auto& c : nodes_) {
    if (const auto& timed = timed_[c.condition])
      c.base = timed(c.X.data(), static_cast<std::size_t>(c.component), t);
    c.value = c.base * scale(c.condition, c.curve);
  }
  for (auto& p : points_) {
    const double f = scale(p.condition, p.curve);
    for (std::size_t k = 0; k < 3; ++k) {
      if (timed_[p.condition] && p.constrained[k])
        p.base[k] = timed_[p.condition](p.X.data(), k, t);
      p.value[k] = p.base[k] * f;
    }
  }
}

double EssentialConditions::constrained_value(const NodeConstraint& c,
                                              const Vector& d_overlap) const {
  const auto u = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double value = 0;
  for (std::size_t k = 0; k < c.nodes.size(); ++k)
    value += c.phi[k] * u(static_cast<std::size_t>(c.nodes[k] * dim_ + c.component), 0);
  return value;
}

void EssentialConditions::replace_rows(const Vector& d_overlap, Vector& r_owned) const {
  for (const auto& c : nodes_)
    r_owned.replaceLocalValue(c.owned_row, c.scale * (constrained_value(c, d_overlap) - c.value));
}

void EssentialConditions::replace_rows(FEMatrix& K) const {
  // In modify mode only local indices are accepted: rows are owned dofs, columns the matrix's
  // column map.
  const auto& cols_map = *K.getColMap();
  std::vector<int> cols;
  std::vector<double> vals;
  for (const auto& c : nodes_) {
    const auto n = K.getNumEntriesInLocalRow(c.owned_row);
    Teuchos::Array<int> all_cols(n);
    Teuchos::Array<double> all_vals(n);
    std::size_t count = 0;
    K.getLocalRowCopy(c.owned_row, all_cols(), all_vals(), count);
    std::fill(all_vals.begin(), all_vals.end(), 0.0);
    K.replaceLocalValues(c.owned_row, all_cols(), all_vals());
    cols.clear();
    vals.clear();
    for (std::size_t k = 0; k < c.nodes.size(); ++k) {
      cols.push_back(cols_map.getLocalElement(
          overlap_dofs_->getGlobalElement(c.nodes[k] * dim_ + c.component)));
      vals.push_back(c.scale * c.phi[k]);
    }
    K.replaceLocalValues(c.owned_row, static_cast<int>(cols.size()), vals.data(), cols.data());
  }
}

std::vector<int> EssentialConditions::constrained_rows() const {
  std::vector<int> rows;
  for (const auto& c : nodes_) rows.push_back(c.owned_row);
  return rows;
}

void EssentialConditions::build_reaction_weights(const Model& model) {
  // s_Ick = integral over condition c's boundary of |phi_I| (or |phi_I(X_J)| at its collocated
  // nodes when it covers no side), for each component k the condition constrains: every
  // particle the condition reaches, MLS shape functions being negative in places. A component a
  // condition leaves free carries none of its reaction (a symmetry plane u_x = 0 takes no share
  // of a vertical load). Assembled on the overlap nodes and summed on their owners.
  const std::size_t n = std::max<std::size_t>(3 * conditions_, 1);
  Tpetra::MultiVector<> overlap(model.maps.overlap_nodes, n), owned(model.maps.owned_nodes, n);
  std::vector<char> has_sides(conditions_, 0);
  for (const auto& p : points_) has_sides[p.condition] = 1;
  {
    auto s = overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (const auto& p : points_)
      for (std::size_t a = 0; a < p.nodes.size(); ++a)
        for (std::size_t k = 0; k < 3; ++k)
          if (p.constrained[k])
            s(static_cast<std::size_t>(p.nodes[a]), 3 * p.condition + k) +=
                std::abs(p.phi[a]) * p.area;
    for (const auto& c : nodes_)
      if (!has_sides[c.condition])
        for (std::size_t a = 0; a < c.nodes.size(); ++a)
          s(static_cast<std::size_t>(c.nodes[a]),
            3 * c.condition + static_cast<std::size_t>(c.component)) += std::abs(c.phi[a]);
  }
  owned.doExport(overlap, Tpetra::Export<>(model.maps.overlap_nodes, model.maps.owned_nodes),
                 Tpetra::ADD);
  const auto s = owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  reaction_weight_.assign(s.extent(0), std::vector<double>(3 * conditions_, 0.0));
  for (std::size_t i = 0; i < s.extent(0); ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      double total = 0;
      for (std::size_t c = 0; c < conditions_; ++c) total += s(i, 3 * c + k);
      if (total > 0)
        for (std::size_t c = 0; c < conditions_; ++c)
          reaction_weight_[i][3 * c + k] = s(i, 3 * c + k) / total;
    }
}

std::vector<std::array<double, 3>> EssentialConditions::reactions(
    const Vector& residual_owned) const {
  const std::size_t n = conditions_ * 3;
  std::vector<double> local(n, 0.0);
  std::vector<double> global(n, 0.0);
  const auto r = residual_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  for (std::size_t i = 0; i < reaction_weight_.size(); ++i)
    for (std::size_t c = 0; c < conditions_; ++c)
      for (std::size_t k = 0; k < udim; ++k)
        local[c * 3 + k] += reaction_weight_[i][3 * c + k] * r(i * udim + k, 0);
  if (n > 0)
    Teuchos::reduceAll(*overlap_dofs_->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n),
                       local.data(), global.data());
  std::vector<std::array<double, 3>> out(conditions_);
  for (std::size_t c = 0; c < conditions_; ++c)
    out[c] = {global[3 * c], global[3 * c + 1], global[3 * c + 2]};
  return out;
}

}  // namespace efg
