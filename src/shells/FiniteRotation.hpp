// Finite rotations of a Reissner-Mindlin shell on a flat reference (mid-surface z = 0): the
// kinematics of the geometrically nonlinear shell parts (`section.formulation:
// total_lagrangian`, docs/shells.md "Finite rotations").
//
// Every particle I carries an orthonormal frame (t1, t2, t3), t3 its director, updated by the
// exponential map when a load step is accepted; its two rotation dofs (a, b) are the rotation
// vector w = a t1 + b t2 (perpendicular to the director: no drilling rotation) since that
// update, so that
//
//   d_I(a, b) = exp(w) t3 = cos r t3 + (sin r / r) (w x t3)
//             = cos r t3 + (sin r / r) (b t1 - a t2),        r = |w|
//
// (Simo & Fox, CMAME 72, 1989, 267-304; the per-step update of the rotation vector avoids the
// singularity of a total rotation vector at |w| = pi). At the start t = (E1, E2, E3) and the
// dofs are the small rotations theta_x, theta_y of the linear shell.
//
// The mid-surface map is x = X + u (translations are totals). With the shape functions' smoothed
// gradients b_I (SCNI, the membrane and bending strains), direct gradients g_I and values phi_I
// (the transverse shear, Wang & Chen 2004) the point quantities are
//
//   F_a = E_a + sum b_Ia u_I,  D_a = sum b_Ia d_I,  f_a = E_a + sum g_Ia u_I,  d = sum phi_I d_I
//
// and the Green-Lagrange generalized strains of the flat reference (Simo & Fox 1989, eq. 4.5)
//
//   eps   = (1/2 (F1.F1 - 1), 1/2 (F2.F2 - 1), F1.F2)
//   kappa = (F1.D1, F2.D2, F1.D2 + F2.D1)
//   gamma = (f1.d, f2.d)
//
// which reduce to shells/PlateStrains.hpp for small u and rotations. The section law (N, M, Q)
// of these strains is the linear one: a strip bent by an end moment M bends into an arc of
// curvature M / (E I) exactly (the rolled strip of docs/shells.md). Plain arrays, no Trilinos.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "shells/PlateStrains.hpp"

namespace efg {

using Vec3 = std::array<double, 3>;

inline double dot(const Vec3& x, const Vec3& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}
inline Vec3 cross(const Vec3& x, const Vec3& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

/// A particle's orthonormal frame: t3 the director, t1 and t2 the axes of its rotation dofs.
struct ShellFrame {
  Vec3 t1{1, 0, 0}, t2{0, 1, 0}, t3{0, 0, 1};
};

/// The director of a particle at rotation dofs (a, b) and its first and second derivatives.
struct NodeDirector {
  Vec3 d{};
  Vec3 T[2]{};     ///< dd/da, dd/db
  Vec3 S[2][2]{};  ///< d2d/(da db)
};

NodeDirector node_director(const ShellFrame& frame, double a, double b);

/// frame <- exp(a t1 + b t2) frame: the accepted rotation made the frame's own.
void rotate_frame(ShellFrame& frame, double a, double b);

/// The rotation R turning frame `from` into frame `now` (each made orthonormal from its t3 and t1
/// first: interpolated frames), as its rotation vector's components about from's t1 and t2 (the
/// flat case: the rotations about x and y; a drilling part about t3 is not shown). The rotation
/// vector is R's logarithm, angle in [0, pi]: its axis is R's fixed direction also at pi, where
/// the directors alone (antiparallel) would not tell it.
void frame_rotation(const ShellFrame& from, const ShellFrame& now, double& rx, double& ry);

/// The point quantities F_a, D_a (smoothed), f_a (direct) and d.
struct ShellPointGeometry {
  Vec3 F[2]{}, D[2]{}, f[2]{}, d{};
};

/// One particle's part of a point: its smoothed gradient b, direct gradient g, value phi, its
/// translations u (totals) and director.
struct ShellNodeAtPoint {
  const double* b;
  const double* g;
  double phi;
  Vec3 u;
  NodeDirector director;
};

/// An integration (or edge) point's particles and its point quantities.
struct FiniteRotationPoint {
  std::vector<ShellNodeAtPoint> nodes;
  ShellPointGeometry geometry;
};

/// Adds one particle's part to the point quantities (start from reference_geometry()).
ShellPointGeometry reference_geometry();
void add_to_geometry(const ShellNodeAtPoint& n, ShellPointGeometry& G);

/// The eight generalized strains (eps, kappa, gamma) of the point.
void finite_rotation_strains(const ShellPointGeometry& G, double (&e)[shell_strains]);

/// B[strain][dof] = d e / d q of one particle's five dofs (u, v, w, a, b).
void finite_rotation_rows(const ShellPointGeometry& G, const ShellNodeAtPoint& n,
                          double (&B)[shell_strains][shell_dofs_per_node]);

/// The geometric block sum_k R_k d2 e_k / (d q_I d q_J) (5 x 5) between particles I = m and
/// J = n of a point; `same` when they are the same particle.
void finite_rotation_geometric(const ShellPointGeometry& G, const double (&R)[shell_strains],
                               const ShellNodeAtPoint& m, const ShellNodeAtPoint& n, bool same,
                               double (&K)[shell_dofs_per_node][shell_dofs_per_node]);

/// The reaction on an edge of outward normal n (in the reference plane) conjugate to the
/// translations and to the director: t = n_a dW/dF_a, m = n_a dW/dD_a (per unit reference
/// length). At an edge point the gradients are the direct ones (b = g, f = F).
void finite_rotation_edge_reaction(const ShellPointGeometry& G, const double (&R)[shell_strains],
                                   const double (&normal)[2], Vec3& t, Vec3& m);

/// The change of (t, m) for a unit change of dof `c` of particle `n`, the resultants changing by
/// dR (the section tangent times the strain row of that dof).
void finite_rotation_edge_reaction_change(const ShellPointGeometry& G,
                                          const double (&R)[shell_strains],
                                          const double (&dR)[shell_strains],
                                          const double (&normal)[2], const ShellNodeAtPoint& n,
                                          int c, Vec3& dt, Vec3& dm);

}  // namespace efg
