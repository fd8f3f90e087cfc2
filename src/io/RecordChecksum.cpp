#include "io/RecordChecksum.hpp"

#include <netcdf.h>

#include <cstring>
#include <stdexcept>

#include "io/ExodusFile.hpp"

namespace efg {
namespace {
constexpr const char* kVariable = "efg_record_checksum";
constexpr const char* kTimeDimension = "time_step";  // Exodus II's record dimension
}  // namespace

void RecordHash::add(const double* values, std::size_t count) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(values);
  for (std::size_t i = 0; i < count * sizeof(double); ++i) {
    h_ ^= bytes[i];
    h_ *= 1099511628211ull;  // the FNV 64-bit prime
  }
}

double RecordHash::value() const {
  return static_cast<double>(h_ & ((std::uint64_t{1} << 53) - 1));
}

namespace exodus {

int define_record_checksum(const File& file) {
  const int id = file.id();
  int dimension = -1, variable = -1;
  file.check(nc_redef(id) == NC_NOERR ? 0 : -1, "entering define mode for the checksums");
  const bool made = nc_inq_dimid(id, kTimeDimension, &dimension) == NC_NOERR &&
                    nc_def_var(id, kVariable, NC_DOUBLE, 1, &dimension, &variable) == NC_NOERR;
  file.check(nc_enddef(id) == NC_NOERR && made ? 0 : -1, "defining the record checksums");
  return variable;
}

void put_record_checksum(const File& file, int variable, int step, double checksum) {
  const std::size_t index = static_cast<std::size_t>(step - 1);
  file.check(nc_put_var1_double(file.id(), variable, &index, &checksum) == NC_NOERR ? 0 : -1,
             "writing a record checksum");
}

std::optional<double> get_record_checksum(const File& file, int step) {
  int variable = -1;
  if (nc_inq_varid(file.id(), kVariable, &variable) != NC_NOERR) return std::nullopt;
  const std::size_t index = static_cast<std::size_t>(step - 1);
  double value = 0;
  file.check(nc_get_var1_double(file.id(), variable, &index, &value) == NC_NOERR ? 0 : -1,
             "reading a record checksum");
  return value;
}

}  // namespace exodus
}  // namespace efg
