#include "contain/core/huge_pages.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace contain
