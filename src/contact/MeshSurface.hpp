// The signed distance of a point to the surface of a rigid body made of mesh blocks (plain
// code, no Trilinos; mesh/RigidSurface holds the facets). In the body's own (reference) frame:
// the facets near the point come from bins over their boxes, each grown by its own size (its
// capture depth; at most the median facet's, so that a die's long sides do not reach across
// it), built once - the body moves as a whole, the point is taken into its frame; a facet
// whose grown box does not hold the point is not tested.
// The closest point p of those facets decides:
// - inside a facet (its projection within the segment or triangle): the facet's plane, the gap
//   g = (y - a) . n and its unit normal n (as an analytic plane or box face);
// - on an edge or corner: the distance |y - p|, signed by the pseudo-normal (the sum of the
//   unit normals of the facets that share that closest point; Baerentzen & Aanaes 2005 weight
//   them by angle, an equal weight is exact in 2D and for the corners of boxes), the normal
//   (y - p) / g pointing out of the body;
// - inside, equally deep under two facets' interiors (the bisector of a corner): that depth,
//   along the normalized sum of their normals (the first facet found would tilt the force by
//   the corner's half angle: a polygonal punch centred on a corner pushed sideways).
// A point in no facet's grown box gets the gap `reach`, the largest facet (at least that far,
// no contact). A penetration deeper than half the body's thickness comes out on the other side's
// facets (as for any closest-point contact): tools thinner than the particles' approach in one
// step are not resolved.
#pragma once

#include <memory>
#include <vector>

#include "contact/FacetBins.hpp"
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
  FacetBins bins_;
  std::vector<double> box_lower_, box_upper_;      ///< each facet's grown box, dim per facet
  std::vector<double> tight_lower_, tight_upper_;  ///< and its own box
  double reach_ = 0;
};

}  // namespace efg::contact
