#pragma once
// Private to contain::distance: the exact stage of the pair searches. A descent with
// floating-point bounds leaves the item pairs (triangles, edges) that can be the closest; the
// exact closest features of each (predicates::closest_flats) and exact comparisons of their
// squared distances pick the answer.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "contain/predicates/sign.h"
#include "contain/predicates/squared_distance.h"

namespace contain::distance::detail {

// Item a of the first shape against item b of the second, with lo <= squared distance <= hi.
struct PairContender {
  std::int32_t a, b;
  double lo, hi;
};

// The winner of `least_contender`: the closest flats of the pair and its items.
template <class FlatPair>
struct LeastContender {
  FlatPair pair{};
  std::int32_t a = -1, b = -1;
  bool found = false;
};

// Drops the contenders whose lower bound exceeds `best` (an upper bound of the answer: they
// cannot be closest), then returns the one of least exact squared distance, ties to the lowest
// a, then b (distance-tie rule, docs/robustness.md). `flats(a, b)` gives the closest flats of a
// pair. Leaves `contenders` sorted by (a, b). O(k log k) for k contenders, plus k exact
// comparisons.
template <class Flats>
auto least_contender(std::vector<PairContender>& contenders, double best, Flats&& flats) {
  using FlatPair = decltype(flats(std::int32_t{}, std::int32_t{}));
  std::erase_if(contenders, [&](const PairContender& c) { return c.lo > best; });
  std::sort(contenders.begin(), contenders.end(),
            [](const PairContender& x, const PairContender& y) {
              return x.a != y.a ? x.a < y.a : x.b < y.b;
            });
  LeastContender<FlatPair> winner;
  for (const PairContender& c : contenders) {
    const FlatPair pair = flats(c.a, c.b);
    if (!winner.found || predicates::compare_squared_distances(pair, winner.pair) == Sign::negative)
      winner = {pair, c.a, c.b, true};
  }
  return winner;
}

}  // namespace contain::distance::detail
