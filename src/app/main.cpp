// efg entry point: parses the command line, runs one command, maps failures to exit codes.
#include <Tpetra_Core.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <iostream>

#include "app/CommandLine.hpp"
#include "app/Commands.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "parallel/Collective.hpp"
#include "core/Version.hpp"

namespace {

int dispatch(const efg::CommPtr& comm, const std::vector<std::string>& args) {
  using efg::ExitCode;
  try {
    const auto cl = efg::parse_command_line(args);
    if (cl.command == "help") {
      if (comm->getRank() == 0) std::cout << efg::help_text();
    } else if (cl.command == "version") {
      if (comm->getRank() == 0) std::cout << "efg " << efg::version_string << " (" << efg::git_describe << ")\n";
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
    return static_cast<int>(ExitCode::success);
  } catch (const efg::PeerFailure& e) {
    return e.exit_code();  // the failing rank printed the message
  } catch (const efg::InputError& e) {
    if (comm->getRank() == 0) std::cerr << "efg: error: " << e.what() << std::endl;
    return static_cast<int>(ExitCode::bad_input);
  } catch (const efg::VerificationError& e) {
    if (comm->getRank() == 0) std::cerr << "efg: verification failed: " << e.what() << std::endl;
    return static_cast<int>(ExitCode::verification);
  } catch (const efg::NumericalError& e) {
    std::cerr << "efg: numerical failure: " << e.what() << std::endl;
    return static_cast<int>(ExitCode::numerical);
  } catch (const std::exception& e) {
    if (comm->getRank() == 0) std::cerr << "efg: error: " << e.what() << std::endl;
    return static_cast<int>(ExitCode::other);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int code = 0;
  {
    // Kokkos would claim efg's own --help: MPI and Kokkos are configured by environment only.
    int library_argc = 1;
    Tpetra::ScopeGuard scope(&library_argc, &argv);
    const auto comm = Tpetra::getDefaultComm();
    efg::Log::set_rank(comm->getRank());
    const std::vector<std::string> args(argv + 1, argv + argc);
    code = dispatch(comm, args);
    // All ranks leave with the worst code any rank saw (a numerical failure may be rank-local).
    int worst = code;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, code, Teuchos::outArg(worst));
    code = worst;
  }
  return code;
}
