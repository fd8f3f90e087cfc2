// Mixed u-p for nearly incompressible solids: a constant pressure per pressure cell (a vertex
// patch of background cells, or one background cell: discretization/PressureCells), condensed
// cell by cell (the cell pressure is local, so its equation is solved on the cell).
//
// Small strain, Herrmann's functional with the deviatoric/volumetric split of the linear elastic
// law (Hughes, "The Finite Element Method", 2000, sec. 4.4; Simo & Hughes 1998, sec. 4.2):
//
//   Pi(u, p) = integral mu dev eps : dev eps + integral p div u - integral p^2 / (2 kappa) - W_ext,
//
// with u^h meshfree and p^h constant on each pressure cell c. Stationarity in p_c gives
// p_c = kappa theta_c, theta_c = b_c . d the cell's average dilatation (discretization/
// CellSmoothing), so the condensed internal force and tangent are
//
//   f_I += V_c kappa theta_c b_cI,      K_IJ += V_c kappa b_cI (x) b_cJ,
//
// beside the deviatoric part, which the solid operator integrates at its own points with the
// law's deviatoric constants (model/MaterialLaws: lambda = -2 mu / 3). One constraint per cell
// (not one per integration point) is what relieves volumetric locking; the cell's dilatation is
// the divergence theorem on its boundary, so constant pressures pass the patch test. The mean
// stress of the part is kappa theta_c; the output pressure is its negative (compression
// positive, as LS-DYNA reports it). Parts without formulation mixed_up have no entry here, and
// a model without any builds no MixedPressure at all (ModelOperators::mixed() is null).
//
// Finite strain (total Lagrangian neo-Hookean parts): the cell's measure is ln J_c of its
// smoothed F_c = I + sum_I d_I (x) b_cI with U(J) = kappa/2 (ln J)^2, so f_I += V_c kappa ln J_c
// g_cI, g_cI = F_c^-T b_cI, and the tangent gains -V_c kappa ln J_c g_Ij g_Ji (docs/mixed.md).
// Host loops over the cells (the solid operator's points run in Kokkos kernels): fine at the
// sizes measured (docs/mixed.md), a kernel when threads need it.
#pragma once

#include <memory>
#include <vector>

#include "operators/BulkTangent.hpp"
#include "operators/CouplingGraph.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

class MixedPressure {
 public:
  /// Null when no part of the model is mixed_up.
  static std::unique_ptr<MixedPressure> build(const Model& model, const SolidOperator& solid);
  MixedPressure(const Model& model, const SolidOperator& solid);

  /// Couplings of every cell (all pairs of the particles its average reaches).
  void add_couplings(CouplingGraph& graph) const;
  /// f += the cells' volumetric forces at d (overlap vectors).
  void add_internal_force(const Vector& d_overlap, Vector& f_overlap) const;
  /// K += the cells' volumetric stiffness at d; `bulk`: its rank-one part V kappa g (x) g at
  /// kappa or at kappa_0 (the bulk split's relieved matrix, operators/BulkTangent.hpp).
  void add_tangent(const Vector& d_overlap, FEMatrix& K,
                   BulkTangent bulk = BulkTangent::full) const;
  /// Volumetric energy of this rank's cells, sum V_c U(J_c) (small strain: V_c kappa theta_c^2/2).
  double strain_energy(const Vector& d_overlap) const;

  /// Explicit stages: the bulk viscosity of the cells (von Neumann & Richtmyer; the form of
  /// LS-DYNA's *CONTROL_BULK_VISCOSITY), a pressure on compressing cells only,
  ///   q_c = rho l_c (quadratic l_c theta'_c^2 - linear c_c theta'_c)   for theta'_c < 0,
  /// with theta'_c = b_c . v, l_c = V_c^(1/dim) and c_c = sqrt((kappa + 4 mu / 3) / rho) the bulk
  /// wave speed: f += -V_c q_c b_c at velocities v (overlap). It damps the ringing a sudden impact
  /// leaves at the highest (cell-scale) frequencies, which central differences never damp.
  void add_bulk_viscosity(const Vector& v_overlap, double linear, double quadratic,
                          Vector& f_overlap) const;

