// efg entry point: parses the command line, runs one command, maps failures to exit codes.
#include <Teuchos_CommHelpers.hpp>
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

namespace {

struct Outcome {
  int code = 0;
  std::string message;  ///< what this rank has to say (empty: nothing)
};

Outcome dispatch(const efg::CommPtr& comm, const std::vector<std::string>& args) {
  using efg::ExitCode;
  auto failed = [](ExitCode code, const std::string& prefix, const char* what) {
    return Outcome{static_cast<int>(code), prefix + what};
  };
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
  } catch (const efg::PeerFailure& e) {
    return {e.exit_code(), ""};  // the failing rank has the message
  } catch (const efg::InputError& e) {
    return failed(ExitCode::bad_input, "efg: error: ", e.what());
  } catch (const efg::VerificationError& e) {
    return failed(ExitCode::verification, "efg: verification failed: ", e.what());
  } catch (const efg::NumericalError& e) {
    return failed(ExitCode::numerical, "efg: numerical failure: ", e.what());
  } catch (const std::bad_alloc&) {
    return failed(ExitCode::other, "efg: error: ",
                  "out of memory: the model needs more memory than this process can have "
                  "(coarsen the mesh, or run on more ranks or machines)");
  } catch (const std::exception& e) {
    return failed(ExitCode::other, "efg: error: ", e.what());
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
    const std::vector<std::string> args(argv + 1, argv + argc);
    const auto outcome = dispatch(comm, args);
    // One message however many ranks failed: the lowest rank that has one prints it. All ranks
    // leave with the worst code any rank saw (a numerical failure may be rank-local).
    const int size = comm->getSize(), rank = comm->getRank();
    int speaker = outcome.message.empty() ? size : rank, first = size;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, speaker, Teuchos::outArg(first));
    if (rank == first) std::cerr << outcome.message << std::endl;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, outcome.code, Teuchos::outArg(code));
  }
  return code;
}
