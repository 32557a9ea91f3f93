#include "contain/core/parallel.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace contain {
namespace {

std::vector<std::uint64_t> squares(std::span<const std::uint64_t> in, int threads,
                                   std::size_t min_chunk) {
  std::vector<std::uint64_t> out(in.size(), 0);
  batch_map(in, std::span<std::uint64_t>(out), BatchOptions{.threads = threads}, min_chunk,
            [](std::uint64_t x) { return x * x; });
  return out;
}

TEST(BatchMap, AnswersEveryItemInPlaceWhateverTheThreadCountAndChunk) {
  std::vector<std::uint64_t> in(10007);
  std::iota(in.begin(), in.end(), std::uint64_t{1});
  const std::vector<std::uint64_t> one = squares(in, 1, 4096);
  for (std::size_t i = 0; i < in.size(); ++i)
    ASSERT_EQ(one[i], in[i] * in[i]) << i;
  for (const int threads : {2, 3, 8})
    for (const std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{4096}})
      EXPECT_EQ(squares(in, threads, chunk), one) << threads << " threads, chunk " << chunk;
}

TEST(BatchMap, AnEmptyBatchAnswersNothing) {
  EXPECT_TRUE(squares({}, 2, 1).empty());
}

TEST(BatchSize, EqualSizesAreTheCount) {
  EXPECT_EQ(batch_size(0, 0), 0u);
  EXPECT_EQ(batch_size(5, 5), 5u);
}

// A different size is a programming error: an assertion in builds that check them (the
// sanitizer suite); elsewhere the common prefix, so nothing is written past `out`.
TEST(BatchSize, ADifferentOutSizeIsAssertedOrCutToThePrefix) {
  EXPECT_DEBUG_DEATH(
      {
        const std::size_t n = batch_size(5, 3);
        EXPECT_EQ(n, 3u);
      },
      "inputs' size");
}

}  // namespace
}  // namespace contain
