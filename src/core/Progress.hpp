// Stage progress: a self-overwriting line with ETA on a terminal, plain periodic lines otherwise.
#pragma once

#include <chrono>
#include <string>

namespace efg {

class Progress {
 public:
  /// `total` is the stage's end (time or step count); `interactive` selects the terminal form
  /// (default: whether stderr is a terminal, on rank 0).
  Progress(std::string label, double total, bool interactive);
  Progress(std::string label, double total);

  /// Reports that `done` of `total` is complete. Prints at most every 0.2 s on a terminal and
  /// every 10 % otherwise.
  void update(double done);
  void finish();

  /// "stage 'impact':  45.0 %  t = 4.5e-04  elapsed 3.2 s  ETA 3.9 s" (exposed for tests).
  static std::string format(const std::string& label, double done, double total,
                            double elapsed_seconds);

 private:
  std::string label_;
  double total_;
  bool interactive_;
  double last_fraction_printed_ = -1.0;
  std::chrono::steady_clock::time_point start_, last_print_;
};

}  // namespace efg
