// A shell surface read in 3D and in slices (mesh.read: distributed): charted as
// mesh/SurfaceChart charts a whole one, so that no rank holds the whole surface. The projection's
// mean normal and centroid are sums over the ranks' slices (each cell and node in one slice; a
// cell's corners fetched from their slice holders), every slice's cells are checked against it
// on their rank, and every slice node gets its chart coordinates before the mesh is dealt out
// (parallel/LocalMesh.hpp partitions and sizes the halo in the chart, where the shells work).
// The 3D positions follow each rank's part afterwards, fetched by global node index
// (parallel/SliceLookup.hpp, fetch_from_slices).
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "mesh/MeshSlice.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Whether the scene's shells are on a surface read in 3D: shell parts and a slice of dimension 3
/// whose blocks are all of 2D cells (quad4, tri3), as mesh/SurfaceChart's is_surface_mesh.
bool is_surface_slice(const Scene& scene, const MeshSlice& slice);

/// Charts `slice` (is_surface_slice) by the scene's mesh.chart or the projection of the whole
/// surface (`plane`, the same on every rank): its coordinates become the chart's (dimension 2).
/// Returns the slice nodes' 3D positions, 3 each. Throws InputError on every rank naming a cell
/// the projection cannot chart. Collective.
std::vector<double> chart_surface_slice(const CommPtr& comm, const Scene& scene, MeshSlice& slice,
                                        SurfaceProjection& plane);

/// The scene gave mesh.chart for a mesh that is no shell surface read in 3D: InputError at
/// mesh.chart.
[[noreturn]] void refuse_chart_without_surface(const Scene& scene);

}  // namespace efg
