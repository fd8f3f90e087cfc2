// Values held in slices fetched by global index (parallel/SliceLookup.hpp): every rank asks for
// an arbitrary ascending set of items, some held by itself, some by others, and gets each item's
// values in the order asked. The held values are a closed form of the item and component
// (1000 g + k), so the expected answer needs no second implementation.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "mesh/MeshSlice.hpp"
#include "parallel/SliceLookup.hpp"

namespace efg {
namespace {

TEST(SliceLookup, FetchesEveryItemFromItsHolderInTheOrderAsked) {
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), size = comm->getSize();
  for (GlobalIndex count : {GlobalIndex{1}, GlobalIndex{7}, GlobalIndex{1000}}) {
    const std::size_t width = 3;
    const auto first = slice_begin(count, rank, size), end = slice_begin(count, rank + 1, size);
    std::vector<double> held;
    for (auto g = first; g < end; ++g)
      for (std::size_t k = 0; k < width; ++k)
        held.push_back(1000.0 * static_cast<double>(g) + static_cast<double>(k));
    // Every (rank + 2)-th item from rank's own offset, and the last item: some asked by
    // several ranks, some by none.
    std::vector<GlobalIndex> wanted;
    for (GlobalIndex g = rank % count; g < count; g += rank + 2) wanted.push_back(g);
    if (wanted.back() != count - 1) wanted.push_back(count - 1);
    const auto got = fetch_from_slices(comm, count, width, held, wanted);
    ASSERT_EQ(got.size(), wanted.size() * width) << "count " << count;
    for (std::size_t i = 0; i < wanted.size(); ++i)
      for (std::size_t k = 0; k < width; ++k)
        EXPECT_EQ(got[i * width + k],
                  1000.0 * static_cast<double>(wanted[i]) + static_cast<double>(k))
            << "item " << wanted[i] << " component " << k << " on rank " << rank;
  }
}

}  // namespace
}  // namespace efg
