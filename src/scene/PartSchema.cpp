#include "scene/PartSchema.hpp"

#include "scene/ShellSchema.hpp"

namespace efg {

using namespace schema;

namespace {

SpecPtr section_spec() {
  return map("Meshfree discretization of the part (LS-DYNA *SECTION_SOLID_EFG).")
      .optional("basis", choice("MLS polynomial basis.", {"linear", "quadratic"}), "linear")
      .optional("kernel",
                choice("Kernel (weight) function.",
                       {"cubic_spline", "quadratic_spline", "quartic_spline"}),
                "cubic_spline")
      .optional("support",
                choice("Support shape: box is a tensor product with a dilation per "
                       "direction, sphere uses the largest.",
                       {"box", "sphere"}),
                "box")
      .optional(
          "dilation",
          real_list("Normalized dilation (support size / nodal spacing); one value, or one per "
                    "direction for box supports.",
                    "-")
              .items(1, 3)
              .at_least(1.0)
              .scalar_allowed(),
          "1.5")
      .optional(
          "spacing",
          choice("How the nodal spacing h_d is measured: cells, the extent in d of the "
                 "background cells around the node (LS-DYNA IDILA=0); edges, the length along d "
                 "of the cell edges running mainly along d (the distance between rows of nodes: "
                 "on cells sheared against the axes, such as a tapered panel, the extent also "
                 "counts the shear and the supports grow several rows wide; equal to cells on "
                 "axis-aligned cells); neighbors, the largest distance in d to the nodes sharing "
                 "a cell (IDILA=1). See docs/discretization.md.",
                 {"cells", "edges", "neighbors"}),
          "cells")
      .optional("support_size",
                choice("Each particle its own support size, or the part's largest for all.",
                       {"per_particle", "per_part"}),
                "per_particle")
      .optional(
          "integration",
          choice("Domain integration: stabilized conforming nodal integration (Chen et al. "
                 "2001); scni_subcells, SCNI with each nodal domain cut into its pieces by the "
                 "background cells, one smoothed strain per piece (2^dim x the points; on "
                 "irregular particles about 10x smaller energy errors, converging at rate 1; "
                 "elastic and hyperelastic laws); direct nodal (unstable, for comparison); or "
                 "Gauss on background cells. See docs/discretization.md.",
                 {"scni", "scni_subcells", "nodal", "gauss"}),
          "scni")
      .optional(
          "smoothing_quadrature",
          choice("Quadrature on the SCNI smoothing facets inside the background cells "
                 "(integration scni; with scni_subcells also the cell sides inside the part): "
                 "split, 2 Gauss points per 2D segment "
                 "and 4 triangles per 3D facet; or centroid, one point per facet at its area "
                 "centroid where the facet is flat (all of them in 2D and in tetrahedra, "
                 "those of undistorted hexahedra; a warped facet gets 2, the triangles on a "
                 "diagonal). Both are exact for "
                 "linear fields (the patch test holds); centroid evaluates 4x fewer shape "
                 "functions in 3D (2x in 2D), setup about 3x faster on hex grids, results moved "
                 "by about 1e-5 there; with a quadratic basis in 2D it gives up the split rule's "
                 "exactness for quadratics along the segments (energy errors about 1.35x). The "
                 "part's boundary sides always use the split rule. auto (default): centroid "
                 "for integration scni with the linear basis in 3D, split otherwise. See "
                 "docs/discretization.md.",
                 {"auto", "split", "centroid"}),
          "auto")
      .optional("gauss_order",
                integer("Gauss points per direction (integration: gauss).").at_least(1).at_most(6),
                "2")
      .optional("formulation",
                choice("Kinematics: small strain, or finite strain total Lagrangian with the "
                       "Lagrangian kernel.",
                       {"small_strain", "total_lagrangian"}),
                "small_strain");
}

}  // namespace

SpecPtr part_spec() {
  return map("A meshfree part: element blocks discretized with one section and one material.")
      .required("name", string("Part name, unique."))
      .required(
          "blocks",
          string_list("Element block names of the mesh that make up the part.").items(1, 1000000))
      .required("material", string("Name of an entry of materials."))
      .optional("section", section_spec(), "{}")
      .optional(
          "thickness",
          real("Out-of-plane thickness (2D plane stress and plane strain).", "length").above(0),
          "1")
      .optional("plane", choice("2D assumption.", {"strain", "stress"}), "strain")
      .optional("shell", shell_spec())
      .optional("formulation",
                choice("Fields of the part: displacement only, or mixed_up: displacement and a "
                       "constant pressure per pressure cell (pressure_cells), condensed cell by "
                       "cell (nearly incompressible solids, nu up to 0.5; linear_elastic or "
                       "j2_plasticity at small strain, neo_hookean or j2_plasticity at finite "
                       "strain with U(J) = kappa/2 (ln J)^2 per cell; plane "
                       "strain or 3D). See docs/mixed.md.",
                       {"displacement", "mixed_up"}),
                "displacement")
      .optional("pressure_cells",
                choice("What carries one pressure of a mixed_up part: cell, one pressure per "
                       "background cell (the default; it has the spurious checkerboard mode of "
                       "Q1/P0 elements), or patch, the background cells around an interior node "
                       "(2 x 2 quads, 2 x 2 x 2 hexes: inf-sup stable, no spurious mode; with "
                       "integration scni_subcells the most accurate pairing for elastic parts, "
                       "but too few constraints for perfectly plastic flow). Only for "
                       "formulation mixed_up. See docs/mixed.md.",
                       {"cell", "patch"}),
                "cell");
}

}  // namespace efg
