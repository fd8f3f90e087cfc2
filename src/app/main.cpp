// efg entry point: parses the command line, runs one command, maps failures to exit codes.
#include <mpi.h>
#include <Tpetra_Core.hpp>

#include <cstdlib>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "app/CommandLine.hpp"
#include "app/Commands.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/MpiSingleton.hpp"
#include "core/Threads.hpp"
#include "core/Version.hpp"
#include "parallel/Collective.hpp"
#include "parallel/ExitReport.hpp"
#include "parallel/FailureWatchdog.hpp"

namespace {

efg::ExitReport dispatch(const efg::CommPtr& comm, const std::vector<std::string>& args) {
  try {
    const auto cl = efg::parse_command_line(args);
    if (cl.command == "help") {
      if (comm->getRank() == 0) std::cout << efg::help_text();
    } else if (cl.command == "version") {
      if (comm->getRank() == 0)
        std::cout << "efg " << efg::version_string << " (" << efg::git_describe << ")\n";
    } else if (cl.command == "run") {
      efg::run_command(comm, cl);
    } else if (cl.command == "check") {
      efg::check_command(comm, cl);
    } else if (cl.command == "study") {
      efg::study_command(comm, cl);
    } else if (cl.command == "mesh") {
      efg::mesh_command(comm, cl);
    } else if (cl.command == "schema") {
      if (comm->getRank() == 0) efg::schema_command();
    }
    return {};
  } catch (...) {
    // A failure of this rank (not a peer's, which was agreed) raises the watchdog's alarm: if
    // the other ranks never come to settle the exit, it still ends, with this message.
    auto report = efg::exit_report(std::current_exception());
    if (!report.message.empty()) efg::raise_failure_alarm(report.code, report.message);
    return report;
  }
}

}  // namespace

int main(int argc, char** argv) {
  int code = 0;
  {
    efg::LibraryArguments library(argc, argv);  // Kokkos sees only the thread count
    const efg::MpiSingletonSetup singleton;     // before MPI_Init, removed after MPI_Finalize
    Tpetra::ScopeGuard scope(library.argc(), library.argv());
    const auto comm = Tpetra::getDefaultComm();
    efg::Log::set_rank(comm->getRank());
    // The exit is settled on a communicator of its own: a rank that failed alone must never
    // match a collective call the others make on the run's communicator.
    MPI_Comm exit_comm = MPI_COMM_NULL;
    MPI_Comm_dup(MPI_COMM_WORLD, &exit_comm);
    efg::start_failure_watchdog();
    const std::vector<std::string> args(argv + 1, argv + argc);
    const auto outcome = dispatch(comm, args);
    // One message however many ranks failed: the lowest rank that has one prints it. All ranks
    // leave with the worst code any rank saw (a numerical failure may be rank-local).
    const int size = comm->getSize(), rank = comm->getRank();
    int mine[2] = {outcome.code, outcome.message.empty() ? -size : -rank}, all[2] = {0, 0};
    MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, exit_comm);
    efg::settle_failure_alarm();
    if (rank == -all[1]) std::cerr << outcome.message << std::endl;
    code = all[0];
    MPI_Comm_free(&exit_comm);
  }
  return code;
}
