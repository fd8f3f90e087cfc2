#include <gtest/gtest.h>

#include "core/Progress.hpp"

namespace efg {
namespace {

TEST(Progress, FormatsFractionAndEta) {
  const auto line = Progress::format("stage 'impact'", 0.25, 1.0, 10.0);
  EXPECT_NE(line.find("25.0 %"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 30 s"), std::string::npos) << line;  // 10 s for a quarter: 30 s left
}

TEST(Progress, NoEtaAtStartOrEnd) {
  EXPECT_EQ(Progress::format("s", 0.0, 1.0, 0.0).find("ETA"), std::string::npos);
  EXPECT_EQ(Progress::format("s", 1.0, 1.0, 5.0).find("ETA"), std::string::npos);
}

}  // namespace
}  // namespace efg
