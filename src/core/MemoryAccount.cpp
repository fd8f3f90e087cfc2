#include "core/MemoryAccount.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

namespace efg {

MemoryAccount& MemoryAccount::process() {
  static MemoryAccount account;
  return account;
}

MemoryAccount::MemoryAccount() : last_(resident_bytes()) {}

long long MemoryAccount::resident_bytes() {
  std::ifstream statm("/proc/self/statm");  // total and resident pages
  long long total = 0, resident = 0;
  if (!(statm >> total >> resident)) return 0;
  return resident * static_cast<long long>(sysconf(_SC_PAGESIZE));
}

long long MemoryAccount::peak_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

void MemoryAccount::mark(const std::string& phase) {
  const long long now = resident_bytes();
  const long long growth = now - last_;
  last_ = now;
  for (auto& p : phases_)
    if (p.name == phase) {
      p.growth += growth;
      p.peak = peak_bytes();
      return;
    }
  phases_.push_back({phase, growth, peak_bytes()});
}

void MemoryAccount::reset() {
  phases_.clear();
  last_ = resident_bytes();
}

}  // namespace efg
