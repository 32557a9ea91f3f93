// sort_few: the order of std::sort on either side of its bound, stable below it.

#include "contain/core/sort_few.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace contain {
namespace {

TEST(SortFew, SortsAsStdSortOnEmptyOneEqualAndRandomRangesOnBothSidesOfTheBound) {
  std::mt19937 random(5);
  for (const std::size_t size : {0U, 1U, 2U, 3U, 15U, 16U, 17U, 40U, 500U}) {
    for (const int spread : {1, 3, 1000}) {
      std::vector<int> values(size);
      for (int& v : values)
        v = static_cast<int>(random() % static_cast<unsigned>(spread));
      std::vector<int> expected = values;
      std::sort(expected.begin(), expected.end());
      sort_few(values.begin(), values.end(), 16);
      EXPECT_EQ(values, expected) << size << " " << spread;
    }
  }
}

// Below the bound equal keys keep their order (the engine's edge uses and a layer's holders
// compare whole records, but the pairing's words are distinct: stability is not relied on, it
// is what insertion gives); a sub-range leaves the rest untouched; `less` is honoured.
TEST(SortFew, KeepsEqualKeysInOrderBelowTheBoundAndSortsOnlyItsRangeByItsLess) {
  std::vector<std::pair<int, int>> records = {{3, 0}, {1, 1}, {3, 2}, {2, 3}, {1, 4}, {3, 5}};
  sort_few(records.begin(), records.end(), 16,
           [](const auto& a, const auto& b) { return a.first < b.first; });
  EXPECT_EQ(records,
            (std::vector<std::pair<int, int>>{{1, 1}, {1, 4}, {2, 3}, {3, 0}, {3, 2}, {3, 5}}));
  std::vector<int> values = {9, 5, 4, 3, 0};
  sort_few(values.begin() + 1, values.end() - 1, 16, std::greater<>{});
  EXPECT_EQ(values, (std::vector<int>{9, 5, 4, 3, 0}));
  sort_few(values.begin() + 1, values.end(), 2);  // past the bound: std::sort
  EXPECT_EQ(values, (std::vector<int>{9, 0, 3, 4, 5}));
}

}  // namespace
}  // namespace contain
