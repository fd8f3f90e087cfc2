// Reading one record of a results file (a restart, scene key initial_state) for a range of its
// nodes: the header (sizes, times, nodal variable names) and, for nodes [first, first + count),
// their coordinates and the named nodal variables at one record, through Exodus' partial reads.
// The whole file is one range; a mesh read in slices reads each rank's slice (run/InitialState).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace efg {

struct ResultsHeader {
  int dimension = 3;
  std::int64_t nodes = 0;
  std::vector<double> times;  ///< of every record
  std::vector<std::string> nodal_names;
};

/// Throws InputError when the file cannot be read.
ResultsHeader read_results_header(const std::string& path);

struct NodalRecordSlice {
  std::vector<double> coordinates;                    ///< `dimension` per node
  std::map<std::string, std::vector<double>> values;  ///< name -> one value per node
};

/// The coordinates and the nodal variables `names` (each in the header's names) at record
/// `record` (0-based) of nodes [first, first + count). Throws InputError when unreadable.
NodalRecordSlice read_nodal_record(const std::string& path, const ResultsHeader& header,
                                   std::size_t record, const std::vector<std::string>& names,
                                   std::int64_t first, std::int64_t count);

/// "" when record `record` (0-based) matches the checksum efg stored with it, or when the file
/// has none (io/RecordChecksum); otherwise what is wrong. Reads the whole record.
std::string record_checksum_problem(const std::string& path, std::size_t record);

}  // namespace efg
