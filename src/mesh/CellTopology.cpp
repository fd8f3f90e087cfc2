#include "mesh/CellTopology.hpp"

#include "mesh/GaussRules.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace efg {
namespace {

// Exodus side tables, 1-based in the Exodus manual, 0-based here.
const std::vector<std::vector<int>> kQuad4Sides = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
const std::vector<std::vector<int>> kTri3Sides = {{0, 1}, {1, 2}, {2, 0}};
const std::vector<std::vector<int>> kHex8Sides = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                  {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
const std::vector<std::vector<int>> kTet4Sides = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
const std::vector<std::vector<int>> kWedge6Sides = {
    {0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};

const std::vector<std::vector<int>>& side_table(CellType type) {
  switch (type) {
    case CellType::quad4:
      return kQuad4Sides;
    case CellType::tri3:
      return kTri3Sides;
    case CellType::hex8:
      return kHex8Sides;
    case CellType::tet4:
      return kTet4Sides;
    case CellType::wedge6:
      return kWedge6Sides;
  }
  throw std::logic_error("unknown cell type");
}

}  // namespace

int cell_dimension(CellType type) {
  return (type == CellType::quad4 || type == CellType::tri3) ? 2 : 3;
}

int cell_node_count(CellType type) {
  switch (type) {
    case CellType::quad4:
      return 4;
    case CellType::tri3:
      return 3;
    case CellType::hex8:
      return 8;
    case CellType::tet4:
      return 4;
    case CellType::wedge6:
      return 6;
  }
  throw std::logic_error("unknown cell type");
}

int cell_side_count(CellType type) {
  return static_cast<int>(side_table(type).size());
}

std::vector<int> cell_side_nodes(CellType type, int side) {
  const auto& table = side_table(type);
  if (side < 0 || side >= static_cast<int>(table.size()))
    throw std::out_of_range("side index out of range for " + cell_scene_name(type));
  return table[static_cast<std::size_t>(side)];
}

std::vector<std::array<int, 2>> cell_edges(CellType type) {
  std::vector<std::array<int, 2>> edges;
  for (const auto& side : side_table(type)) {
    // a 2D side is an edge; a 3D face is bounded by a cycle of edges, each shared by two faces
    const std::size_t segments = cell_dimension(type) == 2 ? 1 : side.size();
    for (std::size_t k = 0; k < segments; ++k) {
      std::array<int, 2> e = {side[k], side[(k + 1) % side.size()]};
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      if (std::find(edges.begin(), edges.end(), e) == edges.end()) edges.push_back(e);
    }
  }
  return edges;
}

std::string cell_exodus_name(CellType type) {
  switch (type) {
    case CellType::quad4:
      return "QUAD4";
    case CellType::tri3:
      return "TRI3";
    case CellType::hex8:
      return "HEX8";
    case CellType::tet4:
      return "TETRA4";
    case CellType::wedge6:
      return "WEDGE6";
  }
  throw std::logic_error("unknown cell type");
}

std::string cell_scene_name(CellType type) {
  switch (type) {
    case CellType::quad4:
      return "quad4";
    case CellType::tri3:
      return "tri3";
    case CellType::hex8:
      return "hex8";
    case CellType::tet4:
      return "tet4";
    case CellType::wedge6:
      return "wedge6";
  }
  throw std::logic_error("unknown cell type");
}

std::optional<CellType> cell_type_from_exodus_name(const std::string& name) {
  std::string n;
  for (char c : name) n += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  // shell cells (SHELL4, TRISHELL3) are the surface cells of a 3D shell mesh
  if (n == "QUAD" || n == "QUAD4" || n == "SHELL" || n == "SHELL4") return CellType::quad4;
  if (n == "TRI" || n == "TRI3" || n == "TRIANGLE" || n == "TRISHELL" || n == "TRISHELL3")
    return CellType::tri3;
  if (n == "HEX" || n == "HEX8") return CellType::hex8;
  if (n == "TET" || n == "TET4" || n == "TETRA" || n == "TETRA4") return CellType::tet4;
  if (n == "WEDGE" || n == "WEDGE6") return CellType::wedge6;
  return std::nullopt;
}

CellGeometry cell_geometry(CellType type, const double* x) {
  // det J of the isoparametric map is a polynomial of degree <= 2 in each reference direction
  // (trilinear hex, bilinear quad, wedge) or constant (simplices): 2-point rules are exact.
  // The rules and corners are built once per type (this runs for every cell of a mesh, twice).
  struct Reference {
    ReferenceRule rule;
    std::vector<double> corners;
  };
  static const std::array<Reference, 5> by_type = [] {
    std::array<Reference, 5> r;
    for (auto t :
         {CellType::quad4, CellType::tri3, CellType::hex8, CellType::tet4, CellType::wedge6})
      r[static_cast<std::size_t>(t)] = {reference_rule(t, 2), reference_corners(t)};
    return r;
  }();
  const auto& rule = by_type[static_cast<std::size_t>(type)].rule;
  CellGeometry g;
  const auto dim = static_cast<std::size_t>(cell_dimension(type));
  double point[3];
  for (std::size_t q = 0; q < rule.weight.size(); ++q)
    g.volume += rule.weight[q] * map_to_cell(type, x, &rule.xi[q * dim], point);
  g.min_corner_det = std::numeric_limits<double>::max();
  const auto& corners = by_type[static_cast<std::size_t>(type)].corners;
  for (std::size_t c = 0; c < corners.size() / dim; ++c)
    g.min_corner_det = std::min(g.min_corner_det, map_to_cell(type, x, &corners[c * dim], point));
  return g;
}

std::vector<double> cell_corner_jacobians(CellType type, const double* x) {
  const auto corners = reference_corners(type);
  const auto dim = static_cast<std::size_t>(cell_dimension(type));
  std::vector<double> det(corners.size() / dim);
  double point[3];
  for (std::size_t c = 0; c < det.size(); ++c)
    det[c] = map_to_cell(type, x, &corners[c * dim], point);
  return det;
}

}  // namespace efg
