#include "contain/core/radix_sort.h"

#include "contain/core/huge_pages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace contain {
namespace {

// The pairs (key, item) sorted by a comparison sort, for keys of `bits` bits drawn from `range`
// values (many ties when small), against the radix sort's keys and items.
void expect_matches_a_sort_of_pairs(unsigned bits, std::uint64_t range, std::size_t n) {
  std::mt19937_64 rng(bits * 1000 + n);
  std::uniform_int_distribution<std::uint64_t> draw(0, range - 1);
  std::vector<std::uint64_t> keys(n);
  std::vector<std::uint32_t> items(n);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> pairs(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Beyond 40 bits the keys are shifted up: their low digits are zero for every key.
    keys[i] = draw(rng) << (bits > 40 ? bits - 40 : 0);
    items[i] = static_cast<std::uint32_t>(i);
    pairs[i] = {keys[i], items[i]};
  }
  std::sort(pairs.begin(), pairs.end());
  stable_radix_sort(keys, items, bits);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(keys[i], pairs[i].first) << i;
    ASSERT_EQ(items[i], pairs[i].second) << i;
  }
}

TEST(StableRadixSort, GivesTheOrderOfASortOfKeyAndPositionWithManyTies) {
  expect_matches_a_sort_of_pairs(21, 1000, 20000);
  expect_matches_a_sort_of_pairs(21, std::uint64_t{1} << 21, 20000);
}

TEST(StableRadixSort, KeysOfManyDigitsAndDigitsEqualForEveryKey) {
  // 63-bit keys whose low 23 bits are all zero: the passes over them are skipped.
  expect_matches_a_sort_of_pairs(63, std::uint64_t{1} << 40, 5000);
  expect_matches_a_sort_of_pairs(33, std::uint64_t{1} << 33, 5000);
}

// 32-bit keys in vectors whose allocator leaves new elements unzeroed (the scratch arrays take
// it too), with a key_bits beyond the keys' width: the passes stop at 32 bits.
TEST(StableRadixSort, ThirtyTwoBitKeysInDefaultInitializingVectors) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> draw(0, 5000);
  const std::size_t n = 30000;
  HugePageVector<std::uint32_t> keys(n), items(n);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs(n);
  for (std::size_t i = 0; i < n; ++i) {
    keys[i] = draw(rng) << 19U;  // up to bit 31
    items[i] = static_cast<std::uint32_t>(i);
    pairs[i] = {keys[i], items[i]};
  }
  std::sort(pairs.begin(), pairs.end());
  stable_radix_sort(keys, items, 40);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(keys[i], pairs[i].first) << i;
    ASSERT_EQ(items[i], pairs[i].second) << i;
  }
}

TEST(StableRadixSort, EmptyAndSingleInputs) {
  std::vector<std::uint64_t> keys;
  std::vector<int> items;
  stable_radix_sort(keys, items, 20);
  EXPECT_TRUE(keys.empty());
  keys = {5};
  items = {7};
  stable_radix_sort(keys, items, 20);
  EXPECT_EQ(keys, std::vector<std::uint64_t>{5});
  EXPECT_EQ(items, std::vector<int>{7});
}

}  // namespace
}  // namespace contain
