// GoogleTest main for efg: MPI and Kokkos through Tpetra::ScopeGuard; every rank runs every test
// and the exit code is the worst over ranks, so a failure on rank 1 alone still fails the test.
// Only rank 0 prints the progress listing; failures are printed by every rank.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <cstdlib>

#include "core/Log.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  setenv("OMP_PROC_BIND", "false",
         0);  // unbound, as the OpenMP runtime already assumed; no Kokkos warning
  int library_argc = 1;
  Tpetra::ScopeGuard scope(&library_argc, &argv);
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
