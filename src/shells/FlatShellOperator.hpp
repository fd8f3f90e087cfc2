// Linear flat Reissner-Mindlin shells (plates with membrane action) on a 2D model: the parts of a
// 2D scene are the mid-surface in the x-y plane, each particle carries five generalized dofs
// (u, v, w, theta_x, theta_y; shells/PlateStrains.hpp), the part's thickness is the shell's.
//
// Stiffness (SCNI; Chen et al. 2001 for membrane and bending, Wang & Chen 2004 for the shear):
//   K = sum_L a_L B(L)^T S B(L),  S = diag(A, D, k_s G t I)  (physics MindlinSection)
// over the nodal integration points L (weights a_L the nodal areas), with the smoothed gradients
// for the membrane and bending rows and the direct gradients for the shear rows. A pressure q
// (force per area along +z) gives f_(I,w) = sum_L a_L phi_I(X_L) q, consistent with the same
// nodal quadrature. Shells are a formulation module of their own beside SolidOperator (a solid
// scene builds none of this); flat, elastic or J2 through the thickness, in implicit (Newton:
// fill_tangent, drivers/ShellStaticProblem) and explicit stages; with `section.formulation:
// total_lagrangian` the kinematics are the finite rotations of shells/FiniteRotation.hpp
// (implicit stages), the tangent then adding the geometric stiffness.
#pragma once

#include <Tpetra_Export.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include <array>
#include <atomic>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "materials/J2Plasticity.hpp"
#include "materials/MindlinSection.hpp"
#include "model/Model.hpp"
#include "parallel/DofMaps.hpp"
#include "shells/FiniteRotation.hpp"
#include "shells/PlateStrains.hpp"
#include "shells/ShellMetric.hpp"
#include "shells/ShellSectionResponse.hpp"

namespace efg {

class ShellConstraints;

class FlatShellOperator {
 public:
  using Matrix = Tpetra::FECrsMatrix<>;
  using Vector = Tpetra::Vector<>;
  /// Pressure (force per area) of part p at x.
  using Pressure = std::function<double(std::size_t part, const double* x)>;

  /// Every part of the 2D model is a shell of its elastic material (E, nu): with parts[].shell
  /// its thickness, thickness points and shear stabilization; otherwise the part's thickness
  /// and `thickness_points` Gauss points through it, `shear_stabilization` the alpha of
  /// with_stabilized_shear (0: none).
  explicit FlatShellOperator(const Model& model, int thickness_points = 2,
                             double shear_stabilization = 0.1);

  /// How many shell operators this process has built: a solid scene builds none (tested).
  static long long instances() { return instances_; }

  const DofMaps& maps() const { return maps_; }
  /// The elastic section of part p where its thickness is t.
  /// (Per point and evaluation: no Gauss rule rebuilt here. The part's uniform thickness has its
  /// section kept; another t scales the unit-thickness one, A ~ t, D ~ t^3, k_s G t ~ t.)
  physics::MindlinSection section(std::size_t part, double t) const {
    if (t == uniform_thickness_[part]) return uniform_section_[part];
    auto s = unit_section_[part];
    for (auto& row : s.membrane)
      for (double& v : row) v *= t;
    for (auto& row : s.bending)
      for (double& v : row) v *= t * t * t;
    s.shear *= t;
    return s;
  }
  /// The section of part p where the particle spacing is h and the thickness t (its shear
  /// stabilized).
  physics::MindlinSection section_at(std::size_t part, double h, double t) const {
    return physics::with_stabilized_shear(section(part, t), t, h, alpha_[part]);
  }
  /// The thickness of part p at a point of shape functions phi over overlap particles `nodes`:
  /// sum phi_I t_I of the particles' thickness (shells/ShellThickness.hpp).
  double thickness_at(std::size_t part, const int* nodes, const double* phi, std::size_t n) const {
    if (uniform_thickness_[part] > 0) return uniform_thickness_[part];  // exactly, no round-off
    double t = 0;
    for (std::size_t k = 0; k < n; ++k)
      t += phi[k] * node_thickness_[part][static_cast<std::size_t>(nodes[k])];
    return t;
  }
  /// The thickness t_I of overlap particle `node` of part p.
  double node_thickness(std::size_t part, int node) const {
    return node_thickness_[part][static_cast<std::size_t>(node)];
  }

