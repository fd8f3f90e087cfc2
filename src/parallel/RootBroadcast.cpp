#include "parallel/RootBroadcast.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/Errors.hpp"

namespace efg {

std::vector<char> produce_on_root(const CommPtr& comm,
                                  const std::function<std::vector<char>()>& produce) {
  // Message: one status byte (0 ok, 2 input error, 3 numerical, 1 other error), then the bytes
  // or the text.
  std::vector<char> message(1, 0);
  if (comm->getRank() == 0) {
    try {
      auto body = produce();
      message.insert(message.end(), body.begin(), body.end());
    } catch (const InputError& e) {
      message = {2};
      message.insert(message.end(), e.what(), e.what() + std::string(e.what()).size());
    } catch (const NumericalError& e) {
      message = {3};
      message.insert(message.end(), e.what(), e.what() + std::string(e.what()).size());
    } catch (const std::exception& e) {
      message = {1};
      message.insert(message.end(), e.what(), e.what() + std::string(e.what()).size());
    }
  }
  if (comm->getSize() > 1) {
    std::uint64_t size = message.size();
    Teuchos::broadcast(*comm, 0, &size);
    message.resize(size);
    // Teuchos counts in int: send large messages in chunks of 1 GiB.
    const std::uint64_t chunk = std::uint64_t{1} << 30;
    for (std::uint64_t offset = 0; offset < size; offset += chunk) {
      const auto n = static_cast<int>(std::min<std::uint64_t>(chunk, size - offset));
      Teuchos::broadcast(*comm, 0, n, message.data() + offset);
    }
  }
  const char status = message.front();
  std::vector<char> body(message.begin() + 1, message.end());
  if (status == 2) throw InputError(std::string(body.begin(), body.end()));
  if (status == 3) throw NumericalError(std::string(body.begin(), body.end()));
  if (status != 0) throw std::runtime_error(std::string(body.begin(), body.end()));
  return body;
}

}  // namespace efg
