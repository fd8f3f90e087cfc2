// A cheap plausibility walk over the header of a classic netCDF file (CDF-1, CDF-2 64-bit offset,
// CDF-5), the container of most Exodus II files, before the netCDF library opens it. A corrupted
// count in the header makes the library allocate and clear whatever the count says (a flipped
// byte cost 36 s and gigabytes in the input fuzzer) before it fails. Every count and length is
// checked against the bytes the file has. Format: "The NetCDF Classic Format Specification"
// (docs.unidata.ucar.edu/netcdf-c, file_format_specifications). HDF5-based (netCDF-4) files are
// left to the library.
#pragma once

#include <string>

namespace efg::exodus {

/// Empty when the header is plausible (or not a classic netCDF file); otherwise what is wrong.
std::string classic_header_problem(const std::string& path);

}  // namespace efg::exodus
