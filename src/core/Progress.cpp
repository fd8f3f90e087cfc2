#include "core/Progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <sstream>

#include "core/Log.hpp"

namespace efg {

Progress::Progress(std::string label, double total, bool interactive)
    : label_(std::move(label)),
      total_(total),
      interactive_(interactive),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

Progress::Progress(std::string label, double total)
    : Progress(std::move(label), total, Log::is_root() && isatty(fileno(stderr))) {}

std::string Progress::format(const std::string& label, double done, double total, double elapsed) {
  const double fraction = total > 0 ? done / total : 1.0;
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(1);
  o << label << ": " << 100.0 * fraction << " %  t = ";
  o.unsetf(std::ios::fixed);
  o.precision(4);
  o << done << "  elapsed " << elapsed << " s";
  if (fraction > 0 && fraction < 1) o << "  ETA " << elapsed * (1 - fraction) / fraction << " s";
  return o.str();
}

void Progress::update(double done) {
  if (!Log::is_root()) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = total_ > 0 ? done / total_ : 1.0;
  if (interactive_) {
    if (std::chrono::duration<double>(now - last_print_).count() < 0.2 && fraction < 1) return;
    std::cerr << "\r" << format(label_, done, total_, elapsed) << "   " << std::flush;
  } else {
    if (fraction < last_fraction_printed_ + 0.1 && fraction < 1) return;
    std::cout << format(label_, done, total_, elapsed) << std::endl;
    last_fraction_printed_ = fraction;
  }
  last_print_ = now;
}

void Progress::finish() {
  if (interactive_ && Log::is_root()) std::cerr << std::endl;
}

}  // namespace efg
