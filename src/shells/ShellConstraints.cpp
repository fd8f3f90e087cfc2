#include "shells/ShellConstraints.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/Errors.hpp"
#include "model/NodeSetSize.hpp"
#include "shells/ShellReference.hpp"

namespace efg {
namespace {
constexpr int nd = shell_dofs_per_node;
}  // namespace

ShellConstraints::ShellConstraints(const Model& model, const FlatShellOperator& op,
                                   const std::vector<ShellSupport>& supports)
    : op_(op), supports_(supports.size()) {
  const auto& overlap = *op.maps().overlap_nodes;
  const auto lid = [&](LocalIndex node) {
    return overlap.getLocalElement(global_node_id(model, node));
  };
  // (node, component) -> (value, support); a later support wins on shared nodes (corners).
  std::map<std::pair<LocalIndex, int>, std::pair<double, int>> value;
  for (std::size_t k = 0; k < supports.size(); ++k) {
    const auto& s = supports[k];
    const auto* set = model.mesh.find_node_set(s.node_set);
    if (!set)
      throw InputError(model.scene.file + ": shell support: node set '" + s.node_set +
                       "' is not in the mesh");
    const bool weak = s.method != ShellMethod::transformation;
    weak_ = weak_ || weak;
    // the collocation rows' values (nitsche and penalty hold their edges without rows)
    for (std::size_t i = 0; !weak && i < set->nodes.size(); ++i) {
      const auto node = set->nodes[i];
      const double* x = model.mesh.coordinates.data() + 2 * static_cast<std::size_t>(node);
      for (int c = 0; c < nd; ++c)
        if (s.value[static_cast<std::size_t>(c)])
          value[{node, c}] = {s.value[static_cast<std::size_t>(c)](x), static_cast<int>(k)};
    }
    long long sides = 0;
    Edge edge;
    edge.method = s.method;
    edge.support = static_cast<int>(k);
    for (int c = 0; c < nd; ++c)
      edge.held[static_cast<std::size_t>(c)] =
          static_cast<bool>(s.value[static_cast<std::size_t>(c)]);
    auto points = shell_edge_points(model, s.node_set, &sides);
    // J2 parts: the edge points' layers continue the history of earlier stages (op's store)
    std::size_t size = 0;
    for (const auto& p : points) size += op.history_size(p.part);
    double* store = size ? op.edge_history(s.node_set, size).data() : nullptr;
    for (auto& p : points) {
      edge.node.clear();
      for (auto n : p.node) edge.node.push_back(lid(n));
      const std::size_t n = op.history_size(p.part);
      edge.committed = n ? store : nullptr;
      store += n;
      edge.trial = trial_.size();
      trial_.resize(trial_.size() + n, 0.0);
      edge.point = std::move(p);
      edge.thickness = op.thickness_at(edge.point.part, edge.node.data(), edge.point.phi.data(),
                                       edge.node.size());
      if (weak) {
        // beta_c = alpha s_c / h per unit edge length (the solids' alpha E / h for a section)
        const double alpha = s.alpha > 0 ? s.alpha : s.method == ShellMethod::nitsche ? 100.0 : 1e4;
        // each component's scale is the stiffness of its own traction: A_11 for N n, the
        // (stabilized) shear k_s G t for Q . n, D_11 for M n; a membrane scale on w would hold
        // a thin shell's deflection at every edge point as if rigid (over-constrained: -16 % on
        // the clamped plate at t/a = 1e-3)
        const auto section = op.section_at(edge.point.part, edge.point.spacing, edge.thickness);
        for (int c = 0; c < nd; ++c)
          edge.beta[static_cast<std::size_t>(c)] = alpha *
                                                   (c == shell_w   ? section.shear
                                                    : c < shell_rx ? section.membrane[0][0]
                                                                   : section.bending[0][0]) /
                                                   edge.point.spacing;
      }
      edges_.push_back(edge);
    }
    // A set covering no edge (a pin, a corner) holds its particles by collocation alone: a
    // point support carries a point reaction, with no edge traction to integrate.
    if (sides == 0 &&
        (model.mesh.is_part() ? owned_entries_over_ranks(model, *set) : set->nodes.size()) == 0)
      throw InputError(model.scene.file + ": shell support: node set '" + s.node_set +
                       "' is empty");
    if (weak && sides == 0)
      throw InputError(model.scene.file + ": " + (s.key.empty() ? "shell support" : s.key) +
                       ".node_set: node set '" + s.node_set + "' covers no edge, and method " +
                       (s.method == ShellMethod::nitsche ? "nitsche" : "penalty") +
                       " holds edges by boundary integrals: expected method transformation for "
                       "a point support");
  }
  set_edge_values(supports);
  if (op.curved()) {
    // the edge points' strains at the reference state (d = 0), which theirs are measured from
    FlatShellOperator::Vector zero(op.maps().overlap_dofs);
    const auto d = zero.getLocalViewHost(Tpetra::Access::ReadOnly);
    FiniteRotationPoint fe;
    for (auto& e : edges_) {
      double strain[shell_strains];
      e.reference = {};
      edge_kinematics(e, d, fe);
      finite_rotation_strains(fe.geometry, strain);
      std::copy(strain, strain + shell_strains, e.reference.begin());
      if (const auto r = part_reference_at(model, e.point.part, e.point.x.data())) {
        e.metric = r->metric;
        e.point.spacing *= std::sqrt(r->metric.area);  // the particle spacing on the surface
      }
    }
  }
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = model.parts[p];
    const auto& rows = part.particle_values();
    for (std::size_t r = 0; r < part.cloud.owned_count; ++r)
      for (int c = 0; c < nd; ++c) {
        const auto it = value.find({part.cloud.mesh_node[r], c});
        if (it == value.end()) continue;
        Row row;
        row.node = lid(part.cloud.mesh_node[r]);
        row.component = c;
        const auto section = op.section(p, op.node_thickness(p, row.node));
        row.scale = c < shell_rx ? section.membrane[0][0] : section.bending[0][0];
        row.value = it->second.first;
        row.support = it->second.second;
        const double* x =
            model.mesh.coordinates.data() + 2 * static_cast<std::size_t>(part.cloud.mesh_node[r]);
        row.x = {x[0], x[1]};
        for (auto k = rows.offsets[r]; k < rows.offsets[r + 1]; ++k) {
          row.columns.push_back(
              lid(part.cloud.mesh_node[static_cast<std::size_t>(rows.particles[k])]));
          row.phi.push_back(rows.values[k]);
        }
        rows_.push_back(std::move(row));
        value.erase(it);  // a node shared by two parts is collocated once
      }
  }
}

