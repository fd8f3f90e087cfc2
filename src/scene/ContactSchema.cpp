#include "scene/ContactSchema.hpp"

namespace efg {

using namespace schema;

SpecPtr rigid_body_spec() {
  auto point = [](const std::string& doc) { return real_list(doc, "length").items(2, 3); };
  return map("A rigid body of analytic shape, or made of mesh blocks (shape: mesh): fixed, moved "
             "by a prescribed velocity, or free "
             "(translation under its contact forces; a round body or a 2D box given an "
             "angular_velocity also turns); in implicit stages a free body is force-controlled: "
             "placed "
             "along its force (or gravity) where its contacts balance that load. "
             "Particles of the parts "
             "named by a contact may not enter it.")
      .required("name", string("Body name, unique."))
      .required("shape", choice("Analytic shape, or mesh: the cells of `blocks`.",
                                {"plane", "sphere", "cylinder", "box", "mesh"}))
      .optional("motion",
                choice("fixed: never moves; prescribed: velocity x curve(t); free: moves under "
                       "the contact forces (needs mass or density).",
                       {"fixed", "prescribed", "free"}),
                "fixed")
      .optional("velocity",
                real_list("Initial velocity (free), or the prescribed velocity (prescribed, "
                          "scaled by curve).",
                          "length/time")
                    .items(2, 3))
      .optional("curve", string("Curve scaling the prescribed velocity (prescribed) or the applied "
                                "force (free) over time; constant when omitted (implicit stages: "
                                "the force then ramps as the other loads)."))
      .optional("axis_curves",
                string_list("Prescribed bodies: one curve per velocity component instead of curve "
                            "(a punch pressed, then dragged sideways).")
                    .items(2, 3))
      .optional("mass", real("Mass of the body (2D: of its thickness).", "mass").above(0))
      .optional("density", real("Density: the mass is density x volume (sphere, box; 2D cylinder: "
                                "density x pi r^2 x thickness).",
                                "mass/length^3")
                               .above(0))
      .optional(
          "angular_velocity",
          real_list("Spheres, cylinders and boxes: the angular velocity (2D: one entry, about z; "
                    "3D: three, world axes). A free body starts with it and turns under the "
                    "moment of its contact forces about its centre (I = m R^2 / 2 for a disc, "
                    "2 m R^2 / 5 for a sphere, m (w^2 + h^2) / 12 for a 2D box, the principal "
                    "moments m (b^2 + c^2) / 12, ... for a 3D box; a 3D box turns with its "
                    "orientation, updated by the exponential map); a prescribed body spins at it "
                    "x curve (explicit stages; a driven roll). A free 3D cylinder (infinitely "
                    "long) does not turn. Omitted, the body only translates.",
                    "1/time")
              .items(1, 3))
      .optional("force",
                real_list("Free bodies: an applied force (e.g. a blank holder's), scaled by curve; "
                          "its work is external work.",
                          "force")
                    .items(2, 3))
      .optional("gravity",
                real_list("Free bodies: body force per unit mass (e.g. [0, -9.81]); its work is "
                          "external work.",
                          "length/time^2")
                    .items(2, 3))
      .optional(
          "thickness",
          real("2D only: out-of-plane length of the body, for its mass from density.", "length")
              .above(0),
          "1")
      .discriminated_by("shape")
      .variant("plane", {required_key("point", point("A point of the plane.")),
                         required_key("normal", real_list("Normal pointing out of the body (to "
                                                          "the side particles stay on).",
                                                          "-")
                                                    .items(2, 3))})
      .variant("sphere", {required_key("center", point("Center (2D: a disc).")),
                          required_key("radius", real("Radius.", "length").above(0))})
      .variant("cylinder",
               {required_key("center", point("A point of the axis (2D: the disc's center).")),
                required_key("radius", real("Radius.", "length").above(0)),
                optional_key("axis",
                             real_list("Axis direction (3D; infinite length).", "-").items(3, 3))})
      .variant("box", {required_key("lower", point("Lower corner (axis-aligned box).")),
                       required_key("upper", point("Upper corner."))})
      .variant("mesh", {required_key("blocks", string_list("Element blocks of the mesh that make "
                                                           "the body (its cells' boundary is its "
                                                           "surface; nodes of their own, in no "
                                                           "part; they are no particles).")
                                                   .items(1, 1000))});
}

SpecPtr contact_spec() {
  return map("Penalty contact between the surface particles of deformable parts and a rigid "
             "body, or the surface of other deformable parts (target_parts), with Coulomb "
             "friction; implicit stages take rigid bodies (free ones force-controlled) and "
             "target_parts.")
      .required("name", string("Contact name, unique."))
      .optional("rigid_body", string("Name of an entry of rigid_bodies."))
      .optional("target_parts",
                string_list("Deformable parts whose surface (the sides of their boundary, in "
                            "the current configuration) the surface particles of parts touch; "
                            "bin search; explicit and implicit stages.")
                    .items(1, 1000))
      .exactly_one_of({"rigid_body", "target_parts"})
      .required("parts",
                string_list("Meshfree parts whose surface particles touch the body or the target "
                            "parts' surface.")
                    .items(1, 1000))
      .optional("two_way",
                boolean("With target_parts: also the target parts' surface particles against "
                        "the parts' surface (symmetric, LS-DYNA's surface-to-surface; the "
                        "stable step then counts twice the penalty)."),
                "true")
      .optional("penalty",
                real("Mass rule of the normal stiffness per particle, k = penalty x m / dt^2 "
                     "(stable up to about 1; the stable step is reduced by sqrt(1 - penalty / "
                     "4)). With a rigid body in explicit stages the larger of this and the "
                     "material rule (penalty_scale) acts.",
                     "-")
                    .above(0)
                    .at_most(1),
                "0.1")
      .optional("penalty_scale",
                real("Rigid bodies, explicit stages, solid parts (shells keep the mass rule): "
                     "material rule of the normal stiffness per surface particle, "
                     "k = penalty_scale x K A^2 / V with V = A h, i.e. "
                     "penalty_scale x K A / h (K = E / (3 (1 - 2 nu)) the bulk modulus of the "
                     "particle's part, E / (2 (1 - nu)) in plane stress; A its share of the "
                     "part's boundary facing the body, x thickness in 2D; h its boundary "
                     "spacing): LS-DYNA's "
                     "SLSFAC x K A^2 / V. A pressure p then sinks a particle by p h / "
                     "(penalty_scale K), 1/penalty_scale of the strain p / K over one spacing. "
                     "The stable step is lowered to keep it stable (docs/contact.md). 0: the "
                     "mass rule alone.",
                     "-")
                    .at_least(0),
                "1")
      .optional("penetration_warning",
                real("Rigid bodies, explicit stages: warn once when a particle is deeper in the "
                     "body than this fraction of its spacing (the history column "
                     "contact_<name>_pen and the run report hold the largest fraction).",
                     "-")
                    .above(0),
                "0.2")
      .optional("initial_penetration",
                choice("Rigid bodies, explicit stages: surface particles inside the body at the "
                       "run's start. stop: the run stops (exit 3) naming the body, the deepest "
                       "particle and its depth; ignore: each such particle's initial depth is "
                       "taken as its zero, the contact pushes only beyond it and the allowance "
                       "shrinks as the particle comes out (LS-DYNA's IGNORE = 1); push: the "
                       "penalty pushes the whole depth out from the first step (a deliberate "
                       "preload, e.g. a roll set biting into a strip; the spring's energy "
                       "k depth^2 / 2 enters at once).",
                       {"stop", "ignore", "push"}),
                "stop")
      .optional("stages",
                string_list("Stages the contact acts in (names of stages); every stage when "
                            "omitted. A springback stage leaves out the tools' contacts.")
                    .items(1, 1000))
      .optional("static_friction", real("Static Coulomb coefficient mu_s.", "-").at_least(0), "0")
      .optional("dynamic_friction",
                real("Dynamic Coulomb coefficient mu_d; default: static_friction. "
                     "mu = mu_d + (mu_s - mu_d) exp(-decay |v_slip|).",
                     "-")
                    .at_least(0))
      .optional("decay",
                real("Exponential decay coefficient of friction with slip speed.", "time/length")
                    .at_least(0),
                "0")
      .optional("implicit_penalty",
                real("Implicit stages: contact pressure per unit penetration beta = "
                     "implicit_penalty x E / h (E the part's Young's modulus, h the boundary "
                     "spacing); the penetration error falls like 1 / implicit_penalty.",
                     "-")
                    .above(0),
                "100")
      .optional("damping",
                real("Normal viscous damping as a fraction of critical, c = 2 damping sqrt(k m) "
                     "per particle (LS-DYNA's VDC / 100): quiets contact chatter; never pulls.",
                     "-")
                    .at_least(0)
                    .at_most(1),
                "0");
}

}  // namespace efg