  /// K on the owned dofs (fill complete), with the constraints' edge terms and the rows of
  /// constrained dofs replaced by their collocation rows (ShellConstraints): the tangent at
  /// d = 0 (elastic parts: the stiffness).
  Teuchos::RCP<Matrix> stiffness(const ShellConstraints& constraints) const;
  /// A matrix on the couplings of the points and of the constraints (no values yet).
  Teuchos::RCP<Matrix> create_matrix(const ShellConstraints& constraints) const;
  /// K(d) = d(f_int + edge terms)/dd with the constrained rows replaced by their collocation
  /// rows, refilled in place (the implicit Newton's Jacobian). J2 parts: the consistent section
  /// tangent (shells/ShellSectionResponse.hpp), the layers' trial states written.
  /// With `follower`, the residual's load stiffness -d f_follower/dd is added (nonsymmetric).
  void fill_tangent(const Vector& d_owned, const ShellConstraints& constraints, Matrix& K,
                    const Pressure* follower = nullptr) const;
  /// The section law of part p where the particle spacing is h (elastic with its stabilized
  /// shear, or J2 through the thickness).
  ShellSectionLaw section_law(std::size_t part, double h, double t) const {
    return {section_at(part, h, t), j2_[part] ? &*j2_[part] : nullptr, t, layers_[part]};
  }
  /// Doubles of J2 history per integration point of part p (0 for elastic parts).
  std::size_t history_size(std::size_t part) const {
    return j2_[part] ? static_cast<std::size_t>(layers_[part]) * physics::j2_state::count : 0;
  }
  /// The committed J2 history of the edge points of a support's node set (ShellConstraints),
  /// kept here so that every stage's constraints continue it; `size` doubles, zero at first.
  std::vector<double>& edge_history(const std::string& node_set, std::size_t size) const {
    auto& h = edge_history_[node_set];
    if (h.size() != size) h.assign(size, 0.0);
    return h;
  }
  /// f_(I,w) += sum_L a_L phi_I(X_L) q(X_L) (owned dofs).
  void add_pressure(const Pressure& q, Vector& f_owned) const;
  /// A follower pressure (finite rotations): f_I += sum_L a_L phi_I(X_L) q(X_L) f1 x f2 on the
  /// translations, f_a the direct gradients of the mid-surface map at the point (f1 x f2 dA is
  /// the deformed area vector: the pressure acts per deformed area along the deformed normal).
  void add_follower_pressure(const Pressure& q, const Vector& d_owned, Vector& f_owned) const;
  /// The physical values u^h(X_J) = sum_I phi_I(X_J) d_I of every owned particle (5 per
  /// particle, in the order of maps().owned_nodes).
  std::vector<double> physical_values(const Vector& d_owned) const;
  /// The resultants (N_xx, N_yy, N_xy, M_xx, M_yy, M_xy, Q_x, Q_y) of every owned particle
  /// (8 per particle, in the order of maps().owned_nodes): the section law of its integration
  /// point's strains (smoothed membrane and bending strains, i.e. the means over its nodal cell;
  /// the shear strain at the particle, with the stabilized shear stiffness the solve used).
  std::vector<double> resultants(const Vector& d_owned) const;
  /// The stresses (xx, yy, xy) on the top, the middle and the bottom of every owned particle's
  /// section (9 per particle, in the order of maps().owned_nodes): elastic parts N / t + 6 M /
  /// t^2, N / t, N / t - 6 M / t^2 (z = t / 2, 0, -t / 2); J2 parts the stresses of the
  /// outermost Gauss layers and of the middle one (the mean of the two middle ones of an even
  /// rule), committed states.
  std::vector<double> surface_stresses(const Vector& d_owned) const;
  /// The current thickness t (1 + mean eps_zz) of every owned particle's section (in the order
  /// of maps().owned_nodes): plane stress sets eps_zz; an elastic section's mean over the
  /// thickness is -nu / (1 - nu) (eps_xx + eps_yy) of its membrane strains (the bending part is
  /// odd in z), a J2 section's the Gauss mean of its layers' own eps_zz (committed states;
  /// isochoric plastic flow thins the sheet).
  std::vector<double> thickness(const Vector& d_owned) const;
  /// Strain energy 1/2 d^T K d of this rank's points (without constraints); for J2 parts the
  /// internal energy of the committed state (stored + dissipated, through the thickness) and
  /// the elastic shear energy.
  double strain_energy(const Vector& d_owned) const;

