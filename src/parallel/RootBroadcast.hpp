// Work done once on rank 0 whose result (or failure) every rank receives: reading the scene
// file, reading or generating the mesh. A failure becomes the same exception on every rank, so
// all ranks exit with the same code and rank 0 prints the message once.
#pragma once

#include <functional>
#include <vector>

#include "parallel/Comm.hpp"

namespace efg {

/// Runs `produce` on rank 0 and returns its bytes on every rank. InputError thrown by `produce`
/// is rethrown as InputError on every rank; any other exception as std::runtime_error.
std::vector<char> produce_on_root(const CommPtr& comm,
                                  const std::function<std::vector<char>()>& produce);

}  // namespace efg
