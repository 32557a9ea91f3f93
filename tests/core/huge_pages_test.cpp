#include "contain/core/huge_pages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>

namespace contain {
namespace {

TEST(HugePageAllocator, LargeBuffersStartOnA2MBBoundaryAndKeepTheirValuesThroughGrowth) {
  HugePageVector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < 3'000'000; ++i)  // grows from small blocks to 12 MB ones
    v.push_back(i);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % HugePageAllocator<int>::huge_page, 0u);
  std::uint64_t sum = std::accumulate(v.begin(), v.end(), std::uint64_t{0});
  EXPECT_EQ(sum, std::uint64_t{2'999'999} * 3'000'000 / 2);
  v.assign(10, 7);  // a small vector again: the ordinary allocator's blocks
  v.shrink_to_fit();
  EXPECT_EQ(v, HugePageVector<std::uint32_t>(10, 7));
}

// From the threshold up (128 kB: a block of 32 small pages, which cost more to fault in than one
// huge page on the benchmark machine) a block starts on a 2 MB boundary; below it, the ordinary
// allocator's, with the same values either way.
TEST(HugePageAllocator, BlocksFromTheThresholdUpStartOnA2MBBoundary) {
  constexpr std::size_t threshold = HugePageAllocator<std::uint8_t>::huge_page_threshold;
  static_assert(threshold <= HugePageAllocator<std::uint8_t>::huge_page / 8);
  for (const std::size_t bytes : {threshold, threshold + 1, 3 * threshold}) {
    HugePageVector<std::uint8_t> v(bytes, 5);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % HugePageAllocator<int>::huge_page, 0u)
        << bytes;
    EXPECT_EQ(std::count(v.begin(), v.end(), 5), static_cast<std::ptrdiff_t>(bytes));
  }
  HugePageVector<std::uint8_t> small(threshold - 1, 3);
  EXPECT_EQ(std::count(small.begin(), small.end(), 3), static_cast<std::ptrdiff_t>(threshold - 1));
}

}  // namespace
}  // namespace contain
