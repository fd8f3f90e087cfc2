// Round bodies as closed, outward-oriented triangle sets (mesh/RigidSurface), for the tests of
// the signed distance to rigid mesh surfaces against the analytic shapes. Every node lies on the
// analytic surface (the tessellation is inscribed), and quadrilaterals are cut along their 0-2
// diagonal as discretization/OrientedFacets cuts a cell's side.
#pragma once

#include "mesh/RigidSurface.hpp"

namespace efg::test {

/// A sphere of radius r about the origin by latitude and longitude: `rings` bands of `segments`
/// quadrilaterals (cut in two), the bands at the poles fans of triangles.
RigidSurface tessellated_sphere(double r, int rings, int segments);

/// A solid cylinder about the z axis, radius r, z in [0, h], as the reported impactor is meshed:
/// each end a disc mapped from the square [-1, 1]^2 of n x n cells
/// (x sqrt(1 - y^2 / 2), y sqrt(1 - x^2 / 2)) r - its rim the 4 n boundary nodes of the square,
/// unevenly spaced, each corner cell a sliver along the rim - and the side `layers` rows of
/// 4 n quadrilaterals between the two rims.
RigidSurface tessellated_mapped_cylinder(double r, double h, int n, int layers);

}  // namespace efg::test

namespace efg::test {

/// A sharp wedge (a triangular prism, convex): its edge along y from the origin to (0, w, 0),
/// its two sides opening at `apex` radians towards +x to x = l, its ends at y = 0 and y = w.
/// At the origin the upper side meets it in a fan of `fan` + 1 triangles, the lower side and
/// the end in one each: a corner whose equal-weight pseudo-normal points the wrong way for
/// `fan` > 1 / cos(apex) (Baerentzen & Aanaes 2005, sec. 2). Triangles oriented away from the
/// prism's centroid.
RigidSurface tessellated_wedge(double apex, double l, double w, int fan);

}  // namespace efg::test
