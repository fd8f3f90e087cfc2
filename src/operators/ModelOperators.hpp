// The operators every stage driver shares, built once per run: the solid internal force (the
// same function for the implicit residual and the explicit step), the external loads, the exact
// solution when the scene names one, and the owned <-> overlap transfers.
#pragma once

#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>

#include <memory>

#include "operators/ExternalLoads.hpp"
#include "operators/MixedPressure.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

class ModelOperators {
 public:
  explicit ModelOperators(const Model& model);

  const Model& model() const { return model_; }
  const SolidOperator& solid() const { return solid_; }
  /// The cell pressures of the mixed_up parts; null when the model has none.
  const MixedPressure* mixed() const { return mixed_.get(); }
  const ExternalLoads& loads() const { return loads_; }
  const ExactSolution* exact() const { return exact_.get(); }

  /// Owned values to the overlap map (owned then ghost particles).
  void to_overlap(const Vector& owned, Vector& overlap) const {
    overlap.doImport(owned, *import_, Tpetra::INSERT);
  }
  /// Overlap contributions summed into the owned map (owned = sum, overwritten).
  void to_owned(const Vector& overlap, Vector& owned) const {
    owned.putScalar(0.0);
    owned.doExport(overlap, *export_, Tpetra::ADD);
  }
  /// f_int(d) on the owned dofs: the one internal-force evaluation of both drivers.
  void internal_force(const Vector& d_owned, Vector& f_owned) const;
  /// The same on overlap vectors (f += f_int(d)): the solid's points and the mixed cells.
  void add_internal_force(const Vector& d_overlap, Vector& f_overlap) const;
  /// K += K_int(d) (assembly mode), and the couplings it needs; `bulk`: the mixed cells' bulk
  /// stiffness at kappa or at the bulk split's kappa_0 (operators/BulkTangent.hpp).
  void add_tangent(const Vector& d_overlap, FEMatrix& K,
                   BulkTangent bulk = BulkTangent::full) const;
  void add_couplings(CouplingGraph& graph) const;
  /// f_owned = the bulk viscosity forces at velocities v (owned; zero without mixed parts).
  void bulk_viscosity(const Vector& v_owned, double linear, double quadratic,
                      Vector& f_owned) const;
  /// c_owned = the row bounds of K(d) (SolidOperator::add_stiffness_row_bound, summed over the
  /// particles' points on every rank): lambda_max(M^-1 K) <= max c / m. False (c untouched) when
  /// the model has mixed u-p parts, whose cell pressures the bound does not cover.
  bool stiffness_row_bound(const Vector& d_owned, Vector& c_owned) const;
  /// The largest |d delta / dx| over every rank's points of finite-strain parts, x the
  /// configuration of the displacements d (both owned): the strain of a change delta of the
  /// displacements there (SolidOperator::largest_gradient).
  double largest_strain_change(const Vector& delta_owned, const Vector& d_owned) const;
  /// Eroded points on every rank.
  long long eroded_points() const;
  /// Stored energy of this rank's points and cells (sum over ranks for the total).
  double strain_energy(const Vector& d_overlap) const;

 private:
  const Model& model_;
  std::unique_ptr<ExactSolution> exact_;
  SolidOperator solid_;
  std::unique_ptr<MixedPressure> mixed_;
  ExternalLoads loads_;
  Teuchos::RCP<Tpetra::Import<>> import_;
  Teuchos::RCP<Tpetra::Export<>> export_;
  mutable Vector d_overlap_, f_overlap_;
};

}  // namespace efg
