#include "io/ExodusRecordReader.hpp"

#include <exodusII.h>

#include <algorithm>
#include <sstream>

#include "core/Errors.hpp"
#include "io/ExodusEntities.hpp"
#include "io/ExodusFile.hpp"
#include "io/RecordChecksum.hpp"

namespace efg {

ResultsHeader read_results_header(const std::string& path) {
  auto f = exodus::File::open_read(path, "results file");
  const auto mesh = exodus::read_mesh_header(f, path);
  ResultsHeader h;
  h.dimension = mesh.dimension;
  h.nodes = mesh.nodes;
  const auto steps = static_cast<std::size_t>(ex_inquire_int(f.id(), EX_INQ_TIME));
  h.times.resize(steps);
  if (steps > 0) f.check(ex_get_all_times(f.id(), h.times.data()), "reading the record times");
  h.nodal_names = exodus::read_variable_names(f, EX_NODAL);
  return h;
}

NodalRecordSlice read_nodal_record(const std::string& path, const ResultsHeader& header,
                                   std::size_t record, const std::vector<std::string>& names,
                                   std::int64_t first, std::int64_t count) {
  auto f = exodus::File::open_read(path, "results file");
  exodus::read_mesh_header(f, path);  // names up to kNameLength, as the header was read
  NodalRecordSlice slice;
  slice.coordinates = exodus::read_coordinates(f, header.dimension, first, count);
  for (const auto& name : names) {
    const auto it = std::find(header.nodal_names.begin(), header.nodal_names.end(), name);
    if (it == header.nodal_names.end())
      throw InputError("results file '" + path + "' has no nodal variable '" + name + "'");
    auto& values = slice.values[name];
    values.resize(static_cast<std::size_t>(count));
    if (count > 0)
      f.check(ex_get_partial_var(f.id(), static_cast<int>(record + 1), EX_NODAL,
                                 static_cast<int>(it - header.nodal_names.begin() + 1), 1,
                                 first + 1, count, values.data()),
              "reading a nodal variable");
  }
  return slice;
}

std::string record_checksum_problem(const std::string& path, std::size_t record) {
  auto f = exodus::File::open_read(path, "results file");
  const int step = static_cast<int>(record + 1);
  const auto stored = exodus::get_record_checksum(f, step);
  if (!stored) return "";
  // The values in the order the writer hashed them (io/ExodusWriter::write_record).
  RecordHash hash;
  double time = 0;
  f.check(ex_get_time(f.id(), step, &time), "reading a time value");
  hash.add(&time, 1);
  const auto nodes = ex_inquire_int(f.id(), EX_INQ_NODES);
  std::vector<double> values;
  auto add = [&](ex_entity_type type, int variable, std::int64_t id, std::int64_t count) {
    values.resize(static_cast<std::size_t>(count));
    f.check(ex_get_var(f.id(), step, type, variable, id, count, values.data()),
            "reading a variable");
    hash.add(values.data(), values.size());
  };
  int nodal = 0, element = 0, global = 0;
  f.check(ex_get_variable_param(f.id(), EX_NODAL, &nodal), "reading variable counts");
  f.check(ex_get_variable_param(f.id(), EX_ELEM_BLOCK, &element), "reading variable counts");
  f.check(ex_get_variable_param(f.id(), EX_GLOBAL, &global), "reading variable counts");
  for (int v = 1; v <= nodal; ++v) add(EX_NODAL, v, 1, nodes);
  if (element > 0) {
    const auto ids = exodus::read_ids(f, EX_ELEM_BLOCK, ex_inquire_int(f.id(), EX_INQ_ELEM_BLK));
    for (int v = 1; v <= element; ++v)
      for (auto id : ids) add(EX_ELEM_BLOCK, v, id, exodus::block_cell_count(f, id));
  }
  if (global > 0) add(EX_GLOBAL, 1, 0, global);
  if (hash.value() == *stored) return "";
  std::ostringstream o;
  o.precision(10);
  o << "record " << step << " (t = " << time
    << ") does not match the checksum written with it: the file was changed or damaged after "
       "the run wrote it";
  return o.str();
}

}  // namespace efg
