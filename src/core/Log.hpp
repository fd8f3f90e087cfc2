// The rank-0 log: every rank may call it, only rank 0 prints (Nalu-Wind style).
#pragma once

#include <iostream>
#include <sstream>
#include <string>

namespace efg {

class Log {
 public:
  /// Set once at start-up; ranks other than 0 stay silent.
  static void set_rank(int rank) { rank_ = rank; }
  static bool is_root() { return rank_ == 0; }
  static void info(const std::string& line) {
    if (rank_ == 0) std::cout << line << std::endl;
  }
  static void warning(const std::string& line) {
    if (rank_ == 0) std::cerr << "efg: warning: " << line << std::endl;
  }

 private:
  static inline int rank_ = 0;
};

}  // namespace efg
