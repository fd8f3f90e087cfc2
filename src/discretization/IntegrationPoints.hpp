// Where and how a part's weak form is integrated: points with weights, and at each point the
// shape function values and (smoothed or direct) gradients of the particles that reach it, in
// compressed rows. The same structure serves SCNI (points = nodes, weights = nodal domain
// volumes, gradients = smoothed B~), direct nodal integration and Gauss quadrature, so the
// force and stiffness operators do not care which scheme built it.
#pragma once

#include <cstddef>
#include <vector>

#include "discretization/ParticleCloud.hpp"

namespace efg {

/// Per-point rows of (particle, value[width]) entries.
struct CsrTable {
  int width = 1;
  std::vector<std::size_t> offsets;   ///< size points + 1
  std::vector<LocalIndex> particles;  ///< cloud indices, ascending global id within a row
  std::vector<double> values;         ///< width per entry

  std::size_t rows() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

struct IntegrationPoints {
  int dimension = 3;
  Integration scheme = Integration::scni;
  std::vector<double> x;         ///< dimension per point (reference configuration)
  std::vector<double> weight;    ///< volume represented by the point
  std::vector<LocalIndex> node;  ///< SCNI and nodal: the mesh node of the point; Gauss: -1
  /// SCNI subcells: the mesh node whose nodal domain holds the piece (its history is averaged
  /// there for output); empty when every point is a particle's own (node) or a Gauss point.
  std::vector<LocalIndex> domain;
  CsrTable values;     ///< phi_I at the point
  CsrTable gradients;  ///< grad phi_I (SCNI: smoothed B~_I), dimension per entry

  std::size_t size() const { return weight.size(); }
};

struct ShapeFunctionValues;
/// The values (gradients = false) or gradients of evaluated shape functions as a table.
CsrTable table_from(const ShapeFunctionValues& v, bool gradients, int dim);

/// Builds the integration points of the cells of `part` that this rank owns (SCNI and nodal:
/// owned particles; Gauss: cells whose lowest node is owned), with shape functions from `cloud`
/// (owned and ghost particles). `owner` is the owning rank of every mesh node.
IntegrationPoints integrate_part(const BackgroundMesh& mesh, const PartSpec& part,
                                 const ParticleCloud& cloud, const std::vector<int>& owner,
                                 int rank);

/// Distance from an owned node within which every particle that can reach one of this rank's
/// integration points lies: twice the largest support reach plus the largest cell diameter of the
/// part, or `group_diameter` when larger (the pressure cells of a mixed u-p part).
double ghost_radius(const BackgroundMesh& mesh, const PartSpec& part, double group_diameter = 0);

}  // namespace efg