void ShellConstraints::add_couplings(CouplingGraph& graph) const {
  for (const auto& e : edges_) graph.add_clique(e.node.data(), e.node.size());
  for (const auto& r : rows_) graph.add_row(r.node, r.columns.data(), r.columns.size());
}

template <class View>
void ShellConstraints::edge_kinematics(const Edge& e, const View& d,
                                       FiniteRotationPoint& fe) const {
  // an edge point's gradients are the direct ones (b = g)
  const auto& p = e.point;
  fe.nodes.clear();
  fe.geometry = reference_geometry();
  for (std::size_t a = 0; a < p.node.size(); ++a) {
    const double* g = &p.grad[2 * a];
    fe.nodes.push_back(op_.node_at(e.node[a], g, g, p.phi[a], d));
    add_to_geometry(fe.nodes.back(), fe.geometry);
  }
}

template <class View>
void ShellConstraints::edge_response(const Edge& e, const View& d, double (&R)[shell_strains],
                                     SectionTangent* S, FiniteRotationPoint* fe) const {
  const auto& p = e.point;
  double strain[shell_strains] = {};
  if (fe) {
    edge_kinematics(e, d, *fe);
    finite_rotation_strains(fe->geometry, strain);
    for (std::size_t i = 0; i < shell_strains; ++i) strain[i] -= e.reference[i];
    if (op_.curved()) strains_to_surface(e.metric, strain);
  }
  for (std::size_t a = 0; !fe && a < p.node.size(); ++a) {
    double B[shell_strains][nd];
    const double g[2] = {p.grad[2 * a], p.grad[2 * a + 1]};
    plate_strain_rows(g, g, p.phi[a], B);
    for (int c = 0; c < nd; ++c) {
      const double dc = d(static_cast<std::size_t>(e.node[a] * nd + c), 0);
      for (int i = 0; i < shell_strains; ++i) strain[i] += B[i][c] * dc;
    }
  }
  shell_section_response(op_.section_law(p.part, p.spacing, e.thickness), strain, e.committed,
                         e.committed ? trial_.data() + e.trial : nullptr, R, S);
}

