// Nitsche and penalty supports of shells (small rotations): the boundary integrals of
// ShellConstraints' weak edges, evaluated at the SCNI edge points (shells/ShellBoundary.hpp).
//
// With the jump j_c = sum_a phi_a d_(a,c) - g_c of a held component c at an edge point of length
// l, the terms added to the residual (resistance) are
//   nitsche:  f_(a,c) += l (-phi_a T_c(d) + beta_c phi_a j_c),  f_k += -l dT_c/dd_k j_c
//   penalty:  f_(a,c) += l beta_c phi_a j_c
// (Nitsche 1971; Fernandez-Mendez & Huerta, CMAME 193, 2004, for meshfree methods). The first
// nitsche term is the transformation method's edge traction term (the work of the unknown
// reaction), the second makes the form symmetric, the third stable for beta above the trace
// inverse constant. The tangent uses one traction row set dT/dd for both traction terms, so it
// is exactly symmetric (exact for elastic sections; for J2 sections the symmetric term's change
// of tangent is left out, as the solids' nitsche does).
#include <Teuchos_CommHelpers.hpp>

#include "shells/ShellConstraints.hpp"

namespace efg {
namespace {
constexpr int nd = shell_dofs_per_node;
}  // namespace

void ShellConstraints::set_edge_values(const std::vector<ShellSupport>& supports) {
  for (auto& e : edges_) {
    if (e.method == ShellMethod::transformation) continue;
    const auto& s = supports.at(static_cast<std::size_t>(e.support));
    for (std::size_t c = 0; c < nd; ++c) e.g[c] = s.value[c] ? s.value[c](e.point.x.data()) : 0.0;
  }
}

ShellConstraints::WeakTraction ShellConstraints::weak_traction(const Edge& e,
                                                               const ReadView& d) const {
  WeakTraction w;
  w.nitsche = e.method == ShellMethod::nitsche;
  if (w.nitsche) linear_traction(e, d, w.T, w.rows);
  return w;
}

double ShellConstraints::jump(const Edge& e, const ReadView& d, std::size_t c) const {
  double j = -e.g[c];
  for (std::size_t a = 0; a < e.node.size(); ++a) j += e.point.phi[a] * d(e.node[a] * nd + c, 0);
  return j;
}

void ShellConstraints::add_weak_forces(const Edge& e, const ReadView& d, WriteView& f) const {
  const auto& p = e.point;
  const std::size_t n = p.node.size(), width = n * nd;
  const auto [T, rows, nitsche] = weak_traction(e, d);
  for (std::size_t c = 0; c < nd; ++c) {
    if (!e.held[c]) continue;
    const double j = jump(e, d, c);
    for (std::size_t a = 0; a < n; ++a)
      f(e.node[a] * nd + c, 0) += p.length * p.phi[a] * (e.beta[c] * j - (nitsche ? T[c] : 0.0));
    for (std::size_t k = 0; nitsche && k < width; ++k)
      f(e.node[k / nd] * nd + k % nd, 0) -= p.length * rows[c * width + k] * j;
  }
}

void ShellConstraints::add_weak_terms(const Edge& e, const ReadView& d,
                                      FlatShellOperator::Matrix& K) const {
  const auto& p = e.point;
  const std::size_t n = p.node.size(), width = n * nd;
  const auto w = weak_traction(e, d);  // (the tangent needs its rows alone)
  std::vector<int> cols(width);
  for (std::size_t k = 0; k < width; ++k) cols[k] = e.node[k / nd] * nd + static_cast<int>(k % nd);
  // the point's block: rows (a, c) and (k) over the point's dofs, a dense width x width block
  std::vector<double> block(width * width, 0.0);
  for (std::size_t c = 0; c < nd; ++c) {
    if (!e.held[c]) continue;
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t row = a * nd + c;
      for (std::size_t b = 0; b < n; ++b)
        block[row * width + b * nd + c] += p.length * e.beta[c] * p.phi[a] * p.phi[b];
      for (std::size_t k = 0; w.nitsche && k < width; ++k) {
        const double t = p.length * p.phi[a] * w.rows[c * width + k];
        block[row * width + k] -= t;  // - phi_a dT_c/dd_k
        block[k * width + row] -= t;  // its transpose: - dT_c/dd_k phi_a
      }
    }
  }
  for (std::size_t r = 0; r < width; ++r)
    K.sumIntoLocalValues(cols[r], static_cast<int>(width), block.data() + r * width, cols.data());
}

void ShellConstraints::weak_resistance(const FlatShellOperator::Vector& d_owned,
                                       FlatShellOperator::Vector& r_owned,
                                       std::vector<double>* support_forces) const {
  FlatShellOperator::Vector d_overlap(op_.maps().overlap_dofs), r_overlap(op_.maps().overlap_dofs);
  op_.to_overlap(d_owned, d_overlap);
  std::vector<double> local(supports_ * nd, 0.0);
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto r = r_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    std::vector<double> before(r.extent(0));
    for (const auto& e : edges_) {
      if (e.method == ShellMethod::transformation) continue;
      if (support_forces)  // the point's own contribution: the difference it makes
        for (auto node : e.node)
          for (std::size_t c = 0; c < nd; ++c) before[node * nd + c] = r(node * nd + c, 0);
      add_weak_forces(e, d, r);
      if (!support_forces) continue;
      for (auto node : e.node)  // (the particles reaching a point are distinct)
        for (std::size_t c = 0; c < nd; ++c) {
          const auto i = static_cast<std::size_t>(node) * nd + c;
          local[static_cast<std::size_t>(e.support) * nd + c] -= r(i, 0) - before[i];
        }
    }
  }
  r_owned.putScalar(0.0);
  op_.add_overlap(r_overlap, r_owned);
  if (!support_forces) return;
  support_forces->assign(local.size(), 0.0);
  Teuchos::reduceAll(*op_.maps().owned_dofs->getComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(local.size()), local.data(), support_forces->data());
}

double ShellConstraints::weak_energy(const FlatShellOperator::Vector& d_owned) const {
  FlatShellOperator::Vector d_overlap(op_.maps().overlap_dofs);
  op_.to_overlap(d_owned, d_overlap);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double local = 0;
  for (const auto& e : edges_) {
    if (e.method == ShellMethod::transformation) continue;
    const auto w = weak_traction(e, d);
    for (std::size_t c = 0; c < nd; ++c) {
      if (!e.held[c]) continue;
      const double j = jump(e, d, c);
      local += e.point.length * (-w.T[c] * j + 0.5 * e.beta[c] * j * j);
    }
  }
  double all = 0;
  Teuchos::reduceAll(*op_.maps().owned_dofs->getComm(), Teuchos::REDUCE_SUM, 1, &local, &all);
  return all;
}

}  // namespace efg
