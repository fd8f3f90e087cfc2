// A validated scene: typed, defaults filled in, cross-references checked. Built by read_scene().
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "expressions/Expression.hpp"
#include "mesh/MeshGenerator.hpp"
#include "mesh/RigidSurface.hpp"
#include "mesh/SurfaceChart.hpp"

namespace efg {

enum class Basis { linear, quadratic };
enum class KernelType { cubic_spline, quadratic_spline, quartic_spline };
enum class SupportShape { box, sphere };
enum class SpacingMeasure { cells, edges, neighbors };
enum class Integration { scni, scni_subcells, nodal, gauss };
/// Quadrature on the SCNI facets inside the cells: split (2 Gauss points per 2D segment, 4
/// triangles per 3D facet) or centroid (one point per flat facet, two per warped one);
/// automatic: chosen per part by discretization/SmoothingFacets' facet_rule.
enum class SmoothingQuadrature { automatic, split, centroid };
enum class Formulation { small_strain, total_lagrangian };
/// The fields of a part: displacement only, or displacement and a pressure per background cell
/// (mixed u-p, statically condensed; operators/MixedPressure.hpp).
enum class PartFormulation { displacement, mixed_up };
/// What carries one pressure of a mixed_up part (discretization/PressureCells): a vertex patch of
/// background cells, or each cell.
enum class PressureCellChoice { cell, patch };

/// A scene value that may vary over position and time: a number, or an expression of x, y, z (and
/// t where the key allows it) compiled once (src/expressions).
struct ScalarField {
  double constant = 0;
  std::shared_ptr<const Expression> expression;  ///< null: the constant
  std::string where;  ///< "file:line:col: key.path" of the value, for messages

