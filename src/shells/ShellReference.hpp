// A curved reference mid-surface over a chart (the seed's "global approach"; docs/shells.md,
// "Curved references"): parts[].shell.reference maps the part's 2D mesh (x, y) onto the surface,
// X = (X(x, y), Y(x, y), Z(x, y)). The shape functions, the SCNI cells and their smoothed
// gradients stay those of the flat mesh; the strains in (x, y) are turned into the surface
// frame's by the metric of the map (shells/ShellMetric.hpp; the identity when the map is an
// isometry, the unrolling of a developable surface). The map's tangents come from central
// differences of the expressions.
#pragma once

#include <optional>
#include <vector>

#include "model/Model.hpp"
#include "scene/Scene.hpp"
#include "shells/FiniteRotation.hpp"
#include "shells/ShellMetric.hpp"

namespace efg {

/// The reference point of the surface over (x, y): its position, the map's tangents A1 = dX/dx,
/// A2 = dX/dy, its frame (t1 along A1, t3 = A1 x A2 / |A1 x A2| the director, t2 = t3 x t1) and
/// the metric of the strains (shells/ShellMetric.hpp; the identity for an isometry).
struct ShellReferencePoint {
  Vec3 position{};
  Vec3 tangent[2]{};
  ShellFrame frame;
  ShellMetric metric;
};

/// `step`: the central differences' (scene/ShellReferenceMap shell_map_step). The scene's check
/// has made sure that the map is regular at the particles (scene/ShellChecks).
ShellReferencePoint shell_reference_at(const std::vector<ScalarField>& map, const double* xy,
                                       double step);

/// Whether model part `part` has a curved reference: a reference map, or the mesh is a shell
/// surface read in 3D (its chart, mesh/SurfaceChart.hpp).
bool curved_part(const Model& model, std::size_t part);

/// The reference point over (x, y) of model part `part` when it has a curved reference (an
/// empty optional for a flat part). A surface read in 3D is the MLS fit of its nodes' 3D
/// positions P_I over the chart, X = sum phi_I(x, y) P_I, its tangents the fit's direct
/// gradients (the part's shape functions: the surface the particles' generalized positions
/// describe).
std::optional<ShellReferencePoint> part_reference_at(const Model& model, std::size_t part,
                                                     const double* xy);

/// The frames of the nodes of a shell surface read in 3D, from the mesh alone (the same on every
/// rank): per node the area-weighted mean over its cells' triangles of the tangents dX/dx,
/// dX/dy of the linear map from chart to surface, then t1 along dX/dx, t3 along dX/dx x dX/dy
/// (as shell_reference_at). One per mesh node (identity frames for nodes of no cell).
std::vector<ShellFrame> surface_node_frames(const BackgroundMesh& mesh);

/// On a shell surface read in 3D a support's rotation components are about its edge: the frames
/// of the nodes of every boundary condition holding rx or ry turn about their director until t1
/// lies along the node set's edges there (the mean direction of the covered cell sides at the
/// node, projected on the tangent plane), t2 = t3 x t1 the edge's normal in the surface. A later
/// condition wins on shared nodes, as for the values.
void align_frames_to_supports(const Model& model, std::vector<ShellFrame>& frames);

/// The surface length per unit mesh length along the direction (-n_y, n_x) of an edge of
/// outward normal n at (x, y) of part `part` (1 for a flat part): edge loads are per unit
/// length of the surface.
double edge_stretch(const Model& model, std::size_t part, const double* xy, const double* normal);

/// The mesh as the results show it when a part has a curved reference: 3D, the nodes of such
/// parts at their mapped positions (the others at (x, y, 0)), without side sets (edges of 2D
/// cells; shells use node sets). ParaView then shows the curved surface, and the displacements
/// (from the reference) warp it.
BackgroundMesh shell_reference_mesh(const Model& model);

}  // namespace efg
