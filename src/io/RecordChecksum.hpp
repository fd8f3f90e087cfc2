// A checksum of every record efg writes, kept in the results file itself, so that a restart
// (initial_state) refuses a record whose bytes changed after it was written (a flipped bit on a
// disk or in a copy): the netCDF container checks no data, and a changed double is still a
// plausible number. The checksum is FNV-1a (64-bit, Fowler-Noll-Vo) over the record's values in
// a fixed order (time, nodal variables, element variables block by block, globals), folded to 53
// bits so that a double holds it exactly; it lives in a netCDF record variable of its own
// ("efg_record_checksum"), which Exodus readers (ParaView, exodiff, epu) do not see.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace efg {

/// FNV-1a over the bytes of doubles, in the order they are added.
class RecordHash {
 public:
  void add(const double* values, std::size_t count);
  /// The hash folded to 53 bits: exact in a double.
  double value() const;

 private:
  std::uint64_t h_ = 14695981039346656037ull;  // the FNV-1a 64-bit offset basis
};

namespace exodus {
class File;

/// Defines the checksum variable in a file being written (before any record; returns its id).
int define_record_checksum(const File& file);
/// Stores the checksum of record `step` (1-based).
void put_record_checksum(const File& file, int variable, int step, double checksum);
/// The stored checksum of record `step` (1-based); nullopt when the file has none (written by
/// another program or an efg before checksums).
std::optional<double> get_record_checksum(const File& file, int step);
}  // namespace exodus

}  // namespace efg
