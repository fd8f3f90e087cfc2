#include "io/ExodusWriter.hpp"

#include <exodusII.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/Errors.hpp"
#include "io/RecordChecksum.hpp"
#include "io/WritePaths.hpp"

namespace efg {
namespace {

// Exodus API takes char** for names it does not modify.
struct NameArray {
  explicit NameArray(const std::vector<std::string>& names) : storage(names) {
    for (auto& s : storage) pointers.push_back(s.data());
  }
  std::vector<std::string> storage;
  std::vector<char*> pointers;
};

// A non-finite result is numerical trouble (an overflowed state), never written silently.
// (`ids`: the whole mesh's index of each entry of a piece's field; empty: the entry's own)
void require_finite(const std::vector<double>& values, const std::string& name, double time,
                    const char* index_kind, const std::vector<GlobalIndex>& ids = {}) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw NumericalError(
          "the results hold a non-finite value (" + std::to_string(values[i]) +
          ") in output field '" + name + "'" +
          (index_kind ? std::string(" at ") + index_kind + " " +
                            std::to_string((ids.empty() ? static_cast<GlobalIndex>(i) : ids[i]) + 1)
                      : std::string()) +
          ", t = " + std::to_string(time) +
          ": the state overflowed or became undefined; nothing of it is written");
}

}  // namespace

std::vector<std::string> vector_component_names(const std::string& base, int dimension) {
  std::vector<std::string> names = {base + "_x", base + "_y"};
  if (dimension == 3) names.push_back(base + "_z");
  return names;
}

ExodusWriter::ExodusWriter(const std::string& path, const BackgroundMesh& mesh,
                           const OutputLayout& layout, const std::string& title,
                           const ExodusPieceIds* piece)
    : path_(path), layout_(layout), nodes_(mesh.node_count()) {
  for (const auto* names : {&layout.nodal, &layout.element, &layout.global})
    for (const auto& n : *names)
      if (n.size() > MAX_STR_LENGTH)
        throw std::logic_error("output variable name '" + n + "' exceeds 32 characters");
  file_.emplace(exodus::File::create(path_ + ".part"));
  write_mesh(mesh, title);
  if (piece) {
    piece_ = *piece;
    write_piece_ids(*piece);
  }
  write_variable_names(EX_NODAL, layout.nodal);
  write_variable_names(EX_ELEM_BLOCK, layout.element);
  write_variable_names(EX_GLOBAL, layout.global);
  checksum_variable_ = exodus::define_record_checksum(*file_);
  file_->check(ex_update(file_->id()), "flushing the mesh");
}

void ExodusWriter::write_mesh(const BackgroundMesh& mesh, const std::string& title) {
  const int id = file_->id();
  const auto dim = mesh.dimension;
  file_->check(
      ex_put_init(id, title.substr(0, MAX_LINE_LENGTH).c_str(), dim,
                  static_cast<std::int64_t>(nodes_), static_cast<std::int64_t>(mesh.cell_count()),
                  static_cast<std::int64_t>(mesh.blocks.size()),
                  static_cast<std::int64_t>(mesh.node_sets.size()),
                  static_cast<std::int64_t>(mesh.side_sets.size())),
      "writing the header");
  std::vector<double> xyz[3];
  for (std::size_t n = 0; n < nodes_; ++n)
    for (int d = 0; d < dim; ++d)
      xyz[d].push_back(
          mesh.coordinates[n * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)]);
  file_->check(ex_put_coord(id, xyz[0].data(), xyz[1].data(), dim == 3 ? xyz[2].data() : nullptr),
               "writing coordinates");
  NameArray coord_names(std::vector<std::string>{"x", "y", "z"});
  file_->check(ex_put_coord_names(id, coord_names.pointers.data()), "writing coordinate names");

  std::vector<std::string> names;
  for (const auto& b : mesh.blocks) {
    const auto per = cell_node_count(b.type);
    // 2D cells in a 3D mesh are a shell surface: SHELL4 / TRISHELL3, as ParaView and SEACAS read
    // shells
    const bool shell = dim == 3 && cell_dimension(b.type) == 2;
    const auto type =
        shell ? (b.type == CellType::quad4 ? "SHELL4" : "TRISHELL3") : cell_exodus_name(b.type);
    file_->check(ex_put_block(id, EX_ELEM_BLOCK, b.id, type.c_str(),
                              static_cast<std::int64_t>(b.cell_count()), per, 0, 0, 0),
                 "writing a block");
    std::vector<std::int64_t> conn;
    for (auto n : b.connectivity) conn.push_back(n + 1);
    if (!conn.empty())
      file_->check(ex_put_conn(id, EX_ELEM_BLOCK, b.id, conn.data(), nullptr, nullptr),
                   "writing connectivity");
    blocks_.emplace_back(b.id, b.cell_count());
    names.push_back(b.name);
  }
  if (!names.empty())
    file_->check(ex_put_names(id, EX_ELEM_BLOCK, NameArray(names).pointers.data()),
                 "writing block names");

  names.clear();
  for (const auto& s : mesh.node_sets) {
    file_->check(
        ex_put_set_param(id, EX_NODE_SET, s.id, static_cast<std::int64_t>(s.nodes.size()), 0),
        "writing a node set");
    std::vector<std::int64_t> entries;
    for (auto n : s.nodes) entries.push_back(n + 1);
    if (!entries.empty())
      file_->check(ex_put_set(id, EX_NODE_SET, s.id, entries.data(), nullptr),
                   "writing a node set");
    names.push_back(s.name);
  }
  if (!names.empty())
    file_->check(ex_put_names(id, EX_NODE_SET, NameArray(names).pointers.data()),
                 "writing node set names");

  names.clear();
  for (const auto& s : mesh.side_sets) {
    file_->check(
        ex_put_set_param(id, EX_SIDE_SET, s.id, static_cast<std::int64_t>(s.cells.size()), 0),
        "writing a side set");
    std::vector<std::int64_t> cells, sides;
    for (std::size_t i = 0; i < s.cells.size(); ++i) {
      cells.push_back(s.cells[i] + 1);
      sides.push_back(s.sides[i] + 1);
    }
    if (!cells.empty())
      file_->check(ex_put_set(id, EX_SIDE_SET, s.id, cells.data(), sides.data()),
                   "writing a side set");
    names.push_back(s.name);
  }
  if (!names.empty())
    file_->check(ex_put_names(id, EX_SIDE_SET, NameArray(names).pointers.data()),
                 "writing side set names");
}

