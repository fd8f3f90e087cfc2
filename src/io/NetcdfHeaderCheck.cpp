#include "io/NetcdfHeaderCheck.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace efg::exodus {
namespace {

// Reads the big-endian header fields; throws std::out_of_range with the reason when a count or
// length runs past the end of the file.
class HeaderWalk {
 public:
  HeaderWalk(std::vector<unsigned char> bytes, std::uint64_t file_size, int version)
      : b_(std::move(bytes)), size_(file_size), version_(version) {}

  void walk() {
    numrecs_ = count();
    list(0x0A, [&] {  // dimensions: name, length (0: the record dimension)
      name();
      dimension_lengths_.push_back(count());
    });
    attributes();
    list(0x0B, [&] {  // variables: name, dimension ids, attributes, type, size, begin
      name();
      const auto rank = count();
      std::uint64_t first_dimension = 0;
      if (rank > 0) {
        first_dimension = wide() == 8 ? u64() : u32();
        skip(rank - 1, wide());
      }
      attributes();
      type_size(u32());
      const auto vsize = count();
      const std::uint64_t begin = version_ == 1 ? u32() : u64();
      const bool record = rank > 0 && first_dimension < dimension_lengths_.size() &&
                          dimension_lengths_[first_dimension] == 0;
      // (The records of a file with none may start past its end: the library aligns them.)
      if (begin > size_ && !(record && numrecs_ == 0))
        fail("a variable starts beyond the end of the file");
      if (record) {
        record_size_ += vsize;
        record_ends_.push_back(begin + vsize);
      } else {
        data_end_ = std::max(data_end_, begin + vsize);
      }
    });
  }

  /// The bytes the header says the data take: every fixed variable's end and, for the record
  /// variables, numrecs records of record_size bytes each. A file cut short (a copy interrupted,
  /// a run killed while it wrote its last record) is shorter: the library would read zeros.
  std::uint64_t data_extent() const {
    std::uint64_t end = data_end_;
    const bool streaming = numrecs_ == (wide() == 8 ? ~std::uint64_t{0} : 0xFFFFFFFFu);
    if (numrecs_ > 0 && !streaming)
      for (auto e : record_ends_) end = std::max(end, e + (numrecs_ - 1) * record_size_);
    return end;
  }
  std::uint64_t records() const { return numrecs_; }

 private:
  [[noreturn]] static void fail(const std::string& why) { throw std::out_of_range(why); }

  std::uint64_t read(int bytes) {
    if (at_ + static_cast<std::uint64_t>(bytes) > b_.size()) fail("the header is truncated");
    std::uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v = (v << 8) | b_[at_++];
    return v;
  }
  std::uint64_t u32() { return read(4); }
  std::uint64_t u64() { return read(8); }
  int wide() const { return version_ == 5 ? 8 : 4; }
  std::uint64_t count() { return read(wide()); }

  // `n` items of `item` bytes must fit in what is left of the file.
  void skip(std::uint64_t n, std::uint64_t item) {
    const std::uint64_t left = size_ - at_;
    if (item > 0 && n > left / item) fail("a count in the header exceeds the file");
    const std::uint64_t bytes = (n * item + 3) / 4 * 4;  // padded to 4 bytes
    if (bytes > b_.size() - at_) fail("the header is truncated");
    at_ += bytes;
  }
  void name() { skip(count(), 1); }

  static std::uint64_t type_size(std::uint64_t type) {
    switch (type) {
      case 1:
      case 2:
      case 7:
        return 1;  // byte, char, ubyte
      case 3:
      case 8:
        return 2;  // short, ushort
      case 4:
      case 5:
      case 9:
        return 4;  // int, float, uint
      case 6:
      case 10:
      case 11:
        return 8;  // double, int64, uint64
      default:
        fail("an unknown value type in the header");
    }
  }

  template <class Item>
  void list(std::uint64_t tag, const Item& item) {
    const auto t = u32();
    const auto n = count();
    if (t == 0 && n == 0) return;  // ABSENT
    if (t != tag) fail("a malformed list tag in the header");
    if (n > size_ - at_) fail("a list length in the header exceeds the file");
    for (std::uint64_t i = 0; i < n; ++i) item();
  }

  void attributes() {
    list(0x0C, [&] {
      name();
      const auto size = type_size(u32());
      skip(count(), size);
    });
  }

  std::vector<unsigned char> b_;
  std::uint64_t size_, at_ = 4;
  int version_;
  std::uint64_t numrecs_ = 0, record_size_ = 0, data_end_ = 0;
  std::vector<std::uint64_t> dimension_lengths_, record_ends_;
};

}  // namespace

std::string classic_header_problem(const std::string& path) {
  std::error_code ec;
  const auto size = static_cast<std::uint64_t>(std::filesystem::file_size(path, ec));
  if (ec) return "";  // the library reports unreadable files
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  // The header only: it precedes the data, and a file's header is kilobytes (the data may be
  // gigabytes). A header longer than this is reported as truncated.
  constexpr std::uint64_t kHeaderLimit = std::uint64_t{64} << 20;
  std::vector<unsigned char> bytes(static_cast<std::size_t>(std::min(size, kHeaderLimit)));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.size() < 4 || bytes[0] != 'C' || bytes[1] != 'D' || bytes[2] != 'F') return "";
  const int version = bytes[3];
  if (version != 1 && version != 2 && version != 5)
    return "an unknown classic netCDF version " + std::to_string(version);
  try {
    HeaderWalk walk(std::move(bytes), size, version);
    walk.walk();
    if (walk.data_extent() > size)
      return "the file is truncated: its header describes " + std::to_string(walk.records()) +
             " record(s) and " + std::to_string(walk.data_extent()) + " bytes, the file has " +
             std::to_string(size) + " (a copy cut short, or a run stopped while it wrote)";
  } catch (const std::out_of_range& e) {
    return e.what();
  }
  return "";
}

}  // namespace efg::exodus
