// The explicit stages' stop on a failed energy balance (drivers/EnergyBalanceCheck) and the
// particle it names (parallel/LargestParticle), against hand-made values.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "drivers/EnergyBalanceCheck.hpp"
#include "parallel/LargestParticle.hpp"

namespace efg {
namespace {

TEST(EnergyBalanceCheck, StopsOnlyAtTwoChecksInARowAboveTheLimit) {
  EnergyBalanceCheck check("pull", 0.1);
  EXPECT_FALSE(check.failed(0.2));   // a single check above: a transient
  EXPECT_FALSE(check.failed(0.05));  // back below
  EXPECT_FALSE(check.failed(0.11));
  EXPECT_TRUE(check.failed(0.12));  // the second in a row
  EXPECT_FALSE(check.failed(0.1));  // at the limit is not above it
}

TEST(EnergyBalanceCheck, ChecksEveryHundredStepsAndNeverWhenOff) {
  EnergyBalanceCheck check("pull", 0.1), off("pull", 0.0);
  EXPECT_TRUE(check.due(200));
  EXPECT_FALSE(check.due(250));
  EXPECT_FALSE(off.due(200));
  EXPECT_FALSE(off.failed(5.0));
  EXPECT_FALSE(off.failed(5.0));
}

TEST(EnergyBalanceCheck, MessageNamesTheErrorStepTimeAndParticle) {
  EnergyBalanceCheck check("pull", 0.1);
  RunState state(Teuchos::rcp(new Tpetra::Map<>(2, 0, Tpetra::getDefaultComm())));
  state.kinetic = 3.0;  // 3 + 9 - 0 - 10 = 2 of the largest 10: 20 %
  state.internal = 9.0;
  state.external_work = 10.0;
  const auto text = check.message(state.balance_error(), 42, 0.5, "kinetic 3 + internal 9",
                                  "the largest kinetic energy is at particle 7 (X = (0.25, 0.75))");
  for (const char* part : {"stage 'pull': energy balance error 20 % exceeds energy_balance_limit "
                           "(10 %) at step 42, t = 0.5: kinetic 3 + internal 9",
                           "particle 7 (X = (0.25, 0.75))"})
    EXPECT_NE(text.find(part), std::string::npos) << text;
}

TEST(LargestParticle, SumsEachParticlesDofs) {
  const auto comm = Tpetra::getDefaultComm();
  // 4 particles of 2 dofs on one rank: sums 3, 7, 7, 1 -> the first of the tie, particle 1.
  auto map = Teuchos::rcp(new Tpetra::Map<>(8, 0, comm));
  Tpetra::Vector<> w(map);
  const double values[8] = {1, 2, 3, 4, 5, 2, 0.5, 0.5};
  for (int k = 0; k < 8; ++k) w.replaceLocalValue(k, values[k]);
  const auto peak = largest_particle_sum(w, 2);
  EXPECT_EQ(peak.particle, 1);
  EXPECT_DOUBLE_EQ(peak.value, 7.0);
}

}  // namespace
}  // namespace efg
