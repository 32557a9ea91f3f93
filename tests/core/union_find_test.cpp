#include "contain/core/union_find.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace contain {
namespace {

TEST(UnionFind, RepresentativeIsTheSmallestElementWhateverTheOrderOfJoins) {
  UnionFind<std::uint32_t> sets(6);
  sets.unite(5, 3);
  sets.unite(3, 4);
  sets.unite(1, 2);
  for (std::uint32_t x : {3u, 4u, 5u})
    EXPECT_EQ(sets.find(x), 3u);
  EXPECT_EQ(sets.find(2), 1u);
  EXPECT_EQ(sets.find(0), 0u);
  sets.unite(4, 2);
  for (std::uint32_t x : {1u, 2u, 3u, 4u, 5u})
    EXPECT_EQ(sets.find(x), 1u);
}

TEST(UnionFind, AgreesWithALabelPropagationOracleOnRandomJoins) {
  std::mt19937_64 rng(3);
  const std::size_t n = 200;
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  UnionFind<std::size_t> sets(n);
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i)
    label[i] = i;
  for (int k = 0; k < 150; ++k) {
    const std::size_t a = pick(rng), b = pick(rng);
    sets.unite(a, b);
    const std::size_t from = std::max(label[a], label[b]), to = std::min(label[a], label[b]);
    for (std::size_t& l : label)
      if (l == from) l = to;
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_EQ(sets.find(i), label[i]) << k << " " << i;
  }
}

TEST(UnionFind, ResetMakesSingletonsOfANewSize) {
  UnionFind<std::uint32_t> sets(4);
  sets.unite(0, 3);
  sets.unite(1, 2);
  sets.reset(6);
  for (std::uint32_t i = 0; i < 6; ++i)
    EXPECT_EQ(sets.find(i), i);
  sets.unite(5, 4);
  EXPECT_EQ(sets.find(5), 4u);
  sets.reset(2);
  EXPECT_EQ(sets.find(1), 1u);
}

}  // namespace
}  // namespace contain
