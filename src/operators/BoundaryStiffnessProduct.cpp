// The boundary terms' stiffness applied to a vector without forming it (the explicit stable-step
// estimate): EssentialConditions::apply_boundary_stiffness at the tangents of boundary_tangent.
#include "operators/EssentialConditions.hpp"

namespace efg {

// y += K_b x with the entries of point_terms' matrix branch: for row (a, i)
//   sum_(b,k) [ -phi_a S(b,i,k) c_i - S(a,k,i) phi_b c_k + beta phi_a phi_b dA c_i delta_ik ] x_bk
// (c the constrained mask), i.e. -phi_a c_i (S x)_i - sum_k c_k S(a,k,i) (phi . x)_k
// + beta phi_a c_i (phi . x)_i dA: two contractions per point instead of a dense block.
// A transformation point has the consistency (traction) term alone, T = -phi_a c_i S(b,i,k),
// which is not symmetric; its symmetric part (T + T^T) / 2 is half the consistency term plus
// half the symmetric term. Every real eigenvalue of M^-1 (K + T) lies below the largest of
// M^-1 (K + (T + T^T) / 2) (a real eigenvector x gives lambda = x^T (K + T) x / x^T M x, and
// x^T T x = x^T T_sym x), which is what the stable step must stay under.
template <int Dim>
void EssentialConditions::point_product(const BoundaryPoint& p, const PointState& st,
                                        const Vector& x_overlap, Vector& y_overlap) const {
  const std::size_t n = p.nodes.size();
  // Weights of the consistency and symmetric terms: Nitsche 1 and 1, penalty none, a
  // transformation point's traction term symmetrized (1/2 and 1/2).
  const double consistency = p.method == 2 ? 0.0 : p.method == 0 ? 0.5 : 1.0;
  const double symmetric = p.method == 2 ? 0.0 : consistency;
  const bool stabilized = p.method != 0;
  const auto x = x_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double phi_x[Dim] = {}, S_x[Dim] = {};  // sum_b phi_b x_b and sum_(b,k) S(b,i,k) x_bk
  for (std::size_t b = 0; b < n; ++b)
    for (int k = 0; k < Dim; ++k) {
      const double xb = x(static_cast<std::size_t>(p.nodes[b] * Dim + k), 0);
      phi_x[k] += p.phi[b] * xb;
      for (int i = 0; i < Dim; ++i) S_x[i] += st.s(b, i, k) * xb;
    }
  auto y = y_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t a = 0; a < n; ++a)
    for (int i = 0; i < Dim; ++i) {
      double v = 0;
      if (p.constrained[static_cast<std::size_t>(i)]) {
        v -= consistency * p.phi[a] * S_x[i];
        if (stabilized) v += p.beta * p.phi[a] * phi_x[i] * p.area;
      }
      for (int k = 0; k < Dim; ++k)
        if (p.constrained[static_cast<std::size_t>(k)]) v -= symmetric * st.s(a, k, i) * phi_x[k];
      y(static_cast<std::size_t>(p.nodes[a] * Dim + i), 0) += v;
    }
}

void EssentialConditions::apply_boundary_stiffness(const BoundaryTangent& tangent,
                                                   const Vector& x_overlap,
                                                   Vector& y_overlap) const {
  // Transformation points (explicit stages with transformation_traction) enter with their
  // traction term's symmetric part: the Hermitian eigensolver of the stable step cannot take
  // the nonsymmetric term itself (it failed on the bent strip), and the symmetric part bounds
  // the real eigenvalues the term can raise.
  for (std::size_t k = 0; k < points_.size(); ++k) {
    if (dim_ == 2)
      point_product<2>(points_[k], tangent.points[k], x_overlap, y_overlap);
    else
      point_product<3>(points_[k], tangent.points[k], x_overlap, y_overlap);
  }
}

}  // namespace efg
