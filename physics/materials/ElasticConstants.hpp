// Isotropic elastic constants from Young's modulus and Poisson's ratio (e.g. Belytschko, Liu,
// Moran, "Nonlinear Finite Elements for Continua and Structures", 2nd ed., box 5.1). Plain
// functions: no Trilinos, callable from Kokkos kernels.
#pragma once

namespace efg::physics {

struct ElasticConstants {
  double lambda;  ///< first Lame parameter
  double mu;      ///< shear modulus
  double kappa;   ///< bulk modulus
};

/// 3D and plane strain. Requires E > 0 and -1 < nu < 0.5 (checked at input).
constexpr ElasticConstants elastic_constants(double youngs_modulus, double poissons_ratio) {
  const double e = youngs_modulus, nu = poissons_ratio;
  return {e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu)), e / (3 * (1 - 2 * nu))};
}

/// Plane stress: the in-plane response of a thin sheet is that of a 3D material with
/// lambda* = 2 lambda mu / (lambda + 2 mu) (sigma_zz = 0 eliminated).
constexpr ElasticConstants plane_stress_constants(double youngs_modulus, double poissons_ratio) {
  const auto c = elastic_constants(youngs_modulus, poissons_ratio);
  const double lambda_star = 2 * c.lambda * c.mu / (c.lambda + 2 * c.mu);
  return {lambda_star, c.mu, lambda_star + 2 * c.mu / 3};
}

}  // namespace efg::physics
