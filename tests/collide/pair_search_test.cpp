#include "contain/collide/pair_search.h"

#include <gtest/gtest.h>

#include <random>

namespace contain::collide {
namespace {

using Pairs = std::vector<std::pair<std::int32_t, std::int32_t>>;

Pairs brute_force(const std::vector<Box3>& boxes) {
  Pairs out;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (!boxes[i].empty() && !boxes[j].empty() && boxes[i].overlaps(boxes[j]))
        out.emplace_back(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
  return out;
}

TEST(PairSearch, MatchesBruteForceOnRandomScenesWithTouchingAndEmptyBoxes) {
  std::mt19937_64 rng(0xb0b0);
  for (int scene = 0; scene < 40; ++scene) {
    // Integer corners on a small grid: shared faces, edges and corners are frequent; flat boxes
    // and empty boxes included.
    const int grid = 4 + scene % 20;
    std::uniform_int_distribution<int> u(0, grid), len(0, 3), kind(0, 15);
    std::vector<Box3> boxes(static_cast<std::size_t>(50 + 20 * scene));
    for (Box3& b : boxes) {
      if (kind(rng) == 0) continue;  // the default Box3 is empty
      const Vec3 lo{double(u(rng)), double(u(rng)), double(u(rng))};
      b = {lo, lo + Vec3{double(len(rng)), double(len(rng)), double(len(rng))}};
      if (kind(rng) == 1) std::swap(b.min.y, b.max.y);  // inverted on one axis: empty
    }
    const Pairs want = brute_force(boxes);
    EXPECT_EQ(pair_search(boxes), want) << "scene " << scene;
  }
}

TEST(PairSearch, TouchingBoxesArePairsAndSeparatedOnesAreNot) {
  const std::vector<Box3> boxes = {{{0, 0, 0}, {1, 1, 1}},
                                   {{1, 1, 1}, {2, 2, 2}},  // corner on box 0
                                   {{std::nextafter(2.0, 3.0), 0, 0}, {3, 1, 1}},
                                   {{0, 0, 5}, {1, 1, 5}}};  // flat, alone
  EXPECT_EQ(pair_search(boxes), (Pairs{{0, 1}}));
  EXPECT_TRUE(pair_search({}).empty());
}

TEST(PairSearch, AllStackedBoxesPairEveryone) {
  std::vector<Box3> boxes(30, Box3{{0, 0, 0}, {1, 1, 1}});
  EXPECT_EQ(pair_search(boxes).size(), 30u * 29u / 2u);
}

}  // namespace
}  // namespace contain::collide
