// Shell surfaces read as 3D meshes (Exodus SHELL4 / TRISHELL3 blocks, or QUAD4 / TRI3 cells in a
// 3D file): the shells of src/shells/ work on a 2D chart of their mid-surface (docs/shells.md,
// "Curved references"), so such a mesh is turned into its chart when it is read. The chart is
// the orthogonal projection onto the plane through the nodes' centroid normal to the surface's
// area-weighted mean normal, x along the projection of the global x axis (of y when x is within
// 25 degrees of the normal): one chart for sheets, panels, roofs and shell segments whose normal
// stays within 80 degrees of the mean (checked cell by cell: a steeper cell is stretched more
// than 5.8 times, or the surface folds over itself); or the scene's own chart (mesh.chart, e.g.
// latitude and longitude of a sphere, the angle around a cylinder). The strains' metric of the shells
// (shells/ShellMetric.hpp) accounts for the projection's stretch; the 3D positions stay in
// BackgroundMesh::surface.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// Whether cells of this type can make a shell surface read in 3D (quad4, tri3).
inline bool is_surface_cell(CellType type) {
  return type == CellType::quad4 || type == CellType::tri3;
}

/// Whether `mesh` is a shell surface in 3D: dimension 3 and only 2D cells (quad4, tri3).
bool is_surface_mesh(const BackgroundMesh& mesh);

/// The chart's projection of a surface mesh: after chart_surface_mesh (mesh.surface set) the one
/// it charted with, before it the one computed from the 3D coordinates.
SurfaceProjection surface_projection(const BackgroundMesh& mesh);

/// Twice the area-weighted normal of the triangle with corners a, b, c (3D points).
std::array<double, 3> triangle_normal(const double* a, const double* b, const double* c);

/// The projection of a surface whose triangles' normals (triangle_normal) sum to `normal_sum`
/// and whose nodes' centroid is `origin`: the plane normal to the mean normal through the
/// centroid, x along the projection of the global x axis (of y when x is within 25 degrees of
/// the normal).
SurfaceProjection projection_from(const std::array<double, 3>& normal_sum,
                                  const std::array<double, 3>& origin);

/// Throws InputError naming cell `cell` (0-based over the mesh's blocks) of block `block` when
/// its triangle a, b, c turns its normal by 80 degrees or more from the projection's, or has no
/// area (a collapsed cell).
void check_chart_triangle(const SurfaceProjection& p, std::size_t cell, const std::string& block,
                          const double* a, const double* b, const double* c);

/// The chart coordinates of a 3D point (its projection onto the chart's plane).
std::array<double, 2> chart_coordinates(const SurfaceProjection& p, const double* X);

/// One line on a charted surface mesh for logs: how many nodes, which chart (the projection's
/// normal, or the scene's), and the range of the surface's area per chart area over its
/// triangles (the projection's stretch: 1 / cos of a cell's angle to the normal).
std::string surface_chart_summary(const BackgroundMesh& mesh, bool given_chart);

/// A chart given by the user (the scene's mesh.chart): the 2D coordinates of the 3D point X.
using SurfaceChartMap = std::function<void(const double* X, double* chart)>;

/// Turns a surface mesh into its chart: mesh.surface gets the 3D positions, mesh.coordinates the
/// chart's 2D ones, dimension 2. The projection chart throws InputError naming the cell whose
/// normal turns by 80 degrees or more from the projection direction; a given `chart` is taken as
/// it is (the mesh's validation then refuses cells it inverts or collapses).
void chart_surface_mesh(BackgroundMesh& mesh, const SurfaceChartMap& chart = {});

}  // namespace efg
