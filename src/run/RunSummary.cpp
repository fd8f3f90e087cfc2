#include "run/RunSummary.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/Log.hpp"
#include "core/MemoryAccount.hpp"

namespace efg {

long long peak_memory_bytes() {
  return MemoryAccount::peak_bytes();
}

std::vector<MemoryPhase> memory_by_phase(const CommPtr& comm, const Model& model) {
  const auto& mine = MemoryAccount::process().phases();
  const int n = static_cast<int>(mine.size());
  std::vector<long long> growth, peak, total(mine.size(), 0), largest(mine.size(), 0);
  for (const auto& p : mine) {
    growth.push_back(p.growth);
    peak.push_back(p.peak);
  }
  if (n > 0) {  // every rank marks the same phases in the same order
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, n, growth.data(), total.data());
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, n, peak.data(), largest.data());
  }
  const double particles =
      std::max(1.0, static_cast<double>(model.maps.owned_nodes->getGlobalNumElements()));
  auto mib = [](long long b) { return static_cast<double>(b) / 1048576.0; };
  std::vector<MemoryPhase> out;
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << "memory by phase (summed over " << comm->getSize()
    << " rank(s), " << static_cast<long long>(particles)
    << " particles): resident growth, per particle, and the high-water mark where a phase "
       "raised it";
  long long sum = 0, previous_peak = 0;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    out.push_back({mine[i].name, total[i], static_cast<double>(total[i]) / particles,
                   largest[i] > previous_peak ? largest[i] : 0});
    sum += total[i];
    o << "\n  " << std::left << std::setw(44) << mine[i].name << std::right << std::setw(9)
      << mib(total[i]) << " MiB " << std::setw(9) << static_cast<double>(total[i]) / particles
      << " B/particle";
    if (largest[i] > previous_peak)
      o << "   peak " << mib(largest[i]) << " MiB (" << static_cast<double>(largest[i]) / particles
        << " B/particle)";
    previous_peak = std::max(previous_peak, largest[i]);
  }
  o << "\n  " << std::left << std::setw(44) << "all phases" << std::right << std::setw(9)
    << mib(sum) << " MiB " << std::setw(9) << static_cast<double>(sum) / particles << " B/particle";
  Log::info(o.str());
  return out;
}

void print_run_summary(const CommPtr& comm) {
  std::ostringstream table;
  Teuchos::TimeMonitor::summarize(comm.ptr(), table, false, true, false);
  const long long mine = peak_memory_bytes();
  long long max = 0, sum = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(max));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(sum));
  std::ostringstream memory;
  memory << std::fixed << std::setprecision(1)
         << "memory high-water mark: " << static_cast<double>(max) / 1048576.0
         << " MiB per rank (max), " << static_cast<double>(sum) / 1048576.0 << " MiB over "
         << comm->getSize() << " rank(s)";
  Log::info(table.str());
  Log::info(memory.str());
}

}  // namespace efg
