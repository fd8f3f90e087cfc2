// The internal force is the gradient of the strain energy and the tangent the derivative of the
// internal force (central differences), assembled in parallel on 1 to 3 ranks.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>

#include <cmath>

#include "operators/SolidOperator.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

std::string scene_text(const char* element, const char* lower, const char* upper, const char* cells,
                       const char* model, const char* formulation, const char* integration) {
  return std::string("mesh:\n  generate: {element: ") + element + ", lower: " + lower +
         ", upper: " + upper + ", cells: " + cells + ", perturbation: 0.25, seed: 4}\n" +
         "parts:\n  - {name: body, blocks: [block_1], material: m, section: {formulation: " +
         formulation + ", integration: " + integration + ", dilation: 1.6}}\n" +
         "materials:\n  - {name: m, model: " + model +
         ", youngs_modulus: 100, poissons_ratio: 0.3}\n";
}

struct Fixture {
  Model model;
  std::unique_ptr<SolidOperator> op;
  Teuchos::RCP<Tpetra::Import<>> import;
  Teuchos::RCP<Tpetra::Export<>> export_;

  explicit Fixture(const std::string& text) {
    const auto comm = Tpetra::getDefaultComm();
    model = build_model(comm, parse_scene(text, "operator_test.yaml"));
    op = std::make_unique<SolidOperator>(model);
    import = Teuchos::rcp(new Tpetra::Import<>(model.maps.owned_dofs, model.maps.overlap_dofs));
    export_ = Teuchos::rcp(new Tpetra::Export<>(model.maps.overlap_dofs, model.maps.owned_dofs));
  }
  // A smooth displacement field as generalized values, by global dof id.
  Vector displacement(double amplitude) const {
    Vector d(model.maps.owned_dofs);
    auto v = d.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto gids = model.maps.owned_dofs->getNodeElementList();
    for (long i = 0; i < gids.size(); ++i)
      v(static_cast<std::size_t>(i), 0) =
          amplitude * std::sin(0.7 * static_cast<double>(gids[i]) + 0.3);
    return d;
  }
  Vector overlap(const Vector& owned) const {
    Vector o(model.maps.overlap_dofs);
    o.doImport(owned, *import, Tpetra::INSERT);
    return o;
  }
  Vector force(const Vector& d) const {
    Vector f_overlap(model.maps.overlap_dofs), f(model.maps.owned_dofs);
    op->add_internal_force(overlap(d), f_overlap);
    f.doExport(f_overlap, *export_, Tpetra::ADD);
    return f;
  }
  double energy(const Vector& d) const {
    const double mine = op->strain_energy(overlap(d));
    double total = 0;
    Teuchos::reduceAll(*model.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM, mine,
                       Teuchos::outArg(total));
    return total;
  }
};

class Operators : public ::testing::TestWithParam<std::tuple<int, const char*, const char*>> {};

TEST_P(Operators, ForceIsEnergyGradientAndTangentIsForceDerivative) {
  const auto [dim, model_name, integration] = GetParam();
  const bool finite = std::string(model_name) == "neo_hookean";
  const auto text = dim == 2
                        ? scene_text("quad4", "[0, 0]", "[2, 1]", "[8, 4]", model_name,
                                     finite ? "total_lagrangian" : "small_strain", integration)
                        : scene_text("hex8", "[0, 0, 0]", "[2, 1, 1]", "[4, 2, 2]", model_name,
                                     finite ? "total_lagrangian" : "small_strain", integration);
  Fixture fx(text);
  const auto d = fx.displacement(0.02);
  const auto f = fx.force(d);
  // Energy gradient along a few global dofs.
  const auto comm = fx.model.maps.owned_dofs->getComm();
  const double h = 1e-6;
  const auto total_dofs = static_cast<long long>(fx.model.maps.owned_dofs->getGlobalNumElements());
  double worst = 0, scale = 0;
  for (long long gid : {0LL, 7LL, total_dofs / 2, total_dofs - 1}) {
    Vector dp(d, Teuchos::Copy), dm(d, Teuchos::Copy);  // Tpetra copies are shallow otherwise
    const auto lid = fx.model.maps.owned_dofs->getLocalElement(gid);
    double fk = 0;
    if (lid != Teuchos::OrdinalTraits<int>::invalid()) {
      dp.sumIntoLocalValue(lid, h);
      dm.sumIntoLocalValue(lid, -h);
      fk = f.getLocalViewHost(Tpetra::Access::ReadOnly)(static_cast<std::size_t>(lid), 0);
    }
    double fk_all = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, fk, Teuchos::outArg(fk_all));
    const double fd = (fx.energy(dp) - fx.energy(dm)) / (2 * h);
    worst = std::max(worst, std::abs(fd - fk_all));
    scale = std::max(scale, std::abs(fk_all));
  }
  EXPECT_LT(worst, 1e-6 * std::max(scale, 1.0)) << "force vs energy";

  // Tangent times a direction vs the central difference of the force.
  FEMatrix K(Teuchos::rcp_const_cast<FEGraph>([&] {
    CouplingGraph graph(fx.model.maps.overlap_nodes->getNodeNumElements());
    fx.op->add_point_couplings(graph);
    return graph.build(fx.model.maps);
  }()));
  // Assemble twice, as Newton iterations do: the refill must replace the old values everywhere,
  // including the owned rows that received other ranks' ghost contributions.
  for (int pass = 0; pass < 2; ++pass) {
    K.beginAssembly();
    K.setAllToScalar(0.0);
    fx.op->add_tangent(fx.overlap(d), K);
    K.endAssembly();
  }
  const auto v = fx.displacement(1.0);
  Vector Kv(fx.model.maps.owned_dofs);
  K.apply(v, Kv);
  Vector dp(d, Teuchos::Copy), dm(d, Teuchos::Copy);
  dp.update(h, v, 1.0);
  dm.update(-h, v, 1.0);
  auto diff = fx.force(dp);
  diff.update(-1.0 / (2 * h), fx.force(dm), 1.0 / (2 * h));
  diff.update(-1.0, Kv, 1.0);
  EXPECT_LT(diff.normInf(), 1e-6 * Kv.normInf()) << "tangent vs force";
}