  bool varies() const { return expression != nullptr; }
  bool uses_time() const { return expression && expression->uses_time(); }
  /// The value at p (3 entries) and time t. Throws InputError naming `where`, the point and the
  /// time when the expression is not finite there (a division by zero, a root of a negative).
  double at(const double* p, double t) const;
  /// Same value definition (number or expression text): conditions sharing a dof must agree.
  bool same_as(const ScalarField& other) const;
};

struct SectionSpec {
  Basis basis = Basis::linear;
  KernelType kernel = KernelType::cubic_spline;
  SupportShape support = SupportShape::box;
  std::vector<double> dilation = {1.5};  ///< one value, or one per direction
  SpacingMeasure spacing = SpacingMeasure::cells;
  bool per_part_support = false;
  /// per_part_support on a rank's part of a mesh read in slices: the part's largest half-width
  /// per direction over the whole mesh (set by model/DistributedMesh; empty otherwise).
  std::vector<double> part_support;
  Integration integration = Integration::scni;
  SmoothingQuadrature smoothing_quadrature = SmoothingQuadrature::automatic;
  int gauss_order = 2;
  Formulation formulation = Formulation::small_strain;
};

/// parts[].shell: the part is a Reissner-Mindlin shell whose mid-surface is its (2D) mesh.
struct ShellSpec {
  /// A number, or an expression of the position (per particle); empty: the mesh's thickness
  /// attributes of the part's blocks (ElementBlock::thickness, averaged at the nodes).
  std::optional<ScalarField> thickness;
  int thickness_points = 2;          ///< Gauss points through the thickness
  double shear_stabilization = 0.1;  ///< alpha of k_s G t t^2 / (t^2 + alpha h^2)
  /// The reference mid-surface X(x, y), Y, Z as expressions of the mesh's (x, y) (a regular
  /// map); empty: the flat mesh itself.
  std::vector<ScalarField> reference;
};

struct PartSpec {
  std::string name;
  std::vector<std::string> blocks;
  std::string material;
  SectionSpec section;
  double thickness = 1.0;
  bool plane_stress = false;
  PartFormulation formulation = PartFormulation::displacement;
  PressureCellChoice pressure_cells = PressureCellChoice::cell;
  std::optional<ShellSpec> shell;  ///< a shell part (src/shells); empty: a solid
};

struct MaterialSpec {
  std::string name;
  std::string model;
  std::optional<double> density;
  std::map<std::string, double> constants;  ///< model constants by key name
  /// A graded Young's modulus E(x, y, z) (elastic laws); constants["youngs_modulus"] then holds
  /// the largest value over the nodes of the material's parts (set by build_model), the
  /// reference the per-point scale E(x)/E_ref is taken against.
  std::optional<ScalarField> youngs_modulus_field;
  std::string hardening_curve;  ///< j2_plasticity: curve of yield stress over plastic strain
  std::string yield_curve;      ///< crushable_foam: curve of yield stress over volumetric strain
  std::string loading_curve;    ///< low_density_foam: nominal stress over nominal strain
  /// A law with history at its integration points (j2_plasticity, crushable_foam,
  /// low_density_foam).
  bool path_dependent() const {
    return model == "j2_plasticity" || model == "crushable_foam" || model == "low_density_foam";
  }
};

/// The stages a condition, load or contact acts in: named ones, or every stage when none are named.
/// A springback stage is an implicit stage whose tools and prescribed motions are not active.
struct ActiveStages {
  std::vector<std::string> names;  ///< empty: every stage
  bool includes(const std::string& stage) const {
    if (names.empty() || stage.empty()) return true;  // "": no particular stage (all)
    for (const auto& n : names)
      if (n == stage) return true;
    return false;
  }
};

struct BoundaryConditionSpec {
  std::string name;
  std::string type;  ///< displacement | velocity
  std::string node_set;
  std::string method;
  std::optional<double> penalty;  ///< alpha of beta = alpha E / h; method default when empty
  std::array<std::optional<ScalarField>, 3> components;
  std::array<std::optional<ScalarField>, 2> rotations;  ///< shells: about x and y
  std::array<bool, 3> from_exact{false, false,
                                 false};  ///< components taken from the exact solution
  std::string curve;                      ///< empty: constant
  ActiveStages stages;
};

struct LoadSpec {
  std::string name;
  std::string type;  ///< traction | pressure | nodal_force | body_force | shell_pressure
  std::string set;   ///< side set or node set; empty for body forces
  std::vector<std::string> parts;
  std::vector<ScalarField> value;  ///< traction, body force, pressure: may vary in x, y, z, t
  bool from_exact = false;  ///< traction or body force from the verification block's exact solution
  bool follower = false;    ///< shell_pressure: along the deformed normal (finite rotations)
  std::array<double, 3> point{0, 0, 0};  ///< shell_point_load: where it acts
  std::string curve;
  ActiveStages stages;
};

struct InitialConditionSpec {
  std::string type;
  std::string node_set;
  std::vector<ScalarField> value;  ///< may vary in x, y, z
};

/// verification.user_solution: an exact solution written as expressions of x, y, z.
struct UserSolutionSpec {
  std::vector<ScalarField> displacement;
  std::vector<ScalarField> stress;      ///< xx, yy, zz, yz, xz, xy (Voigt order); empty: from u
  std::vector<ScalarField> body_force;  ///< empty: zero
};

/// A named point sampled at every record (displacement, strain, stress by MLS interpolation).
struct ProbeSpec {
  std::string name;
  std::array<double, 3> point{0, 0, 0};
};

/// The angle of the segment between two probes (scene/SceneAngles.hpp).
struct AngleSpec {
  std::string name, from, to;
};

/// A node set made by the scene: the nodes of the mesh (or of the node set `within`) inside the
/// axis-aligned box [lower, upper] (LS-DYNA *SET_NODE_GENERAL with BOX): a single pin, an edge.
struct NodeSetSpec {
  std::string name;
  std::vector<double> lower, upper;
  std::string within;  ///< empty: every node of the mesh
};

struct CurveSpec {
  std::string name;
  std::vector<double> time, value;
};

struct RigidWallSpec {
  std::string name;
  std::vector<double> point, normal;
  std::string node_set;  ///< empty: every particle
  double penalty = 0.5;
};

/// A rigid body (analytic shape): fixed, moved by a prescribed velocity, or free (translation
/// under its contact forces).
struct RigidBodySpec {
  std::string name;
  std::string shape;                ///< plane | sphere | cylinder | box | mesh
  std::vector<std::string> blocks;  ///< mesh: the element blocks that make the body
  /// mesh: its surface, volume and centroid, set when the mesh is loaded (model/RigidMeshBlocks)
  std::shared_ptr<const RigidSurface> surface;
  std::vector<double> point, normal;     ///< plane
  std::vector<double> center, axis;      ///< sphere, cylinder (axis: 3D cylinders)
  double radius = 0;                     ///< sphere, cylinder
  std::vector<double> lower, upper;      ///< box (axis-aligned)
  std::string motion;                    ///< fixed | prescribed | free
  std::vector<double> velocity;          ///< initial (free) or prescribed (x curve) velocity
  std::string curve;                     ///< prescribed: scales velocity; empty: constant
  std::vector<std::string> axis_curves;  ///< prescribed: a curve per velocity component
  double mass = 0;                       ///< given (0: none)
  double density = 0;                    ///< given (0: none): mass = density x volume
  double thickness = 1;                  ///< 2D: out-of-plane length of the body (its mass)
  std::vector<double> gravity;           ///< free bodies: a body load per unit mass (empty: none)
  std::vector<double> force;  ///< free bodies: an applied force (blank holder), x curve if any
  /// Free round bodies (2D disc, 3D sphere): the initial angular velocity; given, the body
  /// rotates under the moment of its contact forces (empty: translation only).
  std::vector<double> angular_velocity;
};

/// Penalty contact of the surface particles of deformable parts with a rigid body, or with the
/// surface of other deformable parts (target_parts).
struct ContactSpec {
  std::string name;
  std::string rigid_body;                 ///< empty: contact with target_parts
  std::vector<std::string> target_parts;  ///< deformable surfaces touched (rigid_body empty)
  bool two_way = true;                    ///< target_parts: the other way round too
  std::vector<std::string> parts;
  double penalty = 0.1;  ///< mass rule: k = penalty x m / dt^2 per particle
  /// Explicit stages, rigid bodies: the material rule k = penalty_scale x K A / h (the larger
  /// of the two acts; contact/ContactStiffness.hpp). 0: the mass rule alone.
  double penalty_scale = 1.0;
  /// Explicit stages, rigid bodies: warn once when a particle is deeper than this fraction of
  /// its spacing.
  double penetration_warning = 0.2;
  /// Explicit stages, rigid bodies: a particle inside the body at the run's start stops it
  /// (stop), has that overlap ignored (ignore, LS-DYNA's IGNORE) or pushed out by the penalty
  /// from the first step (push: a deliberate preload).
  std::string initial_penetration = "stop";
  double static_friction = 0, dynamic_friction = 0, decay = 0;
  double damping = 0;             ///< normal viscous damping, fraction of critical per particle
  double implicit_penalty = 100;  ///< implicit stages: beta = implicit_penalty x E / h
  ActiveStages stages;            ///< a springback stage leaves the tools' contacts out
};

/// initial_state: a record of an earlier run's results to start from (a restart).
struct InitialStateSpec {
  std::string file;            ///< resolved path
  std::optional<double> time;  ///< the record's time; empty: the last record
};

struct StageSpec {
  std::string name;
  std::string driver;  ///< implicit | explicit
  double end_time = 1.0;
  std::optional<double> output_interval;
  YAML::Node settings;  ///< the driver's own keys, resolved (defaults filled)
};

struct OutputSpec {
  std::string file;
  std::vector<std::string> fields;
  std::string history;
  std::vector<std::string> history_node_sets;
  bool per_rank_files = false;  ///< files: per_rank (one results file per rank, joined by epu)
};

struct Scene {
  std::string file;       ///< scene file path as given
  std::string directory;  ///< folder of the scene file, for relative paths
  std::string name;       ///< scene file name without folder and extension
  std::string title;
  std::map<std::string, double> parameters;  ///< named constants (parameters:), usable in values
  std::string mesh_file;                     ///< resolved path, empty when generated
  bool distributed_read = false;             ///< mesh.read: distributed (each rank reads its slice)
  std::optional<GeneratorSpec> generator;
  /// mesh.chart: the 2D chart of a shell surface read in 3D, (x, y) of its point X (3 entries);
  /// empty: the projection chart of mesh/SurfaceChart.hpp.
  SurfaceChartMap surface_chart;
  std::vector<GeneratorSpec> more_blocks;  ///< mesh.more_blocks: appended, nodes of their own
  std::vector<PartSpec> parts;
  std::vector<MaterialSpec> materials;
  std::vector<BoundaryConditionSpec> boundary_conditions;
  std::vector<LoadSpec> loads;
  std::vector<InitialConditionSpec> initial_conditions;
  std::optional<InitialStateSpec> initial_state;
  std::vector<CurveSpec> curves;
  std::vector<NodeSetSpec> node_sets;  ///< made by the scene, added to the mesh's own sets
  std::vector<RigidWallSpec> rigid_walls;
  std::vector<RigidBodySpec> rigid_bodies;
  std::vector<ContactSpec> contacts;
  std::vector<StageSpec> stages;
  OutputSpec output;
  YAML::Node verification;                        ///< null when absent
  std::string exact_solution;                     ///< verification.exact_solution, empty when none
  std::optional<UserSolutionSpec> user_solution;  ///< exact_solution "user"
  std::vector<ProbeSpec> probes;
  std::vector<AngleSpec> angles;

  YAML::Node document;  ///< as written, with line marks (for cross-reference messages)
  YAML::Node resolved;  ///< validated, defaults filled (printed by `efg check`)

  const MaterialSpec* find_material(const std::string& name) const;
  const CurveSpec* find_curve(const std::string& name) const;
  /// The largest Poisson's ratio of the parts' materials (0 when none has one): how close to
  /// incompressible the model is (the automatic linear solver choice depends on it).
  double largest_poissons_ratio() const;
  /// True when every part's material is linear elastic (small strain by the scene's rules): the
  /// internal force is then K d with a constant K (one Newton step solves an implicit stage
  /// without contacts; an explicit stage keeps its first stable-step estimate).
  bool every_part_linear_elastic() const;
  /// True when a part is a shell (the run then takes the shell path, src/shells).
  bool has_shells() const {
    for (const auto& p : parts)
      if (p.shell) return true;
    return false;
  }
};

}  // namespace efg