  /// Finite rotations (shells/FiniteRotation.hpp): every part's section formulation is
  /// total_lagrangian. The rotation dofs are then the rotation since the last accepted step.
  bool finite_rotations() const { return finite_; }
  /// A part has a curved reference (parts[].shell.reference, shells/ShellReference.hpp): its
  /// particles start from the mapped surface (an offset from the flat mesh) with its frames.
  bool curved() const { return curved_; }
  /// The rotation (about the reference frame's t1, t2 there) that turns the reference frame into
  /// the current one at a point of shape functions phi over overlap particles `nodes`
  /// (shells/FiniteRotation.hpp frame_rotation: well defined up to and at pi).
  template <class View>
  void physical_rotation(const int* nodes, const double* phi, std::size_t n, const View& d,
                         double& rx, double& ry) const;
  /// Accepts the rotations of d: every particle's frame is turned by its rotation dofs
  /// (exponential map) and those dofs are set to 0 in d (translations stay totals).
  void accept_rotations(Vector& d_owned) const;
  /// One particle's translations and director at the overlap values d (finite rotations).
  template <class View>
  ShellNodeAtPoint node_at(int node, const double* b, const double* g, double phi,
                           const View& d) const {
    const auto k = static_cast<std::size_t>(node) * shell_dofs_per_node;
    Vec3 u = {d(k, 0), d(k + 1, 0), d(k + 2, 0)};
    if (curved_)  // the reference surface's offset from the flat mesh
      for (std::size_t c = 0; c < 3; ++c) u[c] += offset_[static_cast<std::size_t>(node)][c];
    return {b, g, phi, u,
            node_director(frames_[static_cast<std::size_t>(node)], d(k + shell_rx, 0),
                          d(k + shell_ry, 0))};
  }

  /// J2 parts (explicit stages; physics ShellSectionJ2): internal_force evaluates trial states
  /// from the committed ones, commit_state() accepts the last evaluation's. While the elastic
  /// probe is on the layers answer elastically from the committed state (the stable step's
  /// stiffness probes; MaterialStates' elastic probe for solids).
  bool plastic() const;
  /// Part p is J2 (its sections have layers with a history).
  bool plastic_part(std::size_t part) const { return j2_[part].has_value(); }
  void commit_state() const;
  void set_elastic_probe(bool on) const { elastic_probe_ = on; }
  /// The largest effective plastic strain through the thickness of every owned particle (its
  /// own integration point), committed state; 0 for elastic parts.
  std::vector<double> plastic_strain() const;

  /// f = K d without the constraints, assembled point by point (sum_L a_L B(L)^T S B(L) d), no
  /// matrix: the internal force of explicit stages (owned dofs, overwritten). With `edges`, their
  /// edge traction terms are added before the export (the implicit residual; one import, one
  /// export).
  void internal_force(const Vector& d_owned, Vector& f_owned,
                      const ShellConstraints* edges = nullptr) const;
  /// f_owned += the sum over the ranks of their overlap contributions f_overlap.
  void add_overlap(const Vector& f_overlap, Vector& f_owned) const {
    // (an export replaces the entries a rank owns itself: sum into a zeroed vector first)
    Vector sum(maps_.owned_dofs);
    sum.doExport(f_overlap, *exporter_, Tpetra::ADD);
    f_owned.update(1.0, sum, 1.0);
  }
  /// The owned values imported to the overlap map (owned then ghost particles).
  void to_overlap(const Vector& d_owned, Vector& d_overlap) const {
    d_overlap.doImport(d_owned, *importer_, Tpetra::INSERT);
  }
  /// The lumped mass of every owned dof (shells/ShellMass.hpp): translations the row sums
  /// rho t sum_L a_L phi_I(X_L) of the consistent mass, rotations that mass times
  /// max(t^2, h^2) / 12 (rotary inertia scaled up to the particle spacing h). Throws InputError
  /// when a part's material has no density, NumericalError for a mass <= 0.
  Vector lumped_mass() const;

