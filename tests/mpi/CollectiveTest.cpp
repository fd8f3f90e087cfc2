// run_collectively (parallel/Collective): a failure on one rank reaches every rank before the
// next collective call; the failing rank rethrows its own error, the others a PeerFailure with
// its exit code and its message (naming the rank), which a Newton cutback quotes.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <string>

#include "core/Errors.hpp"
#include "parallel/Collective.hpp"

namespace efg {
namespace {

TEST(Collective, EveryRankLearnsTheFailingRanksMessage) {
  const auto comm = Tpetra::getDefaultComm();
  const int last = comm->getSize() - 1;
  try {
    run_collectively(comm, [&] {
      if (comm->getRank() == last) throw NumericalError("det F <= 0 at particle 7");
    });
    ADD_FAILURE() << "no rank threw";
  } catch (const NumericalError& e) {
    EXPECT_EQ(comm->getRank(), last);
    EXPECT_EQ(std::string(e.what()), "det F <= 0 at particle 7");
  } catch (const PeerFailure& e) {
    EXPECT_NE(comm->getRank(), last);
    EXPECT_EQ(e.exit_code(), static_cast<int>(ExitCode::numerical));
    EXPECT_EQ(std::string(e.what()),
              "det F <= 0 at particle 7 (on rank " + std::to_string(last) + ")");
  }
}

TEST(Collective, NothingIsThrownWhenNoRankFails) {
  const auto comm = Tpetra::getDefaultComm();
  int ran = 0;
  EXPECT_NO_THROW(run_collectively(comm, [&] { ran = 1; }));
  EXPECT_EQ(ran, 1);
}

}  // namespace
}  // namespace efg
