// Reading an Exodus file's entity lists (ids, names, element block headers and the shell
// thickness attribute): shared by the whole-mesh reader and the slice reader.
#pragma once

#include <exodusII.h>
#include <cstdint>
#include <string>
#include <vector>

#include "io/ExodusFile.hpp"
#include "mesh/CellTopology.hpp"

namespace efg::exodus {

constexpr int kNameLength = 256;

struct MeshHeader {
  int dimension = 3;
  std::int64_t nodes = 0, cells = 0, blocks = 0, node_sets = 0, side_sets = 0;
};

/// The file's sizes (names up to kNameLength from here on); InputError for a dimension other
/// than 2 or 3.
MeshHeader read_mesh_header(const File& f, const std::string& path);

/// Coordinates of `count` nodes from `first` (0-based), node after node, `dimension` each.
std::vector<double> read_coordinates(const File& f, int dimension, std::int64_t first,
                                     std::int64_t count);

std::vector<std::int64_t> read_ids(const File& f, ex_entity_type type, std::int64_t count);

/// The names of the file's variables of `type` (EX_NODAL, EX_ELEM_BLOCK, EX_GLOBAL), in order.
std::vector<std::string> read_variable_names(const File& f, ex_entity_type type);

/// The number of cells of element block `id`.
std::int64_t block_cell_count(const File& f, std::int64_t id);

/// Entity names; unnamed entities get `prefix` followed by their id ("block_7").
std::vector<std::string> read_names(const File& f, ex_entity_type type, std::size_t count,
                                    const std::vector<std::int64_t>& ids, const char* prefix);

struct BlockHeader {
  CellType type = CellType::hex8;
  std::int64_t cells = 0;
  std::int64_t per_cell = 0;
  int thickness_attribute = 0;  ///< 1-based attribute index of a shell's thickness, 0: none
};

/// The block's cell type (InputError naming the block when efg does not support it), sizes and,
/// for surface cells (shells), which attribute is the thickness: the one named "thickness" (any
/// case) or the only attribute of a block with one (the SEACAS and Cubit convention for SHELL4).
BlockHeader read_block_header(const File& f, const std::string& path, std::int64_t id,
                              const std::string& name);

/// Thickness of `count` cells of a block from its `first` (0-based), each checked finite and > 0.
std::vector<double> read_thickness(const File& f, const std::string& path, const std::string& block,
                                   std::int64_t id, int attribute, std::int64_t first,
                                   std::int64_t count);

}  // namespace efg::exodus