 private:
  /// One integration point: its weight and, per particle reaching it, the particle's overlap
  /// node index, smoothed gradient b, direct gradient g and value phi.
  struct Point {
    double weight = 0, spacing = 0;
    double thickness = 0;  ///< its particle's (shells/ShellThickness.hpp)
    std::array<double, 2> x{};
    int owned_row = 0;  ///< the particle's index in maps().owned_nodes
    std::vector<int> node;
    std::vector<double> b, g, phi;  // 2, 2, 1 per particle
    /// finite rotations: the strains of the reference state (0 on a flat reference), which the
    /// point's strains are measured from
    std::array<double, shell_strains> reference{};
    /// curved references: the strains' metric (the weight is then the surface area)
    ShellMetric metric;
  };
  /// The kinematics of a point with finite rotations: its particles and point quantities.
  using FinitePoint = FiniteRotationPoint;
  template <class View>
  void finite_point(const Point& p, const View& d, FinitePoint& fp) const;
  /// The point's strains from fp's kinematics, measured from its reference state, in the
  /// surface's frame.
  void finite_strains(const Point& p, const FinitePoint& fp, double (&e)[shell_strains]) const {
    finite_rotation_strains(fp.geometry, e);
    for (std::size_t i = 0; i < shell_strains; ++i) e[i] -= p.reference[i];
    if (curved_) strains_to_surface(p.metric, e);
  }
  /// Curved references: offsets, frames and the points' reference strains.
  void build_reference();
  /// B of particle a of a point (finite rotations: of fp's kinematics).
  void strain_rows(const Point& p, std::size_t a, const FinitePoint* fp,
                   double (&B)[shell_strains][shell_dofs_per_node]) const;
  /// K_L = a_L (B^T S B + G) of one point (5n x 5n, row major), S its section tangent, G the
  /// geometric stiffness of the resultants R (finite rotations: fp not null).
  std::vector<double> point_stiffness(const Point& p, const SectionTangent& S,
                                      const FinitePoint* fp = nullptr,
                                      const double* R = nullptr) const;
  Vector to_overlap(const Vector& d_owned) const;
  /// Adds -d/dd of the point's follower pressure force (cols: the point's overlap dofs).
  template <class View>
  void add_follower_stiffness(std::size_t part, const Point& p, const View& d, const Pressure& q,
                              const std::vector<int>& cols, Matrix& K) const;
  /// The direct gradients f_1, f_2 of the mid-surface map x = X + u at a point.
  template <class View>
  void surface_tangents(const Point& p, const View& d, Vec3 (&f)[2]) const;
  /// f_owned = the sum of the overlap contributions of every rank.
  void export_add(const Vector& f_overlap, Vector& f_owned) const;
  /// The 8 generalized strains of a point at the overlap values d.
  template <class View>
  void point_strains(const Point& p, const View& d, double (&e)[shell_strains]) const;
  /// The strains e and resultants R = (N, M, Q) of a point of part `part`.
  template <class View>
  void point_resultants(std::size_t part, const Point& p, const View& d, double (&e)[shell_strains],
                        double (&R)[shell_strains]) const;

  /// N, M, Q of a point of part `part` at its strains e (J2 parts: the layers' trial states
  /// written to trial_; while the elastic probe is on, elastic from the committed states).
  void strain_resultants(std::size_t part, const Point& p, const double (&e)[shell_strains],
                         double (&R)[shell_strains]) const;

  const Model& model_;
  DofMaps maps_;
  // built once: an Import/Export plan is collective setup work, not per evaluation
  Teuchos::RCP<const Tpetra::Import<>> importer_;
  Teuchos::RCP<const Tpetra::Export<>> exporter_;
  std::vector<int> layers_;                               ///< thickness points per part
  std::vector<std::optional<physics::J2Parameters>> j2_;  ///< per part: J2 when plastic
  /// per part: j2_state::count doubles per thickness point per integration point
  mutable std::vector<std::vector<double>> committed_, trial_;
  mutable bool elastic_probe_ = false;
  bool finite_ = false, curved_ = false;
  mutable std::vector<ShellFrame> frames_;    ///< per overlap particle (finite rotations)
  std::vector<ShellFrame> reference_frames_;  ///< per overlap particle: the frames at the start
  std::vector<Vec3> offset_;  ///< per overlap particle: reference position - flat mesh position
  mutable std::map<std::string, std::vector<double>> edge_history_;
  static inline std::atomic<long long> instances_{0};
  std::vector<double> youngs_, poisson_, alpha_;  ///< per part
  /// per part, per overlap particle: its thickness (the scene's number or expression at it, or
  /// the mean of its cells' thickness attributes)
  std::vector<std::vector<double>> node_thickness_;
  std::vector<double> uniform_thickness_;  ///< per part: its one thickness, or 0 when it varies
  /// per part: the elastic section at unit thickness and at the uniform one (section())
  std::vector<physics::MindlinSection> unit_section_, uniform_section_;
  std::vector<std::vector<Point>> points_;  ///< per part
};

template <class View>
void FlatShellOperator::physical_rotation(const int* nodes, const double* phi, std::size_t n,
                                          const View& d, double& rx, double& ry) const {
  // the interpolated reference and current frames (each particle's frame turned by its
  // rotation dofs), and the rotation between them
  ShellFrame then{{}, {}, {}}, now{{}, {}, {}};
  for (std::size_t k = 0; k < n; ++k) {
    const auto lid = static_cast<std::size_t>(nodes[k]);
    ShellFrame current = frames_[lid];
    rotate_frame(current, d(lid * shell_dofs_per_node + shell_rx, 0),
                 d(lid * shell_dofs_per_node + shell_ry, 0));
    for (std::size_t c = 0; c < 3; ++c) {
      then.t1[c] += phi[k] * reference_frames_[lid].t1[c];
      then.t3[c] += phi[k] * reference_frames_[lid].t3[c];
      now.t1[c] += phi[k] * current.t1[c];
      now.t3[c] += phi[k] * current.t3[c];
    }
  }
  frame_rotation(then, now, rx, ry);
}

}  // namespace efg