void ShellConstraints::to_mesh(const Edge& e, const double* R, double (&out)[shell_strains]) const {
  if (op_.curved()) return resultants_to_mesh(e.metric, R, e.metric.area, out);
  std::copy(R, R + shell_strains, out);
}

template <class View, class Force>
void ShellConstraints::add_finite_edge_forces(const Edge& e, const View& d, Force& f) const {
  const auto& p = e.point;
  FiniteRotationPoint fe;
  double surface[shell_strains], R[shell_strains];
  edge_response(e, d, surface, nullptr, &fe);
  to_mesh(e, surface, R);
  Vec3 t, m;
  finite_rotation_edge_reaction(fe.geometry, R, {p.normal[0], p.normal[1]}, t, m);
  for (std::size_t a = 0; a < p.node.size(); ++a)
    for (int c = 0; c < nd; ++c) {
      if (!e.held[static_cast<std::size_t>(c)]) continue;
      const double T = c < shell_rx ? t[static_cast<std::size_t>(c)]
                                    : dot(m, fe.nodes[a].director.T[c - shell_rx]);
      f(static_cast<std::size_t>(e.node[a] * nd + c), 0) -= p.length * p.phi[a] * T;
    }
}

template <class View>
void ShellConstraints::add_finite_edge_terms(const Edge& e, const View& d,
                                             FlatShellOperator::Matrix& K) const {
  const auto& p = e.point;
  const std::size_t n = p.node.size(), width = n * nd;
  FiniteRotationPoint fe;
  double surface[shell_strains], R[shell_strains];
  SectionTangent S;
  edge_response(e, d, surface, &S, &fe);
  to_mesh(e, surface, R);
  const double normal[2] = {p.normal[0], p.normal[1]};
  Vec3 t, m;
  finite_rotation_edge_reaction(fe.geometry, R, normal, t, m);
  // dt[k], dm[k]: the reaction's change for a unit change of column dof k
  std::vector<Vec3> dt(width), dm(width);
  std::vector<int> cols(width);
  for (std::size_t b = 0; b < n; ++b) {
    double B[shell_strains][nd], SB[shell_strains][nd];
    finite_rotation_rows(fe.geometry, fe.nodes[b], B);
    if (op_.curved()) rows_to_surface(e.metric, B);
    tangent_rows(S, B, SB);
    for (int c = 0; c < nd; ++c) {
      const auto k = b * nd + static_cast<std::size_t>(c);
      cols[k] = e.node[b] * nd + c;
      double dS[shell_strains], dR[shell_strains];
      for (int r = 0; r < shell_strains; ++r) dS[r] = SB[r][c];
      to_mesh(e, dS, dR);
      finite_rotation_edge_reaction_change(fe.geometry, R, dR, normal, fe.nodes[b], c, dt[k],
                                           dm[k]);
    }
  }
  std::vector<double> vals(width);
  for (std::size_t a = 0; a < n; ++a)
    for (int c = 0; c < nd; ++c) {
      if (!e.held[static_cast<std::size_t>(c)]) continue;
      const double scale = -p.length * p.phi[a];
      for (std::size_t k = 0; k < width; ++k) {
        if (c < shell_rx) {
          vals[k] = scale * dt[k][static_cast<std::size_t>(c)];
          continue;
        }
        const auto& director = fe.nodes[a].director;
        double v = dot(dm[k], director.T[c - shell_rx]);
        const int column = static_cast<int>(k % nd);
        if (k / nd == a && column >= shell_rx)  // the row's own director turning
          v += dot(m, director.S[c - shell_rx][column - shell_rx]);
        vals[k] = scale * v;
      }
      K.sumIntoLocalValues(e.node[a] * nd + c, static_cast<int>(width), vals.data(), cols.data());
    }
}

