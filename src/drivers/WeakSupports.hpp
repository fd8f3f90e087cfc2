// Displacement conditions enforced weakly in explicit stages: a condition with method nitsche or
// penalty acts through its boundary integrals (operators/EssentialConditions) as a force on the
// body, instead of prescribing the generalized dofs of its particles (drivers/PrescribedMotion).
// With non-interpolating shape functions that prescription imposes the wrong values: the
// physical displacement u^h(X) = sum phi_I(X) d_I of the constrained particles, and the free
// particles near the boundary, feel it (docs/boundary_conditions.md, "Explicit stages").
//
// Symmetric Nitsche (Nitsche 1971; Fernandez-Mendez & Huerta 2004) is consistent, so the
// quasi-static limit of an explicit run is the implicit Nitsche solution, and symmetric, so it
// adds a stiffness the stable-step estimate sees (StableTimeStep adds its exact product to the
// solid's): central differences stay stable for dt below 2 / omega_max
// of M^-1 (K + K_Nitsche). The force's work is external (support) work in the energy balance.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "operators/EssentialConditions.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

class WeakSupports {
 public:
  /// Builds the boundary points only when the stage has a weakly enforced displacement
  /// condition (a scene builds only what it needs).
  /// `transformation_traction` (the explicit stage's key of that name): the transformation
  /// conditions' boundary traction term acts too (their generalized dofs stay prescribed by
  /// drivers/PrescribedMotion), so that the stage's equations on the free dofs are the implicit
  /// stages' and an implicit equilibrium stays put.
  WeakSupports(const ModelOperators& ops, const std::string& stage,
               bool transformation_traction = false);

  /// True when a displacement condition with method nitsche or penalty (or any, with
  /// `transformation_traction`) acts in `stage`.
  static bool wanted(const Scene& scene, const std::string& stage,
                     bool transformation_traction = false);
  bool active() const { return conditions_ != nullptr; }

  /// The prescribed values at `time` (value x curve; a condition without a curve holds its
  /// value from the start).
  void set_time(double time);
  /// r(d): the boundary terms as a resistance (added to f_int; the force on the body is -r),
  /// owned dofs; also kept as last() and its per-condition totals for the reactions.
  const Vector& resistance(const Vector& d_owned);
  /// The boundary terms' stiffness at d as a product y += K(d) x, the transformation traction
  /// term by its symmetric part (exactly symmetric; the stable-step estimate). The product
  /// keeps the points' tangents at d and the overlap vectors of this object.
  std::function<void(const Vector& x_owned, Vector& y_owned)> stiffness_at(
      const Vector& d_owned) const;
  const Vector& last() const { return last_; }
  /// The force each condition applies to the body at the last resistance(), summed over ranks
  /// (collective), with the implicit drivers' sign.
  std::vector<std::array<double, 3>> reactions() const;
  /// The step is accepted at d: plastic boundary points keep their state, and those of the
  /// transformation conditions (which act on the generalized values here) are evaluated at d
  /// when an implicit stage after this one continues their history.
  void commit_history(const Vector& d_owned);

 private:
  const ModelOperators& ops_;
  std::unique_ptr<EssentialConditions> conditions_;
  std::unique_ptr<EssentialConditions> tracked_;  ///< transformation conditions of plastic parts
  Vector last_;
  mutable Vector d_overlap_, r_overlap_, x_overlap_, scratch_;
  std::vector<std::array<double, 3>> totals_;
};

}  // namespace efg