  /// The iterative path's split of the bulk stiffness (operators/BulkSplit.hpp): every part's
  /// kappa = kappa_0 + kappa_1, kappa_0 = relieved_bulk_modulus(kappa, mu) (nu_0 = 1/4). True when
  /// some part has kappa_1 > 0.
  bool has_bulk_excess() const;
  /// kappa_0 of model part p (0 when it is not mixed).
  double bulk_reference(std::size_t part) const;
  /// A global id of every cell of this rank (cell_count() of them, in order), and of pressure
  /// cell `group` of model part `part`: the mixed parts' groups numbered one after another.
  void bulk_group_ids(long long* gid) const;
  long long bulk_group_id(std::size_t part, std::size_t group) const;
  /// The state of the split's rows g_c: F_c^-T b_c at d (finite strain; small strain: b_c). The
  /// cells' tangent is V kappa (g (x) g - ln J_c g_Ij g_Ji); its rank-one part above kappa_0 is
  /// split off, the other term (of the size of the pressure) stays in A. Before the three below.
  void bulk_state(const Vector& d_overlap) const;
  /// The saddle point of the bulk excess (operators/BulkSplit.hpp), over this rank's cells of all
  /// mixed parts in order: their count, q_c = V_c kappa_1 (g_c . x) (D_1 B x), y += sum_c q_c
  /// g_c (B^T q), and the Schur complement's diagonal 1 + kappa_1 / M_0, M_0 = kappa_0 + 4 mu / 3.
  std::size_t cell_count() const;
  void bulk_excess_pressures(const Vector& x_overlap, double* q) const;
  void add_cell_forces(const double* q, Vector& y_overlap) const;
  void bulk_schur_diagonal(double* s) const;
  /// V_c kappa_1 of every cell (D_1's diagonal).
  void bulk_weights(double* w) const;

  /// Whether model part p carries a pressure, and its bulk modulus.
  bool mixed(std::size_t part) const { return index_[part] >= 0; }
  double bulk_modulus(std::size_t part) const;
  /// The pressure of every owned cell of model part p (mixed), compression positive: -kappa
  /// theta_c (small strain), -U'(J_c) = -kappa ln J_c / J_c (finite strain, Cauchy).
  std::vector<double> cell_pressures(std::size_t part, const Vector& d_overlap) const;
  /// theta_c of every owned cell of model part p (mixed), in CellAverages order.
  std::vector<double> cell_dilatations(std::size_t part, const Vector& d_overlap) const;
  /// Pressure at every owned particle (overlap order of the owned nodes; 0 for particles of no
  /// mixed part): the volume-weighted mean of the pressures of the pressure cells around it
  /// (those whose background cells hold it as a node; collective).
  std::vector<double> particle_pressures(const Vector& d_overlap) const;
  /// The same on the overlap nodes (owned then ghost particles), for interpolation with the
  /// shape functions of a point (probes): collective.
  std::vector<double> overlap_pressures(const Vector& d_overlap) const;

 private:
  struct Part {
    std::size_t model_part = 0;
    double kappa = 0;
    double kappa0 = 0, kappa_excess = 0, schur = 1;  // kappa_0, kappa_1, 1 + kappa_1 / M_0
    std::vector<std::size_t> groups;                 // each cell's pressure cell (group)
    // Each group's global id (operators/BulkSplit): the whole mesh's index of its lowest cell,
    // unique over the parts and the same on every rank, also on a part of a distributed read.
    std::vector<long long> group_id;
    mutable std::vector<double> excess_g;  // g_c at the split's state (finite strain), as bbar
    double density = 0, wave_speed = 0;    // rho, sqrt((kappa + 4 mu / 3) / rho); 0 without density
    std::vector<double> volume;            // V_c x thickness (2D)
    std::vector<double> length;  // l_c = V_c^(1/dim) (without thickness), the bulk viscosity's
    std::vector<std::size_t> offsets;
    std::vector<int> node;     // overlap node of each entry
    std::vector<double> bbar;  // dim per entry
    std::vector<std::size_t> cell;
    bool finite = false;  // total Lagrangian: U(J) of the cell's smoothed F
  };
  const std::vector<double>& excess_rows(const Part& p) const {
    return p.finite ? p.excess_g : p.bbar;
  }
  [[noreturn]] void report_inverted(const Part& p, std::size_t c) const;
  const Model& model_;
  int dim_;
  std::vector<int> index_;  // model part -> parts_ entry, -1 when not mixed
  std::vector<Part> parts_;
};

}  // namespace efg
