#include "scene/StageSchema.hpp"

namespace efg {

using namespace schema;

SpecPtr stage_spec() {
  return map("One analysis stage. Stages run in order, each starting from the state the previous "
             "one left. Keys after driver depend on the driver.")
      .required("name", string("Stage name, unique."))
      .required("driver", choice("Time integration.", {"implicit", "explicit"}))
      .required("end_time",
                real("Stage end time (pseudo-time for static implicit stages).", "time").above(0))
      .optional("output_interval",
                real("Time between output records; when omitted, implicit stages write the stage "
                     "end and explicit stages 20 records.",
                     "time")
                    .above(0))
      .discriminated_by("driver")
      .variant(
          "implicit",
          {optional_key("load_steps", integer("Initial number of load steps.").at_least(1), "1"),
           optional_key("springback",
                        boolean("Springback: the forces out of balance when the stage starts "
                                "(of conditions, loads and contacts not active in it, and the "
                                "inertia of an explicit state) are released gradually, to zero "
                                "at end_time, over the load steps (docs/implicit.md)."),
                        "false"),
           optional_key("min_step_fraction",
                        real("Smallest load step after cutbacks, as a fraction of end_time.", "-")
                            .above(0)
                            .at_most(1),
                        "1e-4"),
           optional_key("solver",
                        choice("Linear solver: a direct LU factorization (on rank 0), GMRES "
                               "with multigrid, or auto (direct up to direct_limit dofs, "
                               "iterative above); docs/implicit.md.",
                               {"auto", "direct", "iterative"}),
                        "auto"),
           optional_key("direct_limit",
                        integer("Largest dof count that solver: auto factors directly; 0: the "
                                "default (150000 in 2D, 30000 in 3D; 300000 and 120000 when a "
                                "part's Poisson's ratio is 0.49 or more, where multigrid "
                                "stalls).")
                            .at_least(0),
                        "0"),
           optional_key("residual_tolerance",
                        real("Newton converges when ||r|| <= this x max(||f_ext||, ||f_int||, "
                             "||r_0||), or when the energy of the update is negligible.",
                             "-")
                            .above(0)
                            .below(1),
                        "1e-9"),
           optional_key("nonlinear_solver",
                        passthrough("NOX parameter list (e.g. Nonlinear Solver, Line Search)."),
                        "{}"),
           optional_key("linear_solver",
                        passthrough("Belos parameter list; 'Solver Type' picks the method."), "{}"),
           optional_key(
               "preconditioner",
               passthrough("'Type': direct, MueLu (on the Jacobian), auxiliary (MueLu on the "
                           "background cells' finite elements), Ifpack2 or None; the other keys go "
                           "to that package's list ('solver': MUMPS, UMFPACK or KLU2 for direct)."),
               "{}")})
      .variant(
          "explicit",
          {optional_key("dt_scale",
                        real("Factor on the stable time step.", "-").above(0).at_most(1), "0.9"),
           optional_key(
               "stable_step",
               choice("How the largest frequency of M^-1 K (the stable time step 2 / omega_max) is "
                      "estimated: sharpened (1.1 x the largest Ritz value of 12 Lanczos steps, "
                      "capped by the bound; 0.85-0.95 of the critical step with dt_scale 0.9), "
                      "bound (a guaranteed upper bound from the integration points, needing no "
                      "iteration; 0.5-0.8 of the critical step; solid parts without mixed u-p or "
                      "weak supports, elsewhere sharpened), converged (the Krylov-Schur "
                      "eigensolver run to convergence: the reference, 10-20 times the cost). "
                      "Models of at most 64 dofs take the exact eigenvalue.",
                      {"sharpened", "bound", "converged"}),
               "sharpened"),
           optional_key("mass_scale",
                        real("Uniform mass scaling of a quasi-static stage (forming): the lumped "
                             "mass of every particle times this factor, so the stable time step "
                             "grows by its square root; inertia, kinetic energy and contact "
                             "stiffness follow the scaled mass. Check the kinetic / internal "
                             "energy ratio the stage logs (docs/explicit.md).",
                             "-")
                            .at_least(1),
                        "1"),
           optional_key(
               "damping",
               real("Mass-proportional damping alpha (1/time), the role of LS-DYNA's "
                    "*DAMPING_GLOBAL: a force -alpha M v on every particle, for quasi-static "
                    "stages (forming, settling under a preload); a free particle's velocity decays "
                    "like exp(-alpha t). About 2 omega_1 (the lowest natural frequency, rad/time) "
                    "damps that mode critically. Its work is in the energy account (history "
                    "column mass_damping_work; docs/explicit.md, \"Damping\"). 0: off.",
                    "1/time")
                   .at_least(0),
               "0"),
           optional_key("damping_parts",
                        string_list("The parts damping acts on (per-part damping); none named: "
                                    "every part."),
                        "[]"),
           optional_key(
               "relaxation_kinetic_ratio",
               real("Dynamic relaxation: the stage ends once its kinetic energy stays at or below "
                    "this fraction of its internal energy at two checks in a row (every 100 "
                    "steps and at records; a turning point of an oscillation passes one), with "
                    "damping to settle the state (docs/explicit.md, \"Damping\"). The stage's "
                    "last record is the relaxed state; the next stage starts at end_time. 0: off.",
                    "-")
                   .at_least(0)
                   .below(1),
               "0"),
           optional_key("bulk_viscosity_linear",
                        real("Linear bulk viscosity coefficient (LS-DYNA's Q2) of the cells of "
                             "mixed_up parts: q = rho l (Q1 l theta'^2 - Q2 c theta') on "
                             "compressing cells; 0 turns it off. Parts without mixed_up have "
                             "none (docs/mixed.md).",
                             "-")
                            .at_least(0),
                        "0.06"),
           optional_key("bulk_viscosity_quadratic",
                        real("Quadratic bulk viscosity coefficient (LS-DYNA's Q1) of the cells "
                             "of mixed_up parts.",
                             "-")
                            .at_least(0),
                        "1.5"),
           optional_key(
               "transformation_traction",
               boolean("Displacement conditions with method transformation also apply their "
                       "boundary traction term (the Wagner-Liu consistency term the implicit "
                       "stages carry) as a force: an implicit equilibrium handed to this stage "
                       "then stays put to round-off, as with nitsche. Off by default: the term "
                       "evaluates the stress at the boundary points, which invert in severe "
                       "impacts (docs/boundary_conditions.md, \"Explicit stages\")."),
               "false"),
           optional_key("dt",
                        real("Fixed time step instead of the stable estimate.", "time").above(0)),
           optional_key(
               "allow_unstable_dt",
               boolean(
                   "Run a fixed dt above the stable limit (detected and stopped if it blows up)."),
               "false"),
           optional_key(
               "energy_balance_limit",
               real("Largest energy balance error, |E_kin + E_int - E_0 - W_ext - W_wall| over "
                    "the largest of them, before the stage stops (exit 3, naming the step, time "
                    "and the particle with the largest kinetic energy): checked every 100 steps "
                    "and at every record, stopped when two checks in a row exceed it (energy "
                    "without work is an instability the stable step does not bound). 0: off.",
                    "-")
                   .at_least(0),
               "0.1"),
           optional_key(
               "dt_update_interval",
               integer("Longest interval, in steps, between re-estimates of the stable time step "
                       "(a backstop: they follow the deformation, dt_update_strain).")
                   .at_least(1),
               "1000"),
           optional_key("dt_update_strain",
                        real("The stable time step is re-estimated when the strain since the last "
                             "estimate (the largest component of the displacement gradient of the "
                             "change, at any integration point) reaches this value. Linear "
                             "elastic models keep their first estimate.",
                             "-")
                            .above(0),
                        "0.02")});
}

}  // namespace efg