void ExodusWriter::write_piece_ids(const ExodusPieceIds& piece) {
  const int id = file_->id();
  for (const auto& [type, ids] :
       {std::pair{EX_NODE_MAP, &piece.nodes}, std::pair{EX_ELEM_MAP, &piece.cells}}) {
    std::vector<std::int64_t> one_based(ids->begin(), ids->end());
    for (auto& i : one_based) ++i;
    if (!one_based.empty())
      file_->check(ex_put_id_map(id, type, one_based.data()), "writing an id map");
  }
  // Nemesis' processor count ("p": a parallel file), which the SEACAS tools read
  file_->check(ex_put_init_info(id, piece.ranks, 1, const_cast<char*>("p")),
               "writing the processor count");
}

void ExodusWriter::write_variable_names(int type, const std::vector<std::string>& names) {
  if (names.empty()) return;
  const auto t = static_cast<ex_entity_type>(type);
  const int n = static_cast<int>(names.size());
  file_->check(ex_put_variable_param(file_->id(), t, n), "writing variable counts");
  file_->check(ex_put_variable_names(file_->id(), t, n, NameArray(names).pointers.data()),
               "writing variable names");
  if (t == EX_ELEM_BLOCK) {
    std::vector<int> truth(blocks_.size() * names.size(), 1);
    file_->check(
        ex_put_truth_table(file_->id(), t, static_cast<int>(blocks_.size()), n, truth.data()),
        "writing the element truth table");
  }
}

void ExodusWriter::write_record(double time, const std::vector<std::vector<double>>& nodal,
                                const std::vector<std::vector<double>>& element,
                                const std::vector<double>& global) {
  if (!file_) throw std::logic_error("write_record after close");
  if (nodal.size() != layout_.nodal.size() || element.size() != layout_.element.size() ||
      global.size() != layout_.global.size())
    throw std::logic_error("output record does not match the output layout");
  const int id = file_->id();
  const int step = records_ + 1;
  // The record's checksum, over its values in the order they are written (io/RecordChecksum).
  RecordHash hash;
  hash.add(&time, 1);
  file_->check(ex_put_time(id, step, &time), "writing a time value");
  for (std::size_t v = 0; v < nodal.size(); ++v) {
    if (nodal[v].size() != nodes_) throw std::logic_error("nodal field of wrong length");
    require_finite(nodal[v], layout_.nodal[v], time, "node", piece_.nodes);
    file_->check(ex_put_var(id, step, EX_NODAL, static_cast<int>(v + 1), 1,
                            static_cast<std::int64_t>(nodes_), nodal[v].data()),
                 "writing a nodal variable");
    hash.add(nodal[v].data(), nodes_);
  }
  for (std::size_t v = 0; v < element.size(); ++v) {
    require_finite(element[v], layout_.element[v], time, "cell", piece_.cells);
    std::size_t offset = 0;
    for (const auto& [block_id, count] : blocks_) {
      if (offset + count > element[v].size()) throw std::logic_error("element field too short");
      file_->check(ex_put_var(id, step, EX_ELEM_BLOCK, static_cast<int>(v + 1), block_id,
                              static_cast<std::int64_t>(count), element[v].data() + offset),
                   "writing an element variable");
      hash.add(element[v].data() + offset, count);
      offset += count;
    }
  }
  if (!global.empty()) {
    for (std::size_t g = 0; g < global.size(); ++g)
      require_finite({global[g]}, layout_.global[g], time, nullptr);
    file_->check(ex_put_var(id, step, EX_GLOBAL, 1, 0, static_cast<std::int64_t>(global.size()),
                            global.data()),
                 "writing global variables");
    hash.add(global.data(), global.size());
  }
  exodus::put_record_checksum(*file_, checksum_variable_, step, hash.value());
  file_->check(ex_update(id), "flushing a record");
  ++records_;
}

ExodusWriter::~ExodusWriter() {
  if (!file_) return;
  try {
    file_->close();
  } catch (...) {
  }
  file_.reset();
  std::error_code ec;
  std::filesystem::remove(path_ + ".part", ec);
}

void ExodusWriter::close(bool keep_partial) {
  if (!file_) return;
  file_->close();
  file_.reset();
  if (keep_partial) return;
  const std::string part = path_ + ".part";
  if (std::rename(part.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + part + "' to '" + path_ + "'" + os_reason(errno));
}

}  // namespace efg
