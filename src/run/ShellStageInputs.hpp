// What a shell stage reads of the scene at a time: its supports (the boundary conditions active
// in the stage, their curves' factors at that time), its shell_pressure and shell_edge_load loads.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellBoundary.hpp"
#include "shells/ShellConstraints.hpp"

namespace efg {

/// The displacement and rotation conditions active in `stage`, valued at `time`; a condition
/// without a curve is scaled by `ramp` (implicit load steps: the solids' linear ramp over the
/// first stage, model/Curves.hpp curve_factor).
std::vector<ShellSupport> shell_supports_at(const Scene& scene, const std::string& stage,
                                            double time, double ramp = 1.0);

/// Whether the conditions active in `stage` can prescribe different values at different times
/// (a curve, or an expression of t): explicit stages then re-evaluate them every step.
bool shell_supports_move(const Scene& scene, const std::string& stage);

/// The shell_pressure loads active in `stage`, summed, at `time` (a load without a curve at
/// `ramp` times its value): the dead ones, or with `follower` the follower ones.
FlatShellOperator::Pressure shell_pressure_at(const Model& model, const std::string& stage,
                                              double time, double ramp = 1.0,
                                              bool follower = false);
/// Whether a follower shell_pressure is active in `stage`.
bool has_follower_pressure(const Scene& scene, const std::string& stage);

/// The shell_edge_load line loads and shell_point_load point loads active in a stage: their
/// edge points (the SCNI boundary quadrature of shells/ShellBoundary.hpp) and the points' shape
/// functions (on the rank that evaluates each point, model/PointOwner) found once, the loads
/// added at any time.
class ShellLineAndPointLoads {
 public:
  ShellLineAndPointLoads(const Model& model, const FlatShellOperator& op, const std::string& stage);
  /// f_(I,c) += sum_e l_e phi_I(X_e) s q_c(X_e, t) for the line loads and phi_I(X_P) s Q_c(t)
  /// for the point loads (owned dofs), s the load's curve factor at `time` (without a curve:
  /// `ramp`). Components: forces along x, y, z, moments about the rotation dofs' axes.
  void add(double time, double ramp, FlatShellOperator::Vector& f_owned) const;
  bool empty() const { return loads_.empty() && points_.empty(); }

 private:
  const Model& model_;
  const FlatShellOperator& op_;
  std::string stage_;
  std::vector<std::pair<const LoadSpec*, std::vector<ShellEdgePoint>>> loads_;
  struct PointLoad {
    const LoadSpec* load;
    std::vector<int> node;  ///< overlap particles reaching the point (this rank: empty unless
                            ///< it evaluates the point)
    std::vector<double> phi;
  };
  std::vector<PointLoad> points_;
};

}  // namespace efg
