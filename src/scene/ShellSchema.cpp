#include "scene/ShellSchema.hpp"

namespace efg {

using namespace schema;

SpecPtr shell_spec() {
  return map("The part is a Reissner-Mindlin shell whose mid-surface is the part's 2D mesh, flat "
             "in the x-y plane or mapped onto a developable surface (reference), small strain, "
             "small or finite rotations (section.formulation), linear elastic or J2 through the "
             "thickness, implicit and explicit stages; five dofs per particle (u, v, w and two "
             "rotations). See docs/shells.md.")
      .optional("thickness",
                real("Shell thickness: a number, or an expression of the position x, y, z (the "
                     "particles' thickness, interpolated by the shape functions between them). "
                     "Absent: the mesh's, from a thickness attribute per cell of the part's "
                     "blocks (the attribute named thickness, or a block's only attribute; Exodus "
                     "SHELL4/TRISHELL3, QUAD4/TRI3), each node taking the mean of its cells'. "
                     "See docs/shells.md, \"Thickness\".",
                     "length")
                    .above(0)
                    .varying(ExpressionVariables::position))
      .optional("thickness_points",
                integer("Gauss points through the thickness (2 integrate an elastic section "
                        "exactly; a J2 section needs more: its fully plastic moment comes out "
                        "0.945 of the exact one with 5 points, 0.982 with 9, 1.005 with 12).")
                    .at_least(1)
                    .at_most(12),
                "2")
      .optional("shear_stabilization",
                real("alpha of the transverse shear stiffness k_s G t t^2 / (t^2 + alpha h^2) "
                     "(Lyly, Stenberg & Vihinen 1993; h the particle spacing): keeps thin shells "
                     "free of shear locking; 0 switches it off.",
                     "-")
                    .at_least(0),
                "0.1")
      .optional(
          "reference",
          map("A curved reference mid-surface over a chart (the global approach): (X, Y, Z) = "
              "(x, y, z) of these expressions of the mesh's x, y maps the 2D mesh onto the "
              "surface (a cylinder unrolled, a sphere over latitude and longitude). The map must "
              "be regular (independent tangents, checked at the particles); the strains are "
              "measured on the surface through its metric; needs section.formulation: "
              "total_lagrangian. See docs/shells.md, \"Curved references\".")
              .required(
                  "x",
                  real("X of the surface point.", "length").varying(ExpressionVariables::position))
              .required(
                  "y",
                  real("Y of the surface point.", "length").varying(ExpressionVariables::position))
              .required("z", real("Z of the surface point.", "length")
                                 .varying(ExpressionVariables::position)));
}

std::vector<Key> rotation_keys() {
  const auto v = ExpressionVariables::position_and_time;
  return {optional_key(
              "rx", real("Prescribed rotation about x (shell parts only).", "radian").varying(v)),
          optional_key(
              "ry", real("Prescribed rotation about y (shell parts only).", "radian").varying(v))};
}

std::vector<Key> shell_pressure_keys() {
  return {optional_key("parts", string_list("Shell parts loaded; all when omitted.")),
          required_key("value", real("Pressure on the mid-surface along +z (force per area); a "
                                     "number or an expression of x, y, z, t.",
                                     "stress")
                                    .varying(ExpressionVariables::position_and_time)),
          optional_key("follower",
                       boolean("The pressure follows the deformed mid-surface: along its normal "
                               "f1 x f2, per deformed area (finite rotations only; its load "
                               "stiffness is in the Newton tangent). false: along +z, per "
                               "reference area (a dead load)."),
                       "false"),
          optional_key("curve", string("Name of a curve scaling the load over time; see the "
                                       "stage drivers for what happens without one."))};
}

std::vector<Key> shell_point_load_keys() {
  return {
      required_key("point",
                   real_list("Where the load acts on the mid-surface (x, y of the 2D mesh: "
                             "on a curved reference, of the unrolled surface; on a shell "
                             "surface read in 3D, x, y, z, projected onto its chart).",
                             "length")
                       .items(2, 3)),
      required_key("value",
                   real_list("Force along x, y, z and moment about the rotation dofs' axes at the "
                             "point, applied as f_I = phi_I(point) value; each a number or an "
                             "expression of t.",
                             "force")
                       .items(5, 5)
                       .varying(ExpressionVariables::position_and_time)),
      optional_key("curve", string("Name of a curve scaling the load over time; see the "
                                   "stage drivers for what happens without one."))};
}

std::vector<Key> shell_edge_load_keys() {
  return {required_key("node_set", string("Node set of the loaded edge: the shell edges whose "
                                          "nodes all lie in it.")),
          required_key(
              "value",
              real_list("Line load on the edge per unit reference length: forces along x, y, z "
                        "and moments about x, y (rotations' axes; with finite rotations the axes "
                        "of the particles' frames, docs/shells.md); each a number or an "
                        "expression of x, y, z, t.",
                        "force/length")
                  .items(5, 5)
                  .varying(ExpressionVariables::position_and_time)),
          optional_key("curve", string("Name of a curve scaling the load over time; see the "
                                       "stage drivers for what happens without one."))};
}

}  // namespace efg
