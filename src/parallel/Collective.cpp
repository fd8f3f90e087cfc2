#include "parallel/Collective.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <exception>

#include "core/Errors.hpp"

namespace efg {

void run_collectively(const CommPtr& comm, const std::function<void()>& work) {
  int code = 0;
  std::exception_ptr error;
  try {
    work();
  } catch (const InputError&) {
    code = static_cast<int>(ExitCode::bad_input);
    error = std::current_exception();
  } catch (const NumericalError&) {
    code = static_cast<int>(ExitCode::numerical);
    error = std::current_exception();
  } catch (const PeerFailure& e) {
    code = e.exit_code();
    error = std::current_exception();
  } catch (...) {
    code = static_cast<int>(ExitCode::other);
    error = std::current_exception();
  }
  int worst = code;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, code, Teuchos::outArg(worst));
  if (worst == 0) return;
  // The lowest failing rank's message, for the others to quote (only on failure: one more
  // reduction and a broadcast).
  const int size = comm->getSize(), mine = error ? comm->getRank() : size;
  int first = size;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  std::string message;
  if (comm->getRank() == first) {
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
      message = "unknown failure";
    }
  }
  int length = static_cast<int>(message.size());
  Teuchos::broadcast(*comm, first, Teuchos::outArg(length));
  message.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(*comm, first, length, message.data());
  if (error) std::rethrow_exception(error);
  throw PeerFailure(worst,
                    size > 1 ? message + " (on rank " + std::to_string(first) + ")" : message);
}

}  // namespace efg
