#include "parallel/SliceLookup.hpp"

#include <algorithm>

#include "mesh/MeshSlice.hpp"
#include "parallel/Exchange.hpp"

namespace efg {

std::vector<double> fetch_from_slices(const CommPtr& comm, GlobalIndex count, std::size_t width,
                                      const std::vector<double>& held,
                                      const std::vector<GlobalIndex>& wanted) {
  const int p = comm->getSize();
  const auto first = slice_begin(count, comm->getRank(), p);
  std::vector<std::vector<GlobalIndex>> ask(static_cast<std::size_t>(p));
  for (auto g : wanted) ask[static_cast<std::size_t>(slice_holder(count, p, g))].push_back(g);
  const auto asked = all_to_all(comm, std::move(ask));
  std::vector<std::vector<double>> answer(static_cast<std::size_t>(p));
  for (std::size_t s = 0; s < asked.size(); ++s)
    for (auto g : asked[s]) {
      const auto at = static_cast<std::size_t>(g - first) * width;
      answer[s].insert(answer[s].end(), held.begin() + static_cast<std::ptrdiff_t>(at),
                       held.begin() + static_cast<std::ptrdiff_t>(at + width));
    }
  // Holders answer in the order asked and their ranges ascend with the indices: the answers in
  // rank order follow `wanted`.
  const auto got = all_to_all(comm, std::move(answer));
  std::vector<double> values;
  values.reserve(wanted.size() * width);
  for (const auto& list : got) values.insert(values.end(), list.begin(), list.end());
  return values;
}

}  // namespace efg
