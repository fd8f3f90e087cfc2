// The signed distance of a point to the surface of a rigid body made of mesh blocks (plain
// code, no Trilinos; mesh/RigidSurface holds the facets). In the body's own (reference) frame:
// the facets near the point come from bins over their boxes, each grown by the capture depth
// (the median facet's size, the same for all: a point within it of the surface lies in its
// nearest facet's box, so the nearest found is the nearest of all), built once - the body moves
// as a whole, the point is taken into its frame; a facet whose grown box does not hold the
// point is not tested, and a point farther than the capture depth from every facet does not
// touch (gap `reach`, the largest facet).
// The closest point p of the surface and the feature it lies on (contact/ClosestFeature.hpp)
// decide:
// - a facet's interior: the facet's plane, the gap g = (y - a) . n and its unit normal n (as an
//   analytic plane or box face);
// - an edge or corner: the distance |y - p|, signed by that feature's pseudo-normal
//   (contact/PseudoNormals: the two faces' normals at an edge, the angle-weighted normals at a
//   corner; Baerentzen & Aanaes 2005 prove the sign right for closed surfaces), the normal
//   (y - p) / g, continuous across the facets' edges;
// - inside, equally deep under two facets' interiors (the bisector of a corner): that depth,
//   along the normalized sum of their normals (the first facet found would tilt the force by
//   the corner's half angle: a polygonal punch centred on a corner pushed sideways).
// A penetration deeper than half the body's thickness comes out on the other side's facets (as
// for any closest-point contact): tools thinner than the particles' approach in one step are not
// resolved.
#pragma once

#include <memory>
#include <vector>

#include "contact/FacetBins.hpp"
#include "contact/PseudoNormals.hpp"
#include "contact/RigidShape.hpp"
#include "mesh/RigidSurface.hpp"

namespace efg::contact {

class MeshSurface {
 public:
  explicit MeshSurface(std::shared_ptr<const RigidSurface> surface);

  /// Gap and outward normal of y (body frame).
  Proximity proximity(const double* y) const;
  const RigidSurface& surface() const { return *surface_; }

 private:
  std::shared_ptr<const RigidSurface> surface_;
  PseudoNormals pseudo_;  ///< of every facet, edge and corner
  FacetBins bins_;
  std::vector<double> box_lower_, box_upper_;      ///< each facet's grown box, dim per facet
  std::vector<double> tight_lower_, tight_upper_;  ///< and its own box
  double reach_ = 0;    ///< the largest facet: the gap of a point that touches none
  double capture_ = 0;  ///< the capture depth (the median facet's size)
};

}  // namespace efg::contact
