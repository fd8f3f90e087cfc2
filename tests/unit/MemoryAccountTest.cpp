// The memory account measures: a phase that allocates and touches 64 MiB is charged at least
// that, a phase that frees it is charged its return, and the high-water mark the first phase
// reached is at least the resident set plus the block (core/MemoryAccount).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/MemoryAccount.hpp"

namespace efg {
namespace {

constexpr long long kBlock = 64LL << 20;

const MemoryAccount::Phase& phase(const MemoryAccount& a, const char* name) {
  for (const auto& p : a.phases())
    if (p.name == name) return p;
  throw std::logic_error(name);
}

TEST(MemoryAccount, ChargesWhatAPhaseKeepsAndFrees) {
  auto& account = MemoryAccount::process();
  account.reset();
  const long long before = MemoryAccount::resident_bytes();
  ASSERT_GT(before, 0);  // /proc/self/statm is readable
  auto block = std::make_unique<std::vector<char>>(static_cast<std::size_t>(kBlock), 1);
  account.mark("allocate");
  block.reset();  // a block this large is returned to the system at once (mmap)
  account.mark("free");
  account.mark("allocate");  // a phase marked twice adds up: nothing more here
  EXPECT_GE(phase(account, "allocate").growth, kBlock * 95 / 100);
  EXPECT_LE(phase(account, "free").growth, -kBlock * 95 / 100);
  EXPECT_GE(phase(account, "allocate").peak, before + kBlock * 95 / 100);
  EXPECT_EQ(account.phases().size(), 2u);
}

}  // namespace
}  // namespace efg
