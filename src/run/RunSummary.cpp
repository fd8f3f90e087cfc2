#include "run/RunSummary.hpp"

#include <sys/resource.h>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/Log.hpp"

namespace efg {

long long peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
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