INSTANTIATE_TEST_SUITE_P(Materials, Operators,
                         ::testing::Combine(::testing::Values(2, 3),
                                            ::testing::Values("linear_elastic", "neo_hookean"),
                                            ::testing::Values("scni", "gauss")));

// A rejected Newton iterate or a cut-back load step (issue 15): force and tangent evaluations
// at a trial displacement write only the trial history, so the committed history of a J2 part
// stays bit for bit what the accepted step left, and the force at the accepted displacement is
// reproduced bit for bit after the rejected evaluations (the implicit driver relies on both).
TEST(History, RejectedEvaluationsLeaveTheCommittedStateBitIdentical) {
  for (const char* formulation : {"small_strain", "total_lagrangian"}) {
    SCOPED_TRACE(formulation);
    Fixture fx(std::string("mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [2, 1], "
                           "cells: [8, 4], perturbation: 0.25, seed: 4}\n"
                           "parts:\n  - {name: body, blocks: [block_1], material: m, section: "
                           "{formulation: ") +
               formulation +
               ", integration: scni, dilation: 1.6}}\n"
               "materials:\n  - {name: m, model: j2_plasticity, youngs_modulus: 100, "
               "poissons_ratio: 0.3, yield_stress: 0.2, hardening_modulus: 5}\n");
    auto& history = fx.op->history();
    ASSERT_TRUE(history.any());
    const auto host = [&] {
      const auto& view = history.part(0).committed;
      auto copy = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
      return std::vector<double>(copy.data(), copy.data() + copy.size());
    };
    const auto force_values = [&](const Vector& d) {
      const auto f = fx.force(d);
      const auto v = f.getLocalViewHost(Tpetra::Access::ReadOnly);
      return std::vector<double>(v.data(), v.data() + v.extent(0));
    };
    const auto initial = host();
    const auto accepted = fx.displacement(0.01);
    force_values(accepted);
    history.commit();  // the accepted (plastic) step
    const auto committed = host();
    ASSERT_NE(committed, initial) << "the accepted step must be plastic for the test to mean much";
    const auto f_before = force_values(accepted);

    // Rejected iterates: three times further, force and tangent (the trial history changes).
    const auto rejected = fx.displacement(0.03);
    const auto f_rejected = force_values(rejected);
    FEMatrix K(Teuchos::rcp_const_cast<FEGraph>([&] {
      CouplingGraph graph(fx.model.maps.overlap_nodes->getNodeNumElements());
      fx.op->add_point_couplings(graph);
      return graph.build(fx.model.maps);
    }()));
    K.beginAssembly();
    fx.op->add_tangent(fx.overlap(rejected), K);
    K.endAssembly();
    ASSERT_NE(f_rejected, f_before);

    EXPECT_TRUE(host() == committed) << "a rejected evaluation changed the committed history";
    EXPECT_TRUE(force_values(accepted) == f_before)
        << "the force at the accepted displacement changed after a rejected evaluation";
  }
}

}  // namespace
}  // namespace efg