void ShellConstraints::add_edge_terms(const FlatShellOperator::Vector& d_overlap,
                                      FlatShellOperator::Matrix& K) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> T, vals;
  std::vector<int> cols;
  for (const auto& e : edges_) {
    if (op_.finite_rotations()) {  // (transformation only: the scene check)
      add_finite_edge_terms(e, d, K);
      continue;
    }
    if (e.method != ShellMethod::transformation) {
      add_weak_terms(e, d, K);
      continue;
    }
    const auto& p = e.point;
    const std::size_t n = p.node.size(), width = n * nd;
    double traction[nd];
    linear_traction(e, d, traction, T);
    cols.resize(width);
    for (std::size_t k = 0; k < width; ++k)
      cols[k] = e.node[k / nd] * nd + static_cast<int>(k % nd);
    vals.resize(width);
    for (std::size_t a = 0; a < n; ++a)
      for (int c = 0; c < nd; ++c) {
        if (!e.held[static_cast<std::size_t>(c)]) continue;
        for (std::size_t k = 0; k < width; ++k)
          vals[k] = -p.length * p.phi[a] * T[static_cast<std::size_t>(c) * width + k];
        K.sumIntoLocalValues(e.node[a] * nd + c, static_cast<int>(width), vals.data(), cols.data());
      }
  }
}

void ShellConstraints::linear_traction(const Edge& e, const ReadView& d, double (&traction)[nd],
                                       std::vector<double>& rows) const {
  const auto& p = e.point;
  const std::size_t n = p.node.size(), width = n * nd;
  double R[shell_strains];
  SectionTangent S;
  edge_response(e, d, R, &S);
  edge_traction(R, p.normal, traction);
  rows.assign(nd * width, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    double B[shell_strains][nd], SB[shell_strains][nd];
    const double g[2] = {p.grad[2 * a], p.grad[2 * a + 1]};
    plate_strain_rows(g, g, p.phi[a], B);
    tangent_rows(S, B, SB);
    for (int c = 0; c < nd; ++c) {
      const auto k = a * nd + static_cast<std::size_t>(c);
      double dR[shell_strains], t[nd];
      for (int r = 0; r < shell_strains; ++r) dR[r] = SB[r][c];
      edge_traction(dR, p.normal, t);
      for (int h = 0; h < nd; ++h) rows[static_cast<std::size_t>(h) * width + k] = t[h];
    }
  }
}

void ShellConstraints::add_edge_forces(const FlatShellOperator::Vector& d_overlap,
                                       FlatShellOperator::Vector& f_overlap) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& e : edges_) {
    if (op_.finite_rotations()) {
      add_finite_edge_forces(e, d, f);
      continue;
    }
    if (e.method != ShellMethod::transformation) {
      add_weak_forces(e, d, f);
      continue;
    }
    double R[shell_strains], T[nd];
    edge_response(e, d, R, nullptr);
    edge_traction(R, e.point.normal, T);
    for (std::size_t a = 0; a < e.point.node.size(); ++a)
      for (int c = 0; c < nd; ++c)
        if (e.held[static_cast<std::size_t>(c)])
          f(static_cast<std::size_t>(e.node[a] * nd + c), 0) -=
              e.point.length * e.point.phi[a] * T[c];
  }
}

void ShellConstraints::commit() const {
  for (const auto& e : edges_)
    if (e.committed)
      std::copy_n(trial_.data() + e.trial, op_.history_size(e.point.part), e.committed);
}

