// The discrete inf-sup constant of the mixed u-p pairing (issue 17): meshfree displacements
// (linear basis, SCNI, dilation 2) against one pressure per background cell, on the unit square
// with u = 0 on its whole boundary (the Stokes setting, where the constant pressure is the one
// spurious mode and is left out):
//
//   beta_h^2 = min over p with sum_c V_c p_c = 0 of  (B A^-1 B^T p . p) / (M p . p),
//
// B_cI = V_c b_cI the cells' divergence (discretization/CellSmoothing), M = diag(V_c), A the
// stiffness of a(v, v) = integral eps(v) : eps(v) (E = 1, nu = 0) with the transformation rows of
// the boundary condition (the constrained test functions). Dense: S = M^-1/2 B A^-1 B^T M^-1/2,
// symmetrized (the transformation rows make A slightly nonsymmetric), the mean-free subspace by
// projection, LAPACK's eigenvalues. A pairing that locks or checkerboards shows beta_h -> 0 under
// refinement (Q1/P0 finite elements: beta_h ~ h); the test asks that it does not fall by more
// than 20 % per level (Brezzi & Fortin 1991, ch. II), apart from the spurious modes it counts.
#include <gtest/gtest.h>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "discretization/CellSmoothing.hpp"
#include "drivers/StaticProblem.hpp"
#include "model/Model.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

// Eigenvalues below this are counted as spurious pressure modes (beta_h^2 of the others: 0.4-0.5).
constexpr double kSpurious = 1e-2;

struct InfSup {
  int below = 0;      // eigenvalues under kSpurious, the projected-out constant included
  double beta = 0.0;  // square root of the smallest eigenvalue above it
};

