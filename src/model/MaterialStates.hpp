// History variables of path-dependent materials at every integration point of this rank, per
// part: `committed` holds the state at the end of the last accepted step (explicit step, or
// converged implicit load step), `trial` the state the latest force evaluation computed from it.
// Force evaluations never change `committed`, so a rejected Newton iterate or a cut-back load
// step leaves it bit-identical; the drivers call commit() when a step is accepted. One object per
// run, shared by every stage, so the state passes from an explicit stage to an implicit one and
// back. A part whose law keeps no history allocates nothing (a scene without plasticity holds
// no state at all).
#pragma once

#include <cstddef>
#include <vector>

#include "core/DeviceArrays.hpp"
#include "model/MaterialLaws.hpp"
#include "model/Model.hpp"

namespace efg {

class MaterialStates {
 public:
  struct PartStates {
    MaterialLaw law;  ///< the part's law (the operators read it from here)
    int count = 0;    ///< doubles per point (0: none)
    DeviceView<double**> committed, trial;
    /// Graded elastic material: E(x_q)/E_ref per integration point (empty view otherwise).
    DeviceView<double*> modulus_scale;
  };

  /// One block per part of the model, sized by its law, set to the law's initial state.
  explicit MaterialStates(const Model& model);

  const PartStates& part(std::size_t p) const { return parts_[p]; }
  std::size_t parts() const { return parts_.size(); }
  bool any() const;

  /// The accepted step's states become the committed ones.
  void commit();

  /// Time increment of the step being evaluated (rate-dependent laws read it).
  double step_time() const { return step_time_; }
  void set_step_time(double dt) { step_time_ = dt; }

  /// Elastic probes (the explicit stable-step estimate): plastic points answer with their
  /// elastic predictor from the committed state, no return map. The elastic stiffness bounds the
  /// elastoplastic one from above (the elastic wave speed sets the critical step, as in
  /// commercial explicit codes), and differences of it are smooth and symmetric, where
  /// differences across the yield surface are neither (the Lanczos estimate then returned
  /// residual norms of 2-8 % of the eigenvalue that differed between rank counts).
  bool elastic_probe() const { return elastic_probe_; }
  void set_elastic_probe(bool on) { elastic_probe_ = on; }

  /// The committed plastic history of displacement condition c's boundary points on this rank
  /// (operators/EssentialConditions; empty until a set of conditions first stores it). Kept here,
  /// beside the particles' history, so that every stage's conditions, implicit and explicit,
  /// continue one history (a springback stage sees the formed state at a symmetry plane).
  std::vector<double>& boundary_points(std::size_t condition) {
    if (condition >= boundary_.size()) boundary_.resize(condition + 1);
    return boundary_[condition];
  }

 private:
  std::vector<std::vector<double>> boundary_;
  std::vector<PartStates> parts_;
  double step_time_ = 0.0;
  bool elastic_probe_ = false;
};

}  // namespace efg
