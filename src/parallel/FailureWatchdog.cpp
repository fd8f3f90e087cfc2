#include "parallel/FailureWatchdog.hpp"

#include <mpi.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace efg {
namespace {

struct Alarm {
  std::mutex mutex;
  std::condition_variable changed;
  bool raised = false;
  int code = 0;
  std::string message;
  std::chrono::steady_clock::time_point since;
};

// Never destroyed: the watchdog's thread waits on it until the process ends, and destroying a
// condition variable with a waiter blocks the exit (glibc waits for the waiters).
Alarm& alarm() {
  static Alarm* a = new Alarm;
  return *a;
}

// Sleeps until an alarm is raised, then waits out kPeerWaitSeconds unless it is settled. The exit
// bypasses destructors and MPI_Finalize on purpose: both would wait for the stuck ranks. No MPI
// call is made from this thread (the library may not be initialized for threads).
[[noreturn]] void watch() {
  auto& a = alarm();
  std::unique_lock<std::mutex> lock(a.mutex);
  for (;;) {
    a.changed.wait(lock, [&] { return a.raised; });
    const auto deadline = a.since + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(kPeerWaitSeconds));
    if (a.changed.wait_until(lock, deadline, [&] { return !a.raised; })) continue;
    std::fprintf(stderr,
                 "%s\nefg: the other ranks did not learn of this failure within %.0f s (they "
                 "wait in a collective operation): stopping the run with exit code %d\n",
                 a.message.c_str(), kPeerWaitSeconds, a.code);
    std::fflush(stderr);
    std::fflush(stdout);
    std::_Exit(a.code);
  }
}

MPI_Comm& failure_comm() {
  static MPI_Comm comm = MPI_COMM_NULL;
  return comm;
}

}  // namespace

void start_failure_watchdog() {
  static std::once_flag once;
  std::call_once(once, [] {
    MPI_Comm_dup(MPI_COMM_WORLD, &failure_comm());
    std::thread(watch).detach();
  });
}

void meet_in_failure(int code, const std::string& message) {
  if (failure_comm() == MPI_COMM_NULL) return;
  if (!message.empty()) raise_failure_alarm(code, message);
  MPI_Barrier(failure_comm());
  settle_failure_alarm();  // every rank knows: a stage may go on (a Newton cutback)
}

void raise_failure_alarm(int code, const std::string& message) {
  auto& a = alarm();
  {
    std::lock_guard<std::mutex> lock(a.mutex);
    if (a.raised) return;
    a.raised = true;
    a.code = code;
    a.message = message;
    a.since = std::chrono::steady_clock::now();
  }
  a.changed.notify_all();
}

void settle_failure_alarm() {
  auto& a = alarm();
  {
    std::lock_guard<std::mutex> lock(a.mutex);
    a.raised = false;
  }
  a.changed.notify_all();
}

}  // namespace efg
