// Strain-displacement rows of a flat Reissner-Mindlin shell in the x-y plane (mid-surface z = 0):
// the contribution of one particle's five generalized dofs (u, v, w, theta_x, theta_y) to the
// eight generalized strains at an integration point.
//
// Rotations are right-handed about the x and y axes, so a material line along the normal moves
// by u = z theta_y, v = -z theta_x (the normal's rotation beta = (theta_y, -theta_x)):
//
//   membrane  eps   = (du/dx, dv/dy, du/dy + dv/dx)
//   bending   kappa = (d theta_y/dx, -d theta_x/dy, d theta_y/dy - d theta_x/dx)
//   shear     gamma = (dw/dx + theta_y, dw/dy - theta_x)
//
// Membrane and bending strains use the smoothed gradient b_I of the nodal cell (SCNI; Chen et al.
// 2001): they are exact for linear u and theta fields on any particle set. The transverse shear
// uses the particle's own (direct) gradient g_I of the deflection's shape functions and the
// values phi_I at the node: with a quadratic basis a Kirchhoff mode (w quadratic, theta = its
// gradient, linear) has exactly zero shear strain at every node. This is the Kirchhoff mode
// reproducing condition of Wang & Chen (CMAME 193, 2004, 1065-1083) that keeps the thin limit
// free of shear locking.
#pragma once

#include "materials/MindlinSection.hpp"

namespace efg {

enum ShellDof { shell_u = 0, shell_v, shell_w, shell_rx, shell_ry };
inline constexpr int shell_dofs_per_node = 5;
inline constexpr int shell_strains = 8;  ///< eps (3), kappa (3), gamma (2)

/// B[strain][dof] of one particle: b the smoothed gradient, g the direct gradient, phi the value
/// of its shape function at the point.
inline void plate_strain_rows(const double (&b)[2], const double (&g)[2], double phi,
                              double (&B)[shell_strains][shell_dofs_per_node]) {
  for (auto& row : B)
    for (auto& entry : row) entry = 0;
  B[0][shell_u] = b[0];
  B[1][shell_v] = b[1];
  B[2][shell_u] = b[1];
  B[2][shell_v] = b[0];
  B[3][shell_ry] = b[0];
  B[4][shell_rx] = -b[1];
  B[5][shell_ry] = b[1];
  B[5][shell_rx] = -b[0];
  B[6][shell_w] = g[0];
  B[6][shell_ry] = phi;
  B[7][shell_w] = g[1];
  B[7][shell_rx] = -phi;
}

/// S B of one particle: the resultants (N, M, Q) each of its unit dofs produces.
inline void resultant_rows(const physics::MindlinSection& s,
                           const double (&B)[shell_strains][shell_dofs_per_node],
                           double (&SB)[shell_strains][shell_dofs_per_node]) {
  for (int c = 0; c < shell_dofs_per_node; ++c) {
    for (int i = 0; i < 3; ++i) {
      SB[i][c] = SB[3 + i][c] = 0;
      for (int j = 0; j < 3; ++j) {
        SB[i][c] += s.membrane[i][j] * B[j][c];
        SB[3 + i][c] += s.bending[i][j] * B[3 + j][c];
      }
    }
    SB[6][c] = s.shear * B[6][c];
    SB[7][c] = s.shear * B[7][c];
  }
}

}  // namespace efg
