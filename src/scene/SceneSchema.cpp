#include "scene/SceneSchema.hpp"

#include "scene/ContactSchema.hpp"
#include "scene/ExactSolutionNames.hpp"
#include "scene/MeshSchema.hpp"
#include "scene/PartSchema.hpp"
#include "scene/ShellSchema.hpp"
#include "scene/StageSchema.hpp"

namespace efg {
namespace {

using namespace schema;

SpecPtr material_spec() {
  auto youngs = real("Young's modulus.", "stress").above(0);
  // Elastic laws may be graded: E an expression of x, y, z (nu fixed).
  auto graded_youngs =
      real(
          "Young's modulus. A number, or an expression of x, y, z for a graded material (lambda "
          "and mu scale with E at every integration point; nu stays; penalties and stable-step "
          "scales take the largest E of the part).",
          "stress")
          .above(0)
          .varying(ExpressionVariables::position);
  auto poisson = real("Poisson's ratio.", "-").above(-1.0).below(0.5);
  return map("A material model. Keys after model depend on the model.")
      .required("name", string("Material name, unique."))
      .required("model",
                choice("Constitutive model.", {"linear_elastic", "neo_hookean", "j2_plasticity",
                                               "crushable_foam", "low_density_foam"}))
      .optional("density",
                real("Mass density (needed by explicit stages).", "mass/length^3").above(0))
      .discriminated_by("model")
      .variant("linear_elastic", {required_key("youngs_modulus", graded_youngs),
                                  required_key("poissons_ratio", poisson)})
      .variant("neo_hookean",
               {required_key("youngs_modulus",
                             real("Small-strain Young's modulus; mu = E/(2(1+nu)); a number or an "
                                  "expression of x, y, z (graded, as for linear_elastic).",
                                  "stress")
                                 .above(0)
                                 .varying(ExpressionVariables::position)),
                required_key("poissons_ratio",
                             real("Small-strain Poisson's ratio; kappa = E/(3(1-2nu)).", "-")
                                 .above(-1.0)
                                 .below(0.5))})
      .variant(
          "j2_plasticity",
          {required_key("youngs_modulus", youngs), required_key("poissons_ratio", poisson),
           required_key("yield_stress",
                        real("Initial yield stress (von Mises).", "stress").above(0)),
           optional_key("hardening_modulus",
                        real("Linear isotropic hardening modulus H: sigma_y = yield_stress + H "
                             "eps_p; 0 (default) is perfect plasticity. Not with "
                             "hardening_curve.",
                             "stress")
                            .at_least(0)),
           optional_key("hardening_curve",
                        string("Name of a curve of yield stress (value) over effective plastic "
                               "strain (time), starting at (0, yield_stress), at most 17 "
                               "points, not decreasing; extended with its last slope.")),
           optional_key("rate_c", real("Cowper-Symonds C: sigma_y x (1 + (eps_p rate / C)^(1/p)); "
                                       "omitted: rate independent.",
                                       "1/time")
                                      .above(0)),
           optional_key("rate_p", real("Cowper-Symonds p (default 1).", "-").above(0)),
           optional_key("failure_strain",
                        real("Erosion (explicit stages only): a particle whose effective plastic "
                             "strain reaches this value carries no stress from then on; its "
                             "mass and motion stay.",
                             "-")
                            .above(0))})
      .variant(
          "crushable_foam",
          {required_key("youngs_modulus",
                        real("Young's modulus of elastic loading and unloading (Hencky); with "
                             "poissons_ratio, also the explicit stable step's stiffness.",
                             "stress")
                            .above(0)),
           required_key("poissons_ratio",
                        real("Elastic Poisson's ratio (crash foams: 0 to 0.1). The plastic "
                             "Poisson's ratio is 0: plastic flow is along the loaded principal "
                             "direction only.",
                             "-")
                            .above(-1.0)
                            .below(0.5)),
           required_key("yield_curve",
                        string("Name of a curve of the compressive yield stress (value, > 0) "
                               "over the volumetric strain 1 - J (time: starting at 0, "
                               "increasing, below 1; at most 32 points); extended beyond its "
                               "last point with its last slope when that rises (densification). "
                               "Each principal Cauchy stress stays >= -yield stress "
                               "(LS-DYNA *MAT_063 LCID; docs/foams.md).")),
           optional_key("tension_cutoff",
                        real("Largest principal Cauchy stress in tension (LS-DYNA TSC); a "
                             "positive value is advisable.",
                             "stress")
                            .at_least(0),
                        "0")})
      .variant(
          "low_density_foam",
          {required_key("youngs_modulus",
                        real("Slope of the nominal stress in tension (linear, LS-DYNA E); also "
                             "the contact's stiffness, so give at least the loading curve's "
                             "largest slope. Poisson's ratio is 0 (no coupling between the "
                             "principal directions).",
                             "stress")
                            .above(0)),
           required_key("loading_curve",
                        string("Name of a curve of the nominal compressive stress (value: from "
                               "0, not decreasing) over the nominal strain 1 - stretch (time: "
                               "from 0, increasing, below 1; at most 32 points) in each "
                               "principal direction; extended beyond its last point with its "
                               "last slope (LS-DYNA *MAT_057 LCID; docs/foams.md).")),
           optional_key("hysteresis",
                        real("HU: the unloading curve is (HU + (1 - HU) (e / e_max)^shape) times "
                             "the loading curve below the largest strain reached e_max; 1 "
                             "unloads on the loading curve (no dissipation).",
                             "-")
                            .above(0)
                            .at_most(1),
                        "1"),
           optional_key("shape",
                        real("SHAPE: the exponent of the unloading factor (larger: unloading "
                             "drops sooner, more dissipation).",
                             "-")
                            .above(0),
                        "1"),
           optional_key("tension_cutoff",
                        real("Largest nominal tensile stress (reversible cap, LS-DYNA TC); "
                             "none when absent.",
                             "stress")
                            .above(0))});
}

std::vector<Key> component_keys(const std::string& what, const std::string& unit) {
  const auto v = ExpressionVariables::position_and_time;
  return {optional_key("x", real(what + " in x.", unit).varying(v)),
          optional_key("y", real(what + " in y.", unit).varying(v)),
          optional_key("z", real(what + " in z (3D only).", unit).varying(v))};
}

SpecPtr boundary_condition_spec() {
  auto keys = [](const std::string& what, const std::string& unit) {
    auto k = component_keys(what, unit);
    k.push_back(optional_key("curve", string("Name of a curve scaling the values over time; see "
                                             "the stage drivers for what happens without one.")));
    k.push_back(optional_key(
        "from_exact_solution",
        string_list(
            "Components prescribed from the verification block's exact solution at each node.")
            .choices({"x", "y", "z"})
            .items(1, 3)));
    return k;
  };
  return map("An essential boundary condition on a node set. Only the components given are "
             "constrained.")
      .required("name", string("Condition name, unique."))
      .required("type", choice("Prescribed quantity.", {"displacement", "velocity"}))
      .required("node_set", string("Node set of the mesh the condition applies to."))
      .optional(
          "method",
          choice(
              "Enforcement with non-interpolating shape functions (docs/boundary_conditions.md). "
              "Explicit stages: transformation prescribes the particles' generalized values "
              "(fast, inexact near the boundary); nitsche and penalty act as boundary forces "
              "(exact stresses, a smaller stable time step). Shells (docs/shells.md, "
              "\"Essential conditions\"): all three with small rotations, transformation with "
              "finite "
              "rotations.",
              {"transformation", "nitsche", "penalty"}),
          "transformation")
      .optional("penalty", real("Factor alpha of the boundary stiffness beta = alpha E / h "
                                "(shells: alpha s / h, s the section's stiffness of the "
                                "component; nitsche: default 100; penalty: default 1e4).",
                                "-")
                               .above(0))
      .optional("stages",
                string_list("Stages the condition acts in (names of stages); every stage when "
                            "omitted. A springback stage leaves out the conditions that formed "
                            "the part.")
                    .items(1, 1000))
      .discriminated_by("type")
      .variant("displacement",
               [&] {
                 auto k = keys("Prescribed displacement", "length");
                 for (auto& r : rotation_keys()) k.push_back(r);
                 return k;
               }())
      .variant("velocity", keys("Prescribed velocity", "length/time"))
      .at_least_one_of({"x", "y", "z", "rx", "ry", "from_exact_solution"});
}

SpecPtr load_spec() {
  auto curve = optional_key("curve", string("Name of a curve scaling the load over time; see the "
                                            "stage drivers for what happens without one."));
  auto exact = optional_key("from_exact_solution",
                            boolean("Take the load from the verification block's exact solution "
                                    "(traction P N, or body force) instead of value."),
                            "false");
  return map("An external load. Keys after type depend on the type.")
      .required("name", string("Load name, unique."))
      .required("type",
                choice("Kind of load.", {"traction", "pressure", "nodal_force", "body_force",
                                         "shell_pressure", "shell_edge_load", "shell_point_load"}))
      .optional("stages", string_list("Stages the load acts in (names of stages); every stage "
                                      "when omitted.")
                              .items(1, 1000))
      .discriminated_by("type")
      .variant(
          "traction",
          {required_key("side_set", string("Side set the traction acts on.")),
           optional_key(
               "value",
               real_list("Traction vector (force per reference area), one entry per dimension; "
                         "each a number or an expression of x, y, z, t.",
                         "stress")
                   .items(2, 3)
                   .varying(ExpressionVariables::position_and_time)),
           exact, curve})
      .variant("pressure",
               {required_key("side_set", string("Side set the pressure acts on.")),
                required_key("value", real("Pressure, positive into the body; a number or an "
                                           "expression of x, y, z, t.",
                                           "stress")
                                          .varying(ExpressionVariables::position_and_time)),
                curve})
      .variant("nodal_force",
               {required_key("node_set", string("Node set sharing the force equally.")),
                required_key(
                    "value",
                    real_list("Total force vector, one entry per dimension.", "force").items(2, 3)),
                curve})
      .variant("body_force",
               {optional_key("parts", string_list("Parts loaded; all when omitted.")),
                optional_key("value",
                             real_list("Force per unit reference volume, one entry per "
                                       "dimension; each a number or an expression of x, y, z, t.",
                                       "force/length^3")
                                 .items(2, 3)
                                 .varying(ExpressionVariables::position_and_time)),
                exact, curve})
      .variant("shell_pressure", shell_pressure_keys())
      .variant("shell_edge_load", shell_edge_load_keys())
      .variant("shell_point_load", shell_point_load_keys());
}

SpecPtr initial_condition_spec() {
  return map("An initial condition on a node set.")
      .required("type", choice("Initial quantity.", {"velocity", "displacement"}))
      .required("node_set", string("Node set of the mesh."))
      .required("value", real_list("Vector value, one entry per dimension; each a number or an "
                                   "expression of x, y, z.",
                                   "length/time or length")
                             .items(2, 3)
                             .varying(ExpressionVariables::position));
}

SpecPtr node_set_spec() {
  return map("The nodes of the mesh (or of node set within) inside the box [lower, upper], "
             "bounds included (LS-DYNA *SET_NODE_GENERAL with BOX): a pin, an edge, a patch.")
      .required("name", string("Node set name, unique, not a name the mesh already has."))
      .required("lower", real_list("Lower corner, one entry per dimension.", "length").items(2, 3))
      .required("upper", real_list("Upper corner, one entry per dimension.", "length").items(2, 3))
      .optional("within", string("A node set of the mesh to take the nodes from; all nodes when "
                                 "omitted."));
}

SpecPtr curve_spec() {
  return map("A piecewise-linear function of time (LS-DYNA *DEFINE_CURVE); constant beyond its "
             "ends.")
      .required("name", string("Curve name, unique."))
      .required("time", real_list("Abscissae, strictly increasing.", "time").items(2, 100000))
      .required("value", real_list("Ordinates, as many as times.", "-").items(2, 100000));
}

SpecPtr rigid_wall_spec() {
  return map("A fixed planar rigid wall (LS-DYNA *RIGIDWALL_PLANAR): particles may not cross the "
             "plane through point "
             "against normal; enforced by a penalty force in explicit stages.")
      .required("name", string("Wall name, unique."))
      .required("point", real_list("A point of the plane.", "length").items(2, 3))
      .required(
          "normal",
          real_list("Normal pointing to the side the particles stay on (need not be unit).", "-")
              .items(2, 3))
      .optional("node_set",
                string("Node set of the particles the wall acts on; all particles when omitted."))
      .optional("penalty",
                real("Wall stiffness per particle as a fraction of its mass / dt^2 (stable up to "
                     "about 1).",
                     "-")
                    .above(0)
                    .at_most(1),
                "0.5");
}

SpecPtr output_spec() {
  return map("Results output.")
      .optional("file", string("Exodus II results file, relative to the output folder; default: "
                               "the scene's name with .e."))
      .optional(
          "fields",
          string_list("Nodal (particle) fields written at each record. generalized_displacement, "
                      "generalized_velocity and material_state (the history of path-dependent "
                      "laws) are what initial_state reads back to restart from a record. "
                      "pressure: -tr(sigma)/3, compression positive (mixed_up parts: the mean "
                      "of the cell pressures around the particle). cell_pressure: the condensed "
                      "pressure of every background cell of the mixed_up parts (an element "
                      "field; 0 in other cells). Shell parts (docs/shells.md): stress is the top "
                      "and bottom surface stress, resultants the membrane forces, moments and "
                      "transverse shear forces per unit length, thickness the current thickness "
                      "t (1 + mean eps_zz) of the plane-stress section.")
              .choices({"displacement", "velocity", "acceleration", "stress", "strain", "von_mises",
                        "pressure", "cell_pressure", "plastic_strain", "eroded", "nodal_volume",
                        "owner_rank", "generalized_displacement", "generalized_velocity",
                        "material_state", "resultants", "thickness"}),
          "[displacement, nodal_volume, owner_rank]")
      .optional("history",
                string("CSV file, beside the results file (relative to its folder), of the global "
                       "quantities (energies, wall forces, "
                       "reactions) and the node sets' mean displacement and velocity at "
                       "every record; none when omitted."))
      .optional(
          "history_node_sets",
          string_list("Node sets whose mean displacement and velocity go to the history file."),
          "[]")
      .optional("files",
                string("gathered: rank 0 gathers every record and writes the one results file. "
                       "per_rank: every rank writes its piece of the mesh and of the fields to "
                       "'<file>.<ranks>.<rank>' (SEACAS's decomposed files: node and element id "
                       "maps; the rank zero-padded to the digits of the rank count), nothing is "
                       "gathered; SEACAS epu joins them: `epu -auto <file>.<ranks>.<0...>` "
                       "(docs/scaling.md). On one rank both write the one file.")
                    .choices({"gathered", "per_rank"}),
                "gathered");
}

SpecPtr verification_spec() {
  auto reference =
      map("A scalar result checked against a reference value.")
          .required("name", string("Quantity label, unique."))
          .required("quantity", string("What is measured, e.g. displacement_y@node_set:tip."))
          .required("value", real("Reference value.", "as the quantity"))
          .optional("tolerance", real("Relative tolerance.", "-").above(0), "0.01");
  const auto at_x = ExpressionVariables::position;
  auto user_solution =
      map("An exact solution written in the scene (verification.exact_solution: user): the "
          "displacement as expressions of x, y, z and, optionally, the stress and body force. "
          "Error norms, from_exact_solution conditions and loads use it like a built-in one.")
          .required("displacement",
                    real_list("Exact displacement, one expression per dimension.", "length")
                        .items(2, 3)
                        .varying(at_x))
          .optional("stress",
                    map("Exact stress (Cauchy, small strain), for tractions taken from the "
                        "exact solution; default: the part's linear elastic stress of the "
                        "displacement's gradient (central differences).")
                        .required("xx", real("sigma_xx.", "stress").varying(at_x))
                        .required("yy", real("sigma_yy.", "stress").varying(at_x))
                        .required("xy", real("sigma_xy.", "stress").varying(at_x))
                        .optional("zz", real("sigma_zz (3D).", "stress").varying(at_x))
                        .optional("yz", real("sigma_yz (3D).", "stress").varying(at_x))
                        .optional("xz", real("sigma_xz (3D).", "stress").varying(at_x)))
          .optional("body_force",
                    real_list("Body force of the exact solution, one expression per dimension "
                              "(default zero).",
                              "force/length^3")
                        .items(2, 3)
                        .varying(at_x));
  auto names = exact_solution_names();
  names.push_back("user");
  return map("Optional: how the run checks itself (exact solution or reference values).")
      .optional("exact_solution",
                choice("Named exact solution the error norms are measured against; user: the "
                       "one given in user_solution.",
                       names))
      .optional("user_solution", user_solution)
      .optional("parameters",
                passthrough("Parameters of the exact solution; see docs/verification.md (e.g. "
                            "length, depth, load of the beam)."))
      .optional("reference_values", list("Scalar reference values.", reference).unique_names());
}

Spec build_scene_schema() {
  auto probe =
      map("A named point whose interpolated (MLS) displacement, strain and stress go to the "
          "history file and the run report; reference_values may name them as "
          "<field>_<component>@probe:<name>.")
          .required("name", string("Probe name, unique."))
          .required(
              "point",
              real_list("Reference coordinates, one entry per dimension.", "length").items(2, 3));
  auto angle =
      map("The angle in the x-y plane, in degrees from the x axis (atan2, in (-180, 180]), of the "
          "deformed segment from probe `from` to probe `to`, in the run report at the end of "
          "every stage (angles_by_stage): a springback angle is the difference of two stages' "
          "values.")
          .required("name", string("Angle name, unique."))
          .required("from", string("Probe at the segment's start."))
          .required("to", string("Probe at the segment's end."));
  SpecPtr root =
      map("An efg scene.")
          .optional("title", string("Free text written to the log and the Exodus title."), "\"\"")
          .optional("parameters",
                    passthrough("Named constants (name: number, or an expression of the earlier "
                                "ones), usable in every number of the scene and in expressions."))
          .required("mesh", mesh_spec())
          .required("parts", list("Meshfree parts.", part_spec()).items(1, 1000000).unique_names())
          .required("materials",
                    list("Materials.", material_spec()).items(1, 1000000).unique_names())
          .optional(
              "boundary_conditions",
              list("Essential boundary conditions.", boundary_condition_spec()).unique_names(),
              "[]")
          .optional("loads", list("External loads.", load_spec()).unique_names(), "[]")
          .optional("initial_conditions", list("Initial conditions.", initial_condition_spec()),
                    "[]")
          .optional("initial_state",
                    map("Start from a record of an earlier run's results (a restart, e.g. a "
                        "springback run after a forming run): its generalized displacements and "
                        "velocities and the material history, written by output.fields "
                        "generalized_displacement, generalized_velocity (and material_state); the "
                        "mesh must be the same. The run starts at the record's time.")
                        .required("file", string("Exodus results file of the earlier run, "
                                                 "relative to the scene's folder."))
                        .optional("time", real("Time of the record to start from; the last "
                                               "record when omitted.",
                                               "time")))
          .optional("curves", list("Load curves.", curve_spec()).unique_names(), "[]")
          .optional("node_sets",
                    list("Node sets made by the scene, usable wherever a node set is named.",
                         node_set_spec())
                        .unique_names(),
                    "[]")
          .optional("rigid_walls",
                    list("Planar rigid walls (explicit stages).", rigid_wall_spec()).unique_names(),
                    "[]")
          .optional("rigid_bodies", list("Rigid bodies.", rigid_body_spec()).unique_names(), "[]")
          .optional("contacts",
                    list("Penalty contacts of deformable parts with rigid bodies.", contact_spec())
                        .unique_names(),
                    "[]")
          .optional("stages",
                    list("Analysis stages, run in order. With none, the run writes the "
                         "initial state only (a model check).",
                         stage_spec())
                        .unique_names(),
                    "[]")
          .optional("output", output_spec(), "{}")
          .optional("probes", list("Points sampled at every record.", probe).unique_names(), "[]")
          .optional("angles", list("Angles of segments between probes.", angle).unique_names(),
                    "[]")
          .optional("verification", verification_spec());
  return *root;
}

}  // namespace

const schema::Spec& scene_schema() {
  static const schema::Spec spec = build_scene_schema();
  return spec;
}

}  // namespace efg
