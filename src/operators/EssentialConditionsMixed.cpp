// The transformation conditions' boundary traction on mixed u-p parts, as a coupling to the
// pressure of the point's pressure cell (for the bulk split of the iterative solver,
// operators/BulkSplit.hpp). At small strain a point's traction term in row (a, i), i constrained,
// is -phi_a (P n dA)_i with the cell's volumetric part P_vol n dA = kappa theta_c N (N = n dA,
// operators/BoundaryCellPressure.hpp): linear in the cell pressure kappa theta_c with the
// coefficient -phi_a N_i, and so linear in kappa. Left in the relieved matrix, its share above
// kappa_0 would keep that matrix as stiff as the bulk modulus (measured: the saddle point's inner
// iterations grew from 33 to 65 between nu = 0.4999 and 0.499999 with an exact inverse of it, and
// an incomplete factorization of it did not converge); as a coupling it stays beside the cells'.
#include "operators/EssentialConditions.hpp"

namespace efg {

std::vector<EssentialConditions::CellPressureTraction> EssentialConditions::cell_pressure_tractions(
    bool& weak) const {
  weak = false;
  std::vector<CellPressureTraction> out;
  const auto udim = static_cast<std::size_t>(dim_);
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
    for (std::size_t a = 0; a < p.nodes.size(); ++a)
      for (std::size_t i = 0; i < udim; ++i) {
        const int dof = p.nodes[a] * dim_ + static_cast<int>(i);
        if (p.constrained[i] && p.phi[a] != 0.0) {
          t.rows.push_back(dof);
          t.coefficient.push_back(-p.phi[a] * p.weighted_normal[i]);
        }
        const double b = p.cell_pressure.bbar[a * udim + i];
        if (b != 0.0) {
          t.columns.push_back(dof);
          t.b.push_back(b);
        }
      }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace efg
