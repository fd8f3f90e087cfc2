// Prescribed displacements (method transformation, the default) and velocities in explicit
// stages, on the generalized dofs of the condition's particles (nitsche and penalty
// displacement conditions act weakly instead: drivers/WeakSupports): velocity conditions set v_I, displacement conditions move d_I by the
// change of the prescribed value over each step (so a stage that starts from an implicit
// solution, whose generalized values at a clamp are not zero, does not jump). With non-interpolating shape functions this imposes the values on
// the generalized dofs, not exactly on the physical displacement at the nodes (LS-DYNA's EFG
// uses a boundary transformation); for fixed ends and uniform motions of a whole set the two
// agree.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/Curves.hpp"
#include "model/Model.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

class PrescribedMotion {
 public:
  /// The conditions active in `stage` (a condition's stages list; all when it names none).
  PrescribedMotion(const Model& model, const std::string& stage);

  /// Overwrites the constrained entries of the half-step velocity: the prescribed velocity at
  /// mid-step, or the change of the prescribed displacement from step start to end over dt.
  void constrain_velocity(const LoadFactor& start, const LoadFactor& mid, const LoadFactor& end,
                          double dt, Vector& v_half) const;
  /// Zeroes the constrained entries of an acceleration and sets the constrained velocities
  /// (displacement conditions keep the rate of v_half: the free acceleration must not leak in).
  void constrain_end(const LoadFactor& factor_end, const Vector& v_half, Vector& v,
                     Vector& a) const;
  /// The force the supports apply to hold the prescribed motion, R = -M a_free on the
  /// constrained entries (a_free: the acceleration before constrain_end), 0 elsewhere. Its work
  /// R . dd is external work: a crush driven by prescribed motion puts its energy in that way.
  /// `rows_only`: R's other entries are already zero (a vector only this has written) and are
  /// left alone, sparing a pass over every dof per explicit step.
  void support_force(const Vector& mass, const Vector& a_free, Vector& R,
                     bool rows_only = false) const;
  /// sum over the constrained dofs of m (v_end^2 - v_start^2) / 2, over all ranks (collective):
  /// the kinetic energy the supports give those dofs beyond the free forces' work, which
  /// R = -M a_free accounts. A prescribed velocity that changes (v_x = a t) puts energy in with
  /// a_free = 0; without this share a bar driven that way ended at a 26 % balance error.
  double kinetic_energy_change(const Vector& mass, const Vector& v_start,
                               const Vector& v_end) const;
  /// {R_old . delta, R_new . delta} over the constrained rows alone (collective), each bit for bit
  /// reproducible_dot over every row when R is zero elsewhere (support_force with rows_only
  /// wrote it): the skipped terms are zeros, and the constrained rows' terms are added in the same
  /// blocks in the same order (parallel/ReproducibleSum.hpp). A per-step energy account that
  /// read two whole vectors for a few rows.
  /// The constrained rows (owned dofs), ascending.
  const std::vector<int>& rows() const { return rows_; }
  std::array<double, 2> support_work(const Vector& R_old, const Vector& R_new,
                                     const Vector& delta) const;
  /// The support force summed per boundary condition and direction (collective): the reaction
  /// columns R_<condition>_<axis> of an explicit run, with the implicit drivers' sign (the force
  /// the support applies to the body). A dof named by several conditions counts for the first.
  std::vector<std::array<double, 3>> reactions(const Vector& R) const;

 private:
  struct Dof {
    int row;
    std::size_t condition;
    int direction;
    bool velocity;
    const ScalarField* value;   // the scene's value (a number or an expression of x, y, z, t)
    std::array<double, 3> X{};  // the node's reference position
    std::string curve;
    /// The value at f's time; an expression of t without a curve is not scaled (no ramp).
    double at(const LoadFactor& f) const {
      const double v = value->at(X.data(), f.time());
      return value->uses_time() && curve.empty() ? v : v * f(curve);
    }
  };
  std::vector<Dof> dofs_;
  std::vector<int> rows_;  ///< the constrained rows, ascending
  std::size_t conditions_ = 0;
};

}  // namespace efg