InfSup inf_sup_constant(int n, double perturbation) {
  std::ostringstream text;
  text << "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [1, 1], cells: [" << n << ", "
       << n << "], perturbation: " << perturbation << "}\n"
       << "parts:\n  - {name: square, blocks: [block_1], material: m, section: {dilation: 2.0}}\n"
       << "materials:\n  - {name: m, model: linear_elastic, youngs_modulus: 1.0, "
          "poissons_ratio: 0.0}\n"
       << "boundary_conditions:\n";
  for (const char* side : {"xmin", "xmax", "ymin", "ymax"})
    text << "  - {name: " << side << ", type: displacement, node_set: " << side
         << ", x: 0, y: 0}\n";
  text << "stages:\n  - {name: s, driver: implicit, end_time: 1}\n";
  const auto comm = Tpetra::getDefaultComm();
  const auto model = build_model(comm, parse_scene(text.str(), "inf_sup.yaml"));
  auto ops = std::make_shared<ModelOperators>(model);
  StaticProblem problem(ops);
  problem.begin_stage({}, 0.0);
  Vector d(model.maps.owned_dofs);
  auto K = problem.create_matrix();
  problem.jacobian(d, *K);

  const int dofs = static_cast<int>(model.maps.owned_dofs->getNodeNumElements());
  const auto nd = static_cast<std::size_t>(dofs);
  std::vector<double> A(nd * nd, 0.0);
  const auto local = K->getLocalMatrixHost();
  for (int r = 0; r < dofs; ++r)
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
      A[static_cast<std::size_t>(local.graph.entries(k)) * nd + static_cast<std::size_t>(r)] =
          local.values(k);  // column major

  // The constrained rows (replaced by the transformation's u^h(X_J) = 0): their right-hand
  // sides stay 0, so the columns of A^-1 B^T are test functions with u = 0 on the boundary.
  std::vector<char> constrained(nd, 0);
  const auto& part = model.parts[0];
  const auto cells = cell_averages(
      model.mesh, part.cloud,
      owned_cells(model.mesh, *part.part, model.partition.owner, model.partition.rank));
  const auto& node = ops->solid().overlap_node(0);
  const int m = static_cast<int>(cells.size());
  const auto nm = static_cast<std::size_t>(m);
  // Bt = B^T (dofs x cells, column major), zero in the constrained rows.
  std::vector<double> Bt(nd * nm, 0.0);
  for (std::size_t c = 0; c < nm; ++c)
    for (auto k = cells.gradients.offsets[c]; k < cells.gradients.offsets[c + 1]; ++k) {
      const auto particle =
          static_cast<std::size_t>(node[static_cast<std::size_t>(cells.gradients.particles[k])]);
      for (std::size_t i = 0; i < 2; ++i)
        Bt[c * nd + particle * 2 + i] = cells.volume[c] * cells.gradients.values[k * 2 + i];
    }
  // The rows the boundary condition replaced: the nodes of the boundary node sets.
  for (const char* side : {"xmin", "xmax", "ymin", "ymax"})
    for (auto g : model.mesh.find_node_set(side)->nodes) {
      const auto lid = model.maps.owned_nodes->getLocalElement(static_cast<GlobalOrdinal>(g));
      for (std::size_t i = 0; i < 2; ++i) constrained[static_cast<std::size_t>(lid) * 2 + i] = 1;
    }
  std::vector<double> X = Bt;
  for (std::size_t c = 0; c < nm; ++c)
    for (std::size_t r = 0; r < nd; ++r)
      if (constrained[r]) X[c * nd + r] = 0.0;
  Teuchos::LAPACK<int, double> lapack;
  std::vector<int> pivots(nd);
  int info = 0;
  lapack.GESV(dofs, m, A.data(), dofs, pivots.data(), X.data(), dofs, &info);
  EXPECT_EQ(info, 0);
  // T = M^-1/2 B X M^-1/2, symmetrized, then P T P with P the projection off M^1/2 1.
  std::vector<double> T(nm * nm, 0.0), w(nm);
  double total = 0;
  for (std::size_t c = 0; c < nm; ++c) total += cells.volume[c];
  for (std::size_t c = 0; c < nm; ++c) w[c] = std::sqrt(cells.volume[c] / total);
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < nm; ++b) {
      double v = 0;
      for (std::size_t r = 0; r < nd; ++r) v += Bt[a * nd + r] * X[b * nd + r];
      T[b * nm + a] = v / std::sqrt(cells.volume[a] * cells.volume[b]);
    }
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < a; ++b)
      T[b * nm + a] = T[a * nm + b] = 0.5 * (T[b * nm + a] + T[a * nm + b]);
  std::vector<double> Tw(nm, 0.0);
  double wTw = 0;
  for (std::size_t a = 0; a < nm; ++a) {
    for (std::size_t b = 0; b < nm; ++b) Tw[a] += T[b * nm + a] * w[b];
    wTw += w[a] * Tw[a];
  }
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < nm; ++b)
      T[b * nm + a] += -w[a] * Tw[b] - Tw[a] * w[b] + wTw * w[a] * w[b];
  std::vector<double> eig(nm), work(1);
  int lwork = -1;
  lapack.SYEV('N', 'U', m, T.data(), m, eig.data(), work.data(), lwork, &info);
  lwork = static_cast<int>(work[0]);
  work.resize(static_cast<std::size_t>(lwork));
  lapack.SYEV('N', 'U', m, T.data(), m, eig.data(), work.data(), lwork, &info);
  EXPECT_EQ(info, 0);
  // eig[0..]: the projected-out constant (0), then the spurious modes (below kSpurious), then
  // beta_h^2.
  InfSup out;
  for (double e : eig) {
    if (e < kSpurious) {
      ++out.below;
    } else {
      out.beta = std::sqrt(e);
      break;
    }
  }
  return out;
}

// Measured (tests print them): unperturbed beta_h = 0.698 / 0.664 / 0.634 on 4 / 8 / 16 cells per
// side, 10 % perturbation 0.679 / 0.647 / 0.614; besides the constant, one more mode lies at
// |lambda| = 1e-5..7e-4 (falling with h on the regular grids): the checkerboard (its eigenvector's
// correlation with (-1)^(i+j) measured 0.994-0.99999), spurious for Q1/P0 finite elements in this
// enclosed setting too. It is not counted in beta_h and must stay the only one.
TEST(MixedInfSup, ConstantStaysBoundedUnderRefinement) {
  for (double perturbation : {0.0, 0.1}) {
    std::vector<InfSup> levels;
    for (int n : {4, 8, 16}) levels.push_back(inf_sup_constant(n, perturbation));
    std::ostringstream o;
    o << "perturbation " << perturbation << ": beta_h =";
    for (const auto& l : levels) o << " " << l.beta << " (" << l.below << " modes below)";
    std::cout << o.str() << "\n";
    for (std::size_t k = 0; k < levels.size(); ++k) {
      EXPECT_LE(levels[k].below, 2) << o.str();  // the constant and the checkerboard
      EXPECT_GT(levels[k].beta, 0.5) << o.str();
      if (k > 0) {
        EXPECT_GE(levels[k].beta, 0.8 * levels[k - 1].beta) << o.str();
      }
    }
  }
}

}  // namespace
}  // namespace efg
