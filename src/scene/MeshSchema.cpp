#include "scene/MeshSchema.hpp"

namespace efg {
namespace {

using namespace schema;

// The generator's keys; `block_name_default` empty makes block_name required (further blocks).
SpecPtr generate_spec(const std::string& text, const std::string& block_name_default) {
  auto spec =
      map(text)
          .required("element", choice("Cell type; quad4 and tri3 make a 2D rectangle, hex8, tet4 "
                                      "(6 per cube, Kuhn split) and wedge6 (2 per cube) a 3D box.",
                                      {"quad4", "tri3", "hex8", "tet4", "wedge6"}))
          .required("lower",
                    real_list("Lower corner of the domain, one entry per dimension.", "length")
                        .items(2, 3))
          .required("upper",
                    real_list("Upper corner of the domain, one entry per dimension.", "length")
                        .items(2, 3))
          .required("cells", integer_list("Number of cells per direction, one entry per dimension.")
                                 .items(2, 3)
                                 .at_least(1))
          .optional("perturbation",
                    real("Largest random node shift as a fraction of the cell size per direction; "
                         "boundary nodes move only within their boundary plane.",
                         "-")
                        .at_least(0)
                        .at_most(0.3),
                    "0")
          .optional("seed", integer("Seed of the perturbation's random numbers.").at_least(0), "1")
          .optional("map",
                    real_list("Coordinate map applied to every generated node: the new "
                              "coordinates as expressions of the box coordinates x, y, z (e.g. "
                              "[x*cos(y), x*sin(y)] bends [a, b] x [0, pi/2] into a quarter "
                              "ring). Node and side sets keep their names.",
                              "length")
                        .items(2, 3)
                        .varying(ExpressionVariables::position));
  const auto block_name = string("Name of the generated element block.");
  return block_name_default.empty() ? spec.required("block_name", block_name)
                                    : spec.optional("block_name", block_name, block_name_default);
}

}  // namespace

schema::SpecPtr mesh_spec() {
  return map("The background mesh: its nodes become the particles, its cells give nodal volumes, "
             "integration cells and node/side sets. Generated meshes have node and side sets xmin, "
             "xmax, ymin, ymax (zmin, zmax in 3D) and node set all.")
      .optional("file", string("Exodus II mesh file, relative to the scene file's folder."))
      .optional("read",
                choice("How the ranks read mesh.file or make mesh.generate: root (rank 0 reads "
                       "or generates it whole and sends it to every rank) or distributed (each "
                       "rank reads or generates only its slice and keeps its own part of the "
                       "mesh: the particles it owns, the cells around them and those within "
                       "reach of their supports; no rank holds the whole mesh, results are "
                       "written one file per rank). "
                       "Distributed reading serves every scene the root read does (solid, mixed "
                       "u-p and shell parts, rigid walls and bodies, contact between parts, an "
                       "initial state; docs/scaling.md).",
                       {"root", "distributed"}),
                "root")
      .optional("generate", generate_spec("Built-in structured mesh generator.", "block_1"))
      .optional("more_blocks",
                list("Further generated blocks beside mesh.generate's, each with its own nodes "
                     "(not joined to the others): separate bodies that meet by contact. Their "
                     "node and side sets are named <block_name>_xmin .. and <block_name>_all; "
                     "node set all holds every node.",
                     generate_spec("A further generated block.", "")),
                "[]")
      .optional("chart",
                real_list("A shell surface read in 3D (SHELL4 / TRISHELL3 cells): its chart, the "
                          "2D coordinates the shells work on, as expressions of the surface "
                          "point's x, y, z (e.g. [R*asin(z/R), R*atan2(y, x)]: latitude and "
                          "longitude of a sphere as arc lengths; one-to-one on the surface). "
                          "Default: the projection onto the plane normal to the surface's mean "
                          "normal, for surfaces within 80 degrees of it (docs/shells.md).",
                          "length")
                    .items(2, 2)
                    .varying(ExpressionVariables::position))
      .exactly_one_of({"file", "generate"});
}

}  // namespace efg
