#include "io/ExodusEntities.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/Errors.hpp"

namespace efg::exodus {

MeshHeader read_mesh_header(const File& f, const std::string& path) {
  ex_set_max_name_length(f.id(), kNameLength);
  char title[MAX_LINE_LENGTH + 1] = {};
  std::int64_t dim = 0;
  MeshHeader h;
  f.check(
      ex_get_init(f.id(), title, &dim, &h.nodes, &h.cells, &h.blocks, &h.node_sets, &h.side_sets),
      "reading the header");
  if (dim != 2 && dim != 3)
    throw InputError("mesh file '" + path + "': dimension " + std::to_string(dim) +
                     " is not supported (expected 2 or 3)");
  h.dimension = static_cast<int>(dim);
  return h;
}

std::vector<double> read_coordinates(const File& f, int dimension, std::int64_t first,
                                     std::int64_t count) {
  std::vector<double> x(static_cast<std::size_t>(count)), y(x.size()), z(x.size());
  if (count > 0)
    f.check(ex_get_partial_coord(f.id(), first + 1, count, x.data(), y.data(),
                                 dimension == 3 ? z.data() : nullptr),
            "reading coordinates");
  std::vector<double> xyz;
  xyz.reserve(static_cast<std::size_t>(dimension * count));
  for (std::size_t n = 0; n < x.size(); ++n) {
    xyz.push_back(x[n]);
    xyz.push_back(y[n]);
    if (dimension == 3) xyz.push_back(z[n]);
  }
  return xyz;
}

std::vector<std::string> read_variable_names(const File& f, ex_entity_type type) {
  int count = 0;
  f.check(ex_get_variable_param(f.id(), type, &count), "reading variable counts");
  std::vector<std::vector<char>> storage(static_cast<std::size_t>(count),
                                         std::vector<char>(kNameLength + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& s : storage) pointers.push_back(s.data());
  if (count > 0)
    f.check(ex_get_variable_names(f.id(), type, count, pointers.data()), "reading variable names");
  std::vector<std::string> names;
  for (auto& s : storage) names.emplace_back(s.data());
  return names;
}

std::vector<std::int64_t> read_ids(const File& f, ex_entity_type type, std::int64_t count) {
  std::vector<std::int64_t> ids(static_cast<std::size_t>(count));
  if (count > 0) f.check(ex_get_ids(f.id(), type, ids.data()), "reading entity ids");
  return ids;
}

std::vector<std::string> read_names(const File& f, ex_entity_type type, std::size_t count,
                                    const std::vector<std::int64_t>& ids, const char* prefix) {
  std::vector<std::vector<char>> storage(count, std::vector<char>(kNameLength + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& s : storage) pointers.push_back(s.data());
  if (count > 0) f.check(ex_get_names(f.id(), type, pointers.data()), "reading names");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < count; ++i) {
    std::string name(storage[i].data());
    if (name.empty()) name = std::string(prefix) + std::to_string(ids[i]);
    names.push_back(name);
  }
  return names;
}

namespace {

int thickness_attribute(const File& f, std::int64_t id, std::int64_t attributes) {
  std::vector<std::vector<char>> storage(static_cast<std::size_t>(attributes),
                                         std::vector<char>(kNameLength + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& n : storage) pointers.push_back(n.data());
  f.check(ex_get_attr_names(f.id(), EX_ELEM_BLOCK, id, pointers.data()), "reading attribute names");
  int which = attributes == 1 ? 1 : 0;
  for (std::int64_t a = 0; a < attributes; ++a) {
    std::string name(storage[static_cast<std::size_t>(a)].data());
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (name == "thickness") which = static_cast<int>(a + 1);
  }
  return which;
}

}  // namespace

std::int64_t block_cell_count(const File& f, std::int64_t id) {
  char type_name[MAX_STR_LENGTH + 1] = {};
  std::int64_t count = 0, per_cell = 0, edges = 0, faces = 0, attributes = 0;
  f.check(ex_get_block(f.id(), EX_ELEM_BLOCK, id, type_name, &count, &per_cell, &edges, &faces,
                       &attributes),
          "reading an element block");
  return count;
}

BlockHeader read_block_header(const File& f, const std::string& path, std::int64_t id,
                              const std::string& name) {
  char type_name[MAX_STR_LENGTH + 1] = {};
  std::int64_t count = 0, per_cell = 0, edges = 0, faces = 0, attributes = 0;
  f.check(ex_get_block(f.id(), EX_ELEM_BLOCK, id, type_name, &count, &per_cell, &edges, &faces,
                       &attributes),
          "reading an element block");
  const auto type = cell_type_from_exodus_name(type_name);
  if (!type || cell_node_count(*type) != per_cell)
    throw InputError("mesh file '" + path + "': block '" + name + "' has element type '" +
                     type_name + "' with " + std::to_string(per_cell) +
                     " nodes; supported: HEX8, TETRA4, WEDGE6 (3D), QUAD4, TRI3 (2D), SHELL4, "
                     "TRISHELL3 (shell surfaces in 3D)");
  BlockHeader h{*type, count, per_cell, 0};
  if (attributes > 0 && cell_dimension(*type) == 2)  // a shell's surface cells
    h.thickness_attribute = thickness_attribute(f, id, attributes);
  return h;
}

std::vector<double> read_thickness(const File& f, const std::string& path, const std::string& block,
                                   std::int64_t id, int attribute, std::int64_t first,
                                   std::int64_t count) {
  std::vector<double> values(static_cast<std::size_t>(count));
  if (count > 0)
    f.check(ex_get_partial_one_attr(f.id(), EX_ELEM_BLOCK, id, first + 1, count, attribute,
                                    values.data()),
            "reading the thickness attribute");
  for (std::size_t c = 0; c < values.size(); ++c)
    if (!(values[c] > 0) || !std::isfinite(values[c]))
      throw InputError("mesh file '" + path + "': block '" + block + "', cell " +
                       std::to_string(static_cast<std::int64_t>(c) + first + 1) +
                       ": thickness attribute " + std::to_string(values[c]) +
                       "; expected a finite value > 0");
  return values;
}

}  // namespace efg::exodus
