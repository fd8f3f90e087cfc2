#include "io/ExodusRecordReader.hpp"

#include <exodusII.h>

#include <algorithm>

#include "core/Errors.hpp"
#include "io/ExodusEntities.hpp"
#include "io/ExodusFile.hpp"

namespace efg {

ResultsHeader read_results_header(const std::string& path) {
  auto f = exodus::File::open_read(path);
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
  auto f = exodus::File::open_read(path);
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

}  // namespace efg
