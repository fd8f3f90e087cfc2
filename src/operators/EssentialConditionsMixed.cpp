// The transformation conditions' boundary traction on mixed u-p parts, as a coupling to the
// pressure of the point's pressure cell (for the bulk split of the iterative solver,
// operators/BulkSplit.hpp). A point's traction term in row (a, i), i constrained, is
// -phi_a (P n dA)_i with the cell's volumetric part P_vol n dA = kappa m F^-T N (N = n dA,
// operators/BoundaryCellPressure.hpp; small strain: kappa theta_c N): its derivative's rank-one
// part -phi_a (F^-T N)_i kappa g_b is proportional to kappa. Left in the relieved matrix, its share above
// kappa_0 would keep that matrix as stiff as the bulk modulus (measured: the saddle point's inner
// iterations grew from 33 to 65 between nu = 0.4999 and 0.499999 with an exact inverse of it, and
// an incomplete factorization of it did not converge); as a coupling it stays beside the cells'.
#include "operators/EssentialConditions.hpp"

namespace efg {
namespace {

// Row (a, i) coefficient -phi_a (F^-T N)_i and the columns g_b = F^-T b_b of one point at d:
// the rank-one part kappa g_bk (F^-T N)_i of the traction's derivative (BoundaryCellPressure.hpp;
// its other part, m_f kappa (F^-T N)_k g_bi, is of the size of the pressure and stays in A).
template <int Dim, class Point, class View>
void linearized_traction(const Point& p, const View& d,
                         EssentialConditions::CellPressureTraction& t) {
  const auto st = cell_traction_state<Dim>(p.cell_pressure, p.nodes, d, p.weighted_normal.data());
  for (std::size_t a = 0; a < p.nodes.size(); ++a)
    for (int i = 0; i < Dim; ++i) {
      const int dof = p.nodes[a] * Dim + i;
      const auto k = a * Dim + static_cast<std::size_t>(i);
      if (p.constrained[static_cast<std::size_t>(i)] && p.phi[a] != 0.0) {
        t.rows.push_back(dof);
        t.coefficient.push_back(-p.phi[a] * st.FN[i]);
      }
      if (st.g[k] != 0.0) {
        t.columns.push_back(dof);
        t.b.push_back(st.g[k]);
      }
    }
}

}  // namespace

std::vector<EssentialConditions::CellPressureTraction> EssentialConditions::cell_pressure_tractions(
    const Vector& d_overlap, bool& weak) const {
  weak = false;
  std::vector<CellPressureTraction> out;
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& p : points_) {
    if (!p.cell_pressure.active()) continue;
    if (p.method != 0) {  // Nitsche and penalty: beta and the symmetric term also carry kappa
      weak = true;
      continue;
    }
    CellPressureTraction t;
    t.part = p.cell_pressure.part;
    t.group = p.cell_pressure.group;
    t.volume = p.cell_pressure.volume;
    if (dim_ == 2)
      linearized_traction<2>(p, d, t);
    else
      linearized_traction<3>(p, d, t);
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace efg
