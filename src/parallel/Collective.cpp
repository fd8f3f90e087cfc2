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
  if (error) std::rethrow_exception(error);
  if (worst != 0) throw PeerFailure(worst);
}

}  // namespace efg
