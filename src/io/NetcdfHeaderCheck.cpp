#include "io/NetcdfHeaderCheck.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>
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
    count();          // numrecs
    list(0x0A, [&] {  // dimensions: name, length
      name();
      count();
    });
    attributes();
    list(0x0B, [&] {  // variables: name, dimension ids, attributes, type, size, begin
      name();
      skip(count(), wide());
      attributes();
      type_size(u32());
      count();
      const std::uint64_t begin = version_ == 1 ? u32() : u64();
      if (begin > size_) fail("a variable starts beyond the end of the file");
    });
  }

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
};

}  // namespace

std::string classic_header_problem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";  // the library reports unreadable files
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  if (bytes.size() < 4 || bytes[0] != 'C' || bytes[1] != 'D' || bytes[2] != 'F') return "";
  const int version = bytes[3];
  if (version != 1 && version != 2 && version != 5)
    return "an unknown classic netCDF version " + std::to_string(version);
  const auto size = static_cast<std::uint64_t>(bytes.size());
  try {
    HeaderWalk(std::move(bytes), size, version).walk();
  } catch (const std::out_of_range& e) {
    return e.what();
  }
  return "";
}

}  // namespace efg::exodus
