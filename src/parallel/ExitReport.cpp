#include "parallel/ExitReport.hpp"

#include <new>

#include "core/Errors.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FailureWatchdog.hpp"

namespace efg {

ExitReport exit_report(const std::exception_ptr& error) {
  auto report = [](ExitCode code, const char* prefix, const char* what) {
    return ExitReport{static_cast<int>(code), std::string(prefix) + what};
  };
  try {
    std::rethrow_exception(error);
  } catch (const PeerFailure& e) {
    return {e.exit_code(), ""};  // the failing rank has the message
  } catch (const InputError& e) {
    return report(ExitCode::bad_input, "efg: error: ", e.what());
  } catch (const VerificationError& e) {
    return report(ExitCode::verification, "efg: verification failed: ", e.what());
  } catch (const NumericalError& e) {
    return report(ExitCode::numerical, "efg: numerical failure: ", e.what());
  } catch (const std::bad_alloc&) {
    return report(ExitCode::other, "efg: error: ",
                  "out of memory: the model needs more memory than this process can have "
                  "(coarsen the mesh, or run on more ranks or machines)");
  } catch (const std::exception& e) {
    return report(ExitCode::other, "efg: error: ", e.what());
  } catch (...) {
    return report(ExitCode::other, "efg: error: ", "an unknown failure");
  }
}

ExitReport meet_with_current_failure() {
  auto report = exit_report(std::current_exception());
  meet_in_failure(report.code, report.message);
  return report;
}

}  // namespace efg