void ShellConstraints::replace_rows(FlatShellOperator::Matrix& K) const {
  // Modify mode takes local indices: rows are owned dofs, columns the matrix's column map.
  const auto& col_map = *K.getColMap();
  const auto& overlap_dofs = *op_.maps().overlap_dofs;
  std::vector<int> cols;
  std::vector<double> vals;
  for (auto& r : rows_) {
    const int row = r.node * nd + r.component;
    const auto count = K.getNumEntriesInLocalRow(row);
    Teuchos::Array<int> all_cols(count);
    Teuchos::Array<double> zeros(count);
    std::size_t found = 0;
    K.getLocalRowCopy(row, all_cols(), zeros(), found);
    // The scale of the row it replaces (its largest entry), so that the collocation rows of
    // rotations, whose stiffness rows carry the shear term k_s G t phi^2 of a thin shell, are not
    // many orders of magnitude smaller than their neighbours' (pivoting, round-off).
    double scale = 0;
    for (auto v : zeros) scale = std::max(scale, std::abs(v));
    if (!scaled_) r.scale = scale > 0 ? scale : r.scale;
    std::fill(zeros.begin(), zeros.end(), 0.0);
    K.replaceLocalValues(row, all_cols(), zeros());
    cols.clear();
    vals.clear();
    for (std::size_t k = 0; k < r.columns.size(); ++k) {
      cols.push_back(
          col_map.getLocalElement(overlap_dofs.getGlobalElement(r.columns[k] * nd + r.component)));
      vals.push_back(r.scale * r.phi[k]);
    }
    K.replaceLocalValues(row, static_cast<int>(cols.size()), vals.data(), cols.data());
  }
  scaled_ = true;
}

void ShellConstraints::set_values(FlatShellOperator::Vector& rhs_owned) const {
  if (weak_) {  // the weak edges' terms in g: -r_edges(0)
    FlatShellOperator::Vector r(op_.maps().owned_dofs);
    weak_resistance(FlatShellOperator::Vector(op_.maps().owned_dofs), r);
    rhs_owned.update(-1.0, r, 1.0);
  }
  auto rhs = rhs_owned.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& r : rows_)
    rhs(static_cast<std::size_t>(r.node * nd + r.component), 0) = r.scale * r.value;
}

void ShellConstraints::constrained_residual(const FlatShellOperator::Vector& d_overlap,
                                            const std::vector<double>& values,
                                            FlatShellOperator::Vector& r_owned) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto r = r_owned.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const auto& row = rows_[k];
    double u = 0;
    for (std::size_t j = 0; j < row.columns.size(); ++j)
      u += row.phi[j] * d(static_cast<std::size_t>(row.columns[j] * nd + row.component), 0);
    r(static_cast<std::size_t>(row.node * nd + row.component), 0) = row.scale * (u - values[k]);
  }
}

void ShellConstraints::zero_constrained(FlatShellOperator::Vector& v_owned) const {
  auto v = v_owned.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& row : rows_) v(static_cast<std::size_t>(row.node * nd + row.component), 0) = 0;
}

Teuchos::RCP<Tpetra::CrsMatrix<>> ShellConstraints::collocation_matrix(
    std::vector<double>& values) const {
  const auto& dofs = op_.maps().owned_dofs;
  const auto rows = Teuchos::rcp(new Tpetra::Map<>(
      Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), rows_.size(), 0, dofs->getComm()));
  std::size_t widest = 1;
  for (const auto& r : rows_) widest = std::max(widest, r.columns.size());
  auto C = Teuchos::rcp(new Tpetra::CrsMatrix<>(rows, widest));
  const auto& overlap_dofs = *op_.maps().overlap_dofs;
  values.clear();
  std::vector<GlobalOrdinal> cols;
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const auto& r = rows_[k];
    cols.clear();
    for (auto c : r.columns) cols.push_back(overlap_dofs.getGlobalElement(c * nd + r.component));
    C->insertGlobalValues(rows->getGlobalElement(static_cast<int>(k)),
                          static_cast<int>(cols.size()), r.phi.data(), cols.data());
    values.push_back(r.value);
  }
  C->fillComplete(dofs, rows);
  return C;
}

std::vector<double> ShellConstraints::collocation_values(
    const std::vector<ShellSupport>& supports) const {
  std::vector<double> values;
  values.reserve(rows_.size());
  for (const auto& r : rows_) {
    const auto& f = supports.at(static_cast<std::size_t>(r.support))
                        .value[static_cast<std::size_t>(r.component)];
    values.push_back(f ? f(r.x.data()) : 0.0);
  }
  return values;
}

std::vector<std::pair<int, int>> ShellConstraints::row_supports() const {
  std::vector<std::pair<int, int>> out;
  for (const auto& r : rows_) out.emplace_back(r.support, r.component);
  return out;
}

}  // namespace efg
