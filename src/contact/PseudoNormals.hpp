// The pseudo-normals that sign the distance to a rigid mesh surface near its edges and corners
// (plain code, no Trilinos). Baerentzen & Aanaes (IEEE TVCG 11(3), 2005, "Signed distance
// computation using the angle weighted pseudonormal") prove that with y's closest surface point
// p on a feature (face, edge or corner) of a closed, outward-oriented triangle mesh, y is outside
// exactly when (y - p) . n_f > 0, n_f the feature's pseudo-normal: the face's normal, the sum of
// the normals of the two faces at an edge, and at a corner the sum of the incident faces'
// normals weighted by their angles there. Equal weights at a corner do not have that property:
// a corner of a tessellated round body shared by a thin sliver (angle near pi) and a few narrow
// facets is misjudged by them. The sums must cover every facet at the feature, not only those
// a search happens to return: here they are built once over the whole surface. Corners are
// shared by equal coordinates (the mesh's nodes); in 2D a corner is a segment's end, weighted
// equally (both angles are pi).
#pragma once

#include <array>
#include <vector>

#include "mesh/RigidSurface.hpp"

namespace efg::contact {

class PseudoNormals {
 public:
  PseudoNormals() = default;
  explicit PseudoNormals(const RigidSurface& s);

  /// The unit outward normal of facet f (zero for a degenerate facet).
  const double* face(std::size_t f) const { return &face_[3 * f]; }
  /// The pseudo-normal of the edge from local corner `local` to the next one of facet f.
  const double* edge(std::size_t f, int local) const;
  /// The angle-weighted pseudo-normal of local corner `local` of facet f.
  const double* corner(std::size_t f, int local) const;

 private:
  int per_ = 3;
  std::vector<double> face_;                     ///< 3 per facet
  std::vector<int> corner_id_;                   ///< per facet corner: the shared corner
  std::vector<int> edge_id_;                     ///< per facet edge (3D): the shared edge
  std::vector<std::array<double, 3>> corner_n_;  ///< per shared corner
  std::vector<std::array<double, 3>> edge_n_;    ///< per shared edge
};

}  // namespace efg::contact
