// The peer of issue 12's speed target: the Timoshenko cantilever (Timoshenko & Goodier; L = 48,
// D = 12, E = 3e7, nu = 0.3, P = 1000, plane stress) with Q2 finite elements and a direct solver
// (deal.II 9.4 from Debian, UMFPACK), as efg's verification scene poses it: the exact displacement
// on x = 0, the exact traction on x = L. Prints, per level (4 n x n cells), the dofs, the relative
// energy-norm error sqrt(int (sigma_h - sigma) : (eps_h - eps)) / sqrt(int sigma : eps) and the
// seconds in process from the mesh to the solution (mesh, dofs, constraints, sparsity, assembly,
// factorization and solve; the error integration is not timed), best of `repeats` runs.
//   q2_beam DEGREE REPEATS N...      e.g. q2_beam 2 3 4 8 16 32
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace dealii;

namespace {

constexpr double kL = 48, kD = 12, kE = 3e7, kNu = 0.3, kP = 1000, kI = kD * kD * kD / 12;
constexpr double kLambda = kE * kNu / (1 - kNu * kNu), kMu = kE / (2 * (1 + kNu));  // plane stress

// Timoshenko & Goodier's displacement (the same closed form as efg's src/model/ExactSolutions).
class ExactDisplacement : public Function<2> {
 public:
  ExactDisplacement() : Function<2>(2) {}
  double value(const Point<2>& X, const unsigned int c) const override {
    const double x = X[0], y = X[1];
    if (c == 0)
      return -kP * y / (6 * kE * kI) * ((6 * kL - 3 * x) * x + (2 + kNu) * (y * y - kD * kD / 4));
    return kP / (6 * kE * kI) *
           (3 * kNu * y * y * (kL - x) + (4 + 5 * kNu) * kD * kD * x / 4 + (3 * kL - x) * x * x);
  }
};

// The exact stress: sigma_xx = -P (L - x) y / I, sigma_xy = P / (2 I) (D^2 / 4 - y^2).
SymmetricTensor<2, 2> exact_stress(const Point<2>& X) {
  SymmetricTensor<2, 2> s;
  s[0][0] = -kP * (kL - X[0]) * X[1] / kI;
  s[0][1] = kP / (2 * kI) * (kD * kD / 4 - X[1] * X[1]);
  return s;
}

SymmetricTensor<2, 2> stress_of(const SymmetricTensor<2, 2>& eps) {
  SymmetricTensor<2, 2> s = 2 * kMu * eps;
  s[0][0] += kLambda * trace(eps);
  s[1][1] += kLambda * trace(eps);
  return s;
}

SymmetricTensor<2, 2> strain_of(const SymmetricTensor<2, 2>& s) {  // plane stress compliance
  SymmetricTensor<2, 2> e;
  e[0][0] = (s[0][0] - kNu * s[1][1]) / kE;
  e[1][1] = (s[1][1] - kNu * s[0][0]) / kE;
  e[0][1] = s[0][1] / (2 * kMu);
  return e;
}

struct Level {
  unsigned int dofs = 0;
  double error = 0, seconds = 0;
};

Level solve(unsigned int degree, unsigned int n) {
  const auto start = std::chrono::steady_clock::now();
  Triangulation<2> tria;
  // colorize: boundary id 0 on x = 0, 1 on x = L
  GridGenerator::subdivided_hyper_rectangle(tria, {4 * n, n}, Point<2>(0, -kD / 2),
                                            Point<2>(kL, kD / 2), true);
  const FESystem<2> fe(FE_Q<2>(degree), 2);
  DoFHandler<2> dofs(tria);
  dofs.distribute_dofs(fe);
  AffineConstraints<double> constraints;
  VectorTools::interpolate_boundary_values(dofs, 0, ExactDisplacement(), constraints);
  constraints.close();
  DynamicSparsityPattern dsp(dofs.n_dofs());
  DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
  SparsityPattern pattern;
  pattern.copy_from(dsp);
  SparseMatrix<double> K(pattern);
  Vector<double> f(dofs.n_dofs()), u(dofs.n_dofs());
  const QGauss<2> quadrature(degree + 1);
  const QGauss<1> face_quadrature(degree + 1);
  FEValues<2> values(fe, quadrature, update_gradients | update_JxW_values);
  FEFaceValues<2> face_values(fe, face_quadrature,
                              update_values | update_quadrature_points | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int per_cell = fe.n_dofs_per_cell();
  FullMatrix<double> k(per_cell, per_cell);
  Vector<double> r(per_cell);
  std::vector<types::global_dof_index> indices(per_cell);
  std::vector<SymmetricTensor<2, 2>> eps(per_cell);
  for (const auto& cell : dofs.active_cell_iterators()) {
    k = 0;
    r = 0;
    values.reinit(cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q) {
      for (unsigned int i = 0; i < per_cell; ++i)
        eps[i] = values[displacement].symmetric_gradient(i, q);
      for (unsigned int i = 0; i < per_cell; ++i) {
        const auto s = stress_of(eps[i]);
        for (unsigned int j = 0; j < per_cell; ++j) k(i, j) += (s * eps[j]) * values.JxW(q);
      }
    }
    for (const auto& face : cell->face_iterators())
      if (face->at_boundary() && face->boundary_id() == 1) {
        face_values.reinit(cell, face);
        for (unsigned int q = 0; q < face_quadrature.size(); ++q) {
          const auto t = exact_stress(face_values.quadrature_point(q)) * Tensor<1, 2>({1.0, 0.0});
          for (unsigned int i = 0; i < per_cell; ++i)
            r(i) += face_values[displacement].value(i, q) * t * face_values.JxW(q);
        }
      }
    cell->get_dof_indices(indices);
    constraints.distribute_local_to_global(k, r, indices, K, f);
  }
  SparseDirectUMFPACK direct;
  direct.initialize(K);
  direct.vmult(u, f);
  constraints.distribute(u);
  Level level;
  level.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  level.dofs = dofs.n_dofs();
  // The energy-norm error, not timed.
  const QGauss<2> fine(degree + 3);
  FEValues<2> error_values(fe, fine,
                           update_gradients | update_quadrature_points | update_JxW_values);
  std::vector<SymmetricTensor<2, 2>> eps_h(fine.size());
  double error = 0, energy = 0;
  for (const auto& cell : dofs.active_cell_iterators()) {
    error_values.reinit(cell);
    error_values[displacement].get_function_symmetric_gradients(u, eps_h);
    for (unsigned int q = 0; q < fine.size(); ++q) {
      const auto sigma = exact_stress(error_values.quadrature_point(q));
      const auto e = strain_of(sigma);
      error += (stress_of(eps_h[q] - e) * (eps_h[q] - e)) * error_values.JxW(q);
      energy += (sigma * e) * error_values.JxW(q);
    }
  }
  level.error = std::sqrt(error / energy);
  return level;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: q2_beam DEGREE REPEATS N...\n");
    return 2;
  }
  const auto degree = static_cast<unsigned int>(std::atoi(argv[1]));
  const int repeats = std::atoi(argv[2]);
  std::printf("cells,dofs,energy_error,seconds\n");
  for (int a = 3; a < argc; ++a) {
    const auto n = static_cast<unsigned int>(std::atoi(argv[a]));
    Level best;
    for (int k = 0; k < repeats; ++k) {
      const auto level = solve(degree, n);
      if (k == 0 || level.seconds < best.seconds) best = level;
    }
    std::printf("%ux%u,%u,%.6e,%.6f\n", 4 * n, n, best.dofs, best.error, best.seconds);
  }
  return 0;
}
