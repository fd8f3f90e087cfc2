// The element-free solid operators of a model: internal force f_int(d), its tangent K(d) and the
// strain energy, from every part's integration points. Shared by the implicit and the explicit
// drivers (one function computes the internal force for both). Vectors are Tpetra vectors on the
// overlap dof map (owned then ghost particles); callers import d and export-add f.
#pragma once

#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <vector>

#include "model/MaterialLaws.hpp"
#include "model/MaterialStates.hpp"
#include "model/Model.hpp"
#include "operators/CouplingGraph.hpp"
#include "operators/SolidKernels.hpp"

namespace efg {

using Vector = Tpetra::Vector<>;
using FEMatrix = Tpetra::FECrsMatrix<>;

class SolidOperator {
 public:
  /// `graph` must contain the couplings of the model's points (see add_point_couplings).
  explicit SolidOperator(const Model& model);

  /// Couplings of every integration point (all pairs of its particles).
  void add_point_couplings(CouplingGraph& graph) const;

  /// f += f_int(d). Throws NumericalError naming the point and particle when det F <= 0.
  void add_internal_force(const Vector& d_overlap, Vector& f_overlap) const;
  /// Adds K(d) to a matrix in assembly mode (overlap rows, overlap-dof columns).
  void add_tangent(const Vector& d_overlap, FEMatrix& K) const;
  /// c += the row bounds c_I of K(d) on every dof of I (operators/StiffnessBound.hpp):
  /// x^T K x <= sum c_I x_Ii^2 for every x, so lambda_max(M^-1 K) <= max c / m.
  void add_stiffness_row_bound(const Vector& d_overlap, Vector& c_overlap) const;
  /// The largest |L_ij| of L = grad_X(delta) F(d)^-1, the gradient of the displacement field
  /// `delta` (overlap) in the configuration of the displacements d (overlap), over this rank's
  /// points of finite-strain parts (not eroded): the strain a change of the displacements by
  /// delta makes there, for the stable step's re-estimates (a small-strain part's tangent,
  /// plastic points probed elastically, does not change with strain). In the current
  /// configuration, not the reference one: a foam crushed to a stretch of 0.1 stiffens by 44 %
  /// (1 / stretch^2) over a reference strain of 0.02, a current strain of 0.2. A point with
  /// det F <= 0 counts as strained without limit (1e300).
  double largest_gradient(const Vector& delta_overlap, const Vector& d_overlap) const;
  /// Eroded points of this rank.
  long long eroded_points() const;
  /// The small-strain validity check of this rank's small-strain points: throws NumericalError
  /// naming the point when det(I + grad u) <= 0 (particles passed through each other, which a
  /// small-strain formulation cannot represent) at `time`; returns the largest |sym H|.
  double check_small_strain(const Vector& d_overlap, double time) const;
  /// Per part, for path-dependent parts only (others: empty): per integration point its mesh
  /// node (SCNI and nodal integration) and history_columns values, the Cauchy stress (row major),
  /// the effective plastic strain and the erosion flag at the committed state.
  static constexpr std::size_t history_columns = 11;
  /// Each point's history columns, with the particle it is (node) or whose domain it is a
  /// piece of (domain, weighted by the piece's volume), -1 for neither.
  struct HistoryOutput {
    std::vector<LocalIndex> node, domain;
    std::vector<double> weight;
    std::vector<double> values;  // points x history_columns
  };
  std::vector<HistoryOutput> history_output(const Vector& d_overlap) const;
  /// Energy (stored + dissipated, at failure) of this rank's eroded points.
  double eroded_energy() const;
  /// Strain energy of this rank's points (sum over ranks for the total).
  double strain_energy(const Vector& d_overlap) const;

  /// The mesh node of every integration point of part p (SCNI and nodal: its particle; Gauss:
  /// -1), in the order of the part's material states.
  const std::vector<LocalIndex>& point_nodes(std::size_t part) const { return parts_[part].node; }
  /// Overlap node index of every particle of part p (cloud order).
  const std::vector<int>& overlap_node(std::size_t part) const { return parts_[part].overlap_node; }
  int dimension() const { return dim_; }

  /// History of the path-dependent parts: force evaluations write its trial states; the drivers
  /// commit them when a step is accepted and set the step time (rate-dependent laws).
  MaterialStates& history() const { return history_; }

 private:
  struct PartData {
    DevicePoints device;
    // Pass-1 scratch (SolidKernels.hpp), allocated on first use: force terms per entry, and A per
    // point once a tangent is asked for.
    mutable DeviceView<double**> term;
    mutable DeviceView<double**> tangent;
    std::vector<int> overlap_node;
    std::size_t points = 0;
    std::size_t slot_count = 0;  // entries of the point table
    std::string name;
    std::vector<double> x;           // point coordinates, for messages
    std::vector<LocalIndex> node;    // the particle of each point (SCNI, nodal), -1 for Gauss
    std::vector<LocalIndex> domain;  // subcells: the particle whose domain holds the piece
    std::vector<double> weight;      // subcells: the pieces' volumes
    bool small_strain = true;
  };
  /// The part's device data with the current step time.
  DevicePoints device(const PartData& p) const {
    DevicePoints d = p.device;
    d.material.step_time = history_.step_time();
    if (history_.elastic_probe() && d.material.plastic) {  // MaterialStates::elastic_probe
      d.material.j2 = physics::without_yield(d.material.j2);
      d.material.foam_params = physics::without_yield(d.material.foam_params);
      d.material.ldfoam_params = physics::without_yield(d.material.ldfoam_params);
    }
    return d;
  }
  void report_inversion(const PartData& part, int point) const;
  std::string point_location(const PartData& part, int point) const;
  /// For every part: pass1(dimension tag, point policy, part, inverted), inverted points
  /// reported, then gather(dimension tag, node policy, part).
  template <class Pass1, class Gather>
  void for_each_part(const Pass1& pass1, const Gather& gather) const;

  int dim_;
  mutable MaterialStates history_;
  std::size_t overlap_nodes_ = 0;
  std::vector<PartData> parts_;
};

}  // namespace efg
