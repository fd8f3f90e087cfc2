// The response of one shell section to its generalized strains e = (membrane strain, curvature,
// transverse shear; shells/PlateStrains.hpp): the resultants R = (N, M, Q) and, when asked, the
// section tangent S = dR/de (8 x 8). Elastic parts: the Mindlin section (S block diagonal: A, D,
// k_s G t). J2 parts: plane-stress J2 at each Gauss point through the thickness (physics
// ShellSectionJ2), elastic transverse shear; the layer tangent C = dsigma/deps comes from forward
// AD of the layer's update (operators/MaterialTangent.hpp, the algorithmic tangent of Simo &
// Taylor 1985), integrated as the resultants are:
//   dN/deps = sum_k C_k dz_k,  dN/dkappa = dM/deps = sum_k C_k z_k dz_k,
//   dM/dkappa = sum_k C_k z_k^2 dz_k,
// so Newton on an implicit J2 shell converges quadratically (tests: the tangent equals the
// central difference of the internal force).
#pragma once

#include "materials/ShellSectionJ2.hpp"
#include "operators/MaterialTangent.hpp"
#include "shells/PlateStrains.hpp"

namespace efg {

struct ShellSectionLaw {
  physics::MindlinSection elastic;            ///< with the point's stabilized shear
  const physics::J2Parameters* j2 = nullptr;  ///< J2 through the thickness when set
  double thickness = 0;
  int layers = 0;
};

using SectionTangent = double[shell_strains][shell_strains];

/// R from e; for J2 sections the layers' states start from `committed` and are written to
/// `trial` (layers x j2_state::count each). S = dR/de when S is given.
inline void shell_section_response(const ShellSectionLaw& law, const double (&e)[shell_strains],
                                   const double* committed, double* trial,
                                   double (&R)[shell_strains], SectionTangent* S = nullptr) {
  if (S)
    for (auto& row : *S)
      for (auto& v : row) v = 0.0;
  if (!law.j2) {
    double N[3], M[3], Q[2];
    physics::mindlin_resultants(law.elastic, {e[0], e[1], e[2]}, {e[3], e[4], e[5]}, {e[6], e[7]},
                                N, M, Q);
    for (int i = 0; i < 3; ++i) {
      R[i] = N[i];
      R[3 + i] = M[i];
      if (S)
        for (int j = 0; j < 3; ++j) {
          (*S)[i][j] = law.elastic.membrane[i][j];
          (*S)[3 + i][3 + j] = law.elastic.bending[i][j];
        }
    }
    R[6] = Q[0];
    R[7] = Q[1];
  } else if (!S) {
    double N[3], M[3];
    physics::j2_section_resultants(*law.j2, law.thickness, law.layers, {e[0], e[1], e[2]},
                                   {e[3], e[4], e[5]}, committed, trial, 0.0, N, M);
    for (int i = 0; i < 3; ++i) {
      R[i] = N[i];
      R[3 + i] = M[i];
    }
    R[6] = law.elastic.shear * e[6];
    R[7] = law.elastic.shear * e[7];
  } else {
    physics::J2Parameters p = *law.j2;
    p.small_strain = true;
    p.plane_stress = true;
    double xi[physics::max_thickness_points], w[physics::max_thickness_points];
    const int n = physics::thickness_rule(law.layers, xi, w);
    for (int i = 0; i < 6; ++i) R[i] = 0.0;
    constexpr int count = physics::j2_state::count;
    for (int k = 0; k < n; ++k) {
      const double z = 0.5 * law.thickness * xi[k], dz = 0.5 * law.thickness * w[k];
      const double eps[3] = {e[0] + z * e[3], e[1] + z * e[4], e[2] + z * e[5]};
      const double H[2][2] = {{eps[0], 0.5 * eps[2]}, {0.5 * eps[2], eps[1]}};
      double old_state[count], new_state[count] = {}, P[2][2] = {}, A[2][2][2][2] = {},
                               cauchy[3][3];
      for (int s = 0; s < count; ++s) old_state[s] = committed[k * count + s];
      j2_stress_and_tangent<2>(p, H, old_state, 0.0, P, A, new_state,
                               cauchy);  // small strain: true
      for (int s = 0; s < count; ++s) trial[k * count + s] = new_state[s];
      const double sigma[3] = {P[0][0], P[1][1], P[0][1]};
      const int I[3][2] = {{0, 0}, {1, 1}, {0, 1}};
      double C[3][3];  // d sigma_i / d (eps_xx, eps_yy, gamma_xy)
      for (int i = 0; i < 3; ++i) {
        const auto& a = A[I[i][0]][I[i][1]];
        C[i][0] = a[0][0];
        C[i][1] = a[1][1];
        C[i][2] = 0.5 * (a[0][1] + a[1][0]);
      }
      for (int i = 0; i < 3; ++i) {
        R[i] += sigma[i] * dz;
        R[3 + i] += sigma[i] * z * dz;
        for (int j = 0; j < 3; ++j) {
          (*S)[i][j] += C[i][j] * dz;
          (*S)[i][3 + j] += C[i][j] * z * dz;
          (*S)[3 + i][j] += C[i][j] * z * dz;
          (*S)[3 + i][3 + j] += C[i][j] * z * z * dz;
        }
      }
    }
    R[6] = law.elastic.shear * e[6];
    R[7] = law.elastic.shear * e[7];
  }
  if (S) (*S)[6][6] = (*S)[7][7] = law.elastic.shear;
}

/// S B of one particle (B: its strain rows): the resultants each of its unit dofs produces.
inline void tangent_rows(const SectionTangent& S,
                         const double (&B)[shell_strains][shell_dofs_per_node],
                         double (&SB)[shell_strains][shell_dofs_per_node]) {
  for (int i = 0; i < shell_strains; ++i)
    for (int c = 0; c < shell_dofs_per_node; ++c) {
      double v = 0;
      for (int j = 0; j < shell_strains; ++j) v += S[i][j] * B[j][c];
      SB[i][c] = v;
    }
}

}  // namespace efg
