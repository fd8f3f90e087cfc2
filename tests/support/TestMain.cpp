// GoogleTest main for efg: MPI and Kokkos through Tpetra::ScopeGuard; every rank runs every test
// and the exit code is the worst over ranks, so a failure on rank 1 alone still fails the test.
// Only rank 0 prints the progress listing; failures are printed by every rank.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "core/Log.hpp"
#include "core/MpiSingleton.hpp"
#include "core/Threads.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  efg::LibraryArguments library(argc, argv);  // as efg itself: --threads N, OMP_PROC_BIND
  const efg::MpiSingletonSetup singleton;     // as efg itself: an isolated singleton
  Tpetra::ScopeGuard scope(library.argc(), library.argv());
  const auto comm = Tpetra::getDefaultComm();
  efg::Log::set_rank(comm->getRank());
  if (comm->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    struct FailurePrinter : ::testing::EmptyTestEventListener {
      int rank;
      explicit FailurePrinter(int r) : rank(r) {}
      void OnTestPartResult(const ::testing::TestPartResult& r) override {
        if (r.failed())
          std::fprintf(stderr, "[rank %d] %s:%d: failure\n%s\n", rank,
                       r.file_name() ? r.file_name() : "?", r.line_number(), r.summary());
      }
    };
    listeners.Append(new FailurePrinter(comm->getRank()));
  }
  const int mine = RUN_ALL_TESTS();
  int worst = mine;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(worst));
  return worst;
}
