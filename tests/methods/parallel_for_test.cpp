// parallel_for (methods/parallel_for.h): every index exactly once, whatever the split; a block's
// exception reaches the caller after all blocks ran; a count below one block stays on the caller's thread.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "methods/parallel_for.h"

namespace weft {
namespace {

TEST(ParallelFor, VisitsEveryIndexOnce) {
  for (size_t n : {size_t(0), size_t(1), size_t(63), size_t(64), size_t(65), size_t(1000), size_t(100003)}) {
    std::vector<std::atomic<int>> visits(n);
    parallel_for(n, [&](size_t i) { visits[i].fetch_add(1); });
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << n;
  }
}

TEST(ParallelFor, SmallCountsRunOnTheCallersThread) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> elsewhere{0};
  parallel_for(64, [&](size_t) { elsewhere += std::this_thread::get_id() != caller; });
  EXPECT_EQ(elsewhere.load(), 0);
}

TEST(ParallelFor, RethrowsABlocksExceptionAfterAllBlocksRan) {
  const size_t n = 10000;
  std::atomic<size_t> ran{0};
  try {
    parallel_for(n, [&](size_t i) {
      ++ran;
      if (i == n - 1) throw std::runtime_error("vertex " + std::to_string(i));
    }, 16);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "vertex 9999");
  }
  EXPECT_EQ(ran.load(), n);  // the throwing index is the last of its block: nothing was skipped
}

}  // namespace
}  // namespace weft
