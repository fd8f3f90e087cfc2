// Where a run's memory goes, measured: the resident set of the process is read at the end of each
// setup phase and stage (/proc/self/statm), and each phase is charged the growth since the
// previous mark. What a phase builds and keeps (the mesh, the shape-function tables, the
// stiffness graph, a factorization) shows as its growth; what it frees shows as a negative one.
// One account per process, filled in run order (as Teuchos' timers are), reduced over ranks and
// divided by the particle count in the log and the run report (issue 20: bytes per particle).
#pragma once

#include <string>
#include <vector>

namespace efg {

class MemoryAccount {
 public:
  /// The account of this process.
  static MemoryAccount& process();

  /// Charges `phase` with the growth of the resident set since the previous mark (or since the
  /// account was first used). A phase marked twice adds up.
  void mark(const std::string& phase);
  /// Forgets every phase (a new run in the same process, e.g. `efg study`); the next mark
  /// starts from the resident set now.
  void reset();

  struct Phase {
    std::string name;
    long long growth = 0;  ///< resident bytes kept (or freed, negative) by the phase
    long long peak = 0;    ///< the process's high-water mark when the phase ended
  };
  /// Phases in the order first marked. A peak above the previous phase's was reached inside
  /// the phase: its temporaries (freed before it ended) are the difference to the growth.
  const std::vector<Phase>& phases() const { return phases_; }

  /// Resident bytes of this process now (0 where /proc is unavailable).
  static long long resident_bytes();
  /// The high-water mark of the resident set of this process so far (getrusage).
  static long long peak_bytes();

 private:
  MemoryAccount();
  std::vector<Phase> phases_;
  long long last_ = 0;
};

}  // namespace efg
