// Background cell types efg reads, writes and integrates over, with the Exodus II node and side
// ordering (Sjaardema et al., "Exodus II: A Finite Element Data Model", SAND92-2137, fig. 4-7).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace efg {

enum class CellType { quad4, tri3, hex8, tet4, wedge6 };

/// Spatial dimension of a cell type (2 for quad4/tri3, 3 otherwise).
int cell_dimension(CellType type);
/// Number of nodes of a cell type.
int cell_node_count(CellType type);
/// Number of sides (edges in 2D, faces in 3D).
int cell_side_count(CellType type);
/// Local node indices (0-based) of side `side` (0-based), ordered so that the side's normal by the
/// right-hand rule points out of the cell.
std::vector<int> cell_side_nodes(CellType type, int side);
/// The cell's edges as pairs of local node indices (0-based), each edge once: the sides in 2D,
/// the sides' boundary segments in 3D.
std::vector<std::array<int, 2>> cell_edges(CellType type);

/// The Exodus element type name written to files ("QUAD4", "TRI3", "HEX8", "TETRA4", "WEDGE6").
std::string cell_exodus_name(CellType type);
/// Parses an Exodus element type name (case-insensitive; "HEX", "TETRA", "TET4", "SHELL"... are
/// recognised where they mean a supported type). Returns nothing for unsupported types.
std::optional<CellType> cell_type_from_exodus_name(const std::string& name);
/// The lower-case name used in scene files ("quad4", "tri3", "hex8", "tet4", "wedge6").
std::string cell_scene_name(CellType type);

/// Geometry of one cell from its node coordinates (dim components per node, node after node).
struct CellGeometry {
  double volume = 0.0;          ///< area in 2D
  double min_corner_det = 0.0;  ///< smallest Jacobian determinant over the corners
};
CellGeometry cell_geometry(CellType type, const double* node_coords);
/// The Jacobian determinant of the cell's map at each of its corners, in node order.
std::vector<double> cell_corner_jacobians(CellType type, const double* node_coords);

}  // namespace efg
