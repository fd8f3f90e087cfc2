// The cell pressure in the traction of an essential condition's boundary point on a mixed u-p
// part (operators/MixedPressure): the point's law is the deviatoric one, so the traction P N of
// the transformation and Nitsche terms needs the volumetric stress of the point's cell,
//
//   (P_vol N)_k = kappa m (F^-T N)_k,
//   d (P_vol N)_k / d d_ai = kappa (g_ai (F^-T N)_k - m_f (F^-T N)_i g_ak),   g_a = F^-T b_a,
//
// with m the cell's measure (small strain: theta = tr H, F^-T = I, m_f = 0; finite strain:
// m = m_f = ln J of the cell-smoothed F = I + H, H = sum_a d_a (x) b_a), as MixedPressure's
// cell_state computes it for the cells themselves.
#pragma once

#include <cmath>
#include <vector>

#include "core/Errors.hpp"
#include "discretization/PartDiscretization.hpp"
#include "model/MaterialLaws.hpp"
#include "operators/BulkTangent.hpp"
#include "tensor/Tensor.hpp"

namespace efg {

struct BoundaryCellPressure {
  double kappa = 0, kappa0 = 0;  ///< the part's bulk modulus and its relieved kappa_0
  bool finite = false;
  std::vector<double> bbar;         ///< b_a of the cell, dim per entry of the point's node list
  std::size_t part = 0, group = 0;  ///< model part and pressure cell (the bulk split's coupling)
  double volume = 0;                ///< V_c of the pressure cell (x thickness in 2D)
  bool active() const { return !bbar.empty(); }
};

/// The row of the point's cell (`row`: cell_averages of that one cell) for a boundary point of a
/// mixed part: `nodes`, `phi` and `grad` (dim per entry) gain the cell's particles the point does
/// not reach (phi = grad = 0 there).
BoundaryCellPressure attach_cell_pressure(const CellAverages& row, const PartDiscretization& d,
                                          const std::vector<int>& overlap_node,
                                          const MaterialLaw& law, std::vector<int>& nodes,
                                          std::vector<double>& phi, std::vector<double>& grad);

/// The cell's kinematics at generalized displacements `d` (a host view on the overlap dofs):
/// its measure m (theta = tr H, or ln J), m_f (ln J at finite strain, else 0), F^-T N and
/// g_a = F^-T b_a (dim per entry of `nodes`); small strain: F^-T = I.
template <int Dim>
struct CellTractionState {
  double m = 0, m_f = 0, FN[Dim] = {};
  std::vector<double> g;
};

template <int Dim, class View>
CellTractionState<Dim> cell_traction_state(const BoundaryCellPressure& c,
                                           const std::vector<int>& nodes, const View& d,
                                           const double* N) {
  const std::size_t n = nodes.size();
  CellTractionState<Dim> st;
  // H first: theta = tr H directly (1 + theta - 1 would lose a nearly incompressible theta's
  // digits).
  double H[Dim][Dim] = {}, F[Dim][Dim], Finv[Dim][Dim] = {};
  for (std::size_t a = 0; a < n; ++a)
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j)
        H[i][j] += d(static_cast<std::size_t>(nodes[a] * Dim + i), 0) *
                   c.bbar[a * Dim + static_cast<std::size_t>(j)];
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
  if (c.finite) {
    const double j_minus_1 = physics::determinant_of_identity_plus_minus_one<Dim>(H);
    const double J = 1.0 + j_minus_1;
    if (!(J > 0)) throw NumericalError("det F <= 0 in the mixed u-p cell of a boundary point");
    physics::inverse<Dim>(F, J, Finv);
    st.m = st.m_f = std::log1p(j_minus_1);
  } else {
    for (int i = 0; i < Dim; ++i) {
      st.m += H[i][i];
      Finv[i][i] = 1.0;
    }
  }
  for (int k = 0; k < Dim; ++k)
    for (int l = 0; l < Dim; ++l) st.FN[k] += Finv[l][k] * N[l];
  st.g.assign(n * Dim, 0.0);  // (F^-T b_a)_i
  for (std::size_t a = 0; a < n; ++a)
    for (int i = 0; i < Dim; ++i)
      for (int l = 0; l < Dim; ++l)
        st.g[a * Dim + static_cast<std::size_t>(i)] +=
            Finv[l][i] * c.bbar[a * Dim + static_cast<std::size_t>(l)];
  return st;
}

/// Adds the volumetric traction to Pn (N = weighted normal, n dA) and its derivative to
/// S[(a Dim + k) Dim + i] at generalized displacements `d` (a host view on the overlap dofs);
/// `bulk`: the derivative's rank-one part kappa g_ai (F^-T N)_k at kappa or kappa_0
/// (operators/BulkTangent.hpp).
template <int Dim, class View>
void add_cell_pressure_traction(const BoundaryCellPressure& c, const std::vector<int>& nodes,
                                const View& d, const double* N, double* Pn, std::vector<double>& S,
                                BulkTangent bulk = BulkTangent::full) {
  const double rank_one = bulk == BulkTangent::full ? c.kappa : c.kappa0;
  const auto st = cell_traction_state<Dim>(c, nodes, d, N);
  for (int k = 0; k < Dim; ++k) Pn[k] += c.kappa * st.m * st.FN[k];
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < Dim; ++k)
      for (int i = 0; i < Dim; ++i)
        S[(a * Dim + static_cast<std::size_t>(k)) * Dim + static_cast<std::size_t>(i)] +=
            rank_one * st.g[a * Dim + static_cast<std::size_t>(i)] * st.FN[k] -
            c.kappa * st.m_f * st.FN[i] * st.g[a * Dim + static_cast<std::size_t>(k)];
}

}  // namespace efg
