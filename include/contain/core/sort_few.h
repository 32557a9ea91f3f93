#pragma once
/// \file
/// Sorting the few elements a vertex, a point or a cell usually holds: by insertion, where
/// std::sort's set-up and its insertions' memmove cost more than the sorting, by std::sort past
/// a bound. Shared by the half-edge pairing, the solid engine's edge uses and the holders of a
/// point in a layer.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>

namespace contain {

/// Sorts [first, last) ascending by `less`: by insertion when the range holds at most `few`
/// elements (then equal elements keep their order), by std::sort otherwise.
template <class Iterator, class Less = std::less<>>
void sort_few(Iterator first, Iterator last, std::size_t few, Less less = {}) {
  if (static_cast<std::size_t>(last - first) > few) {
    std::sort(first, last, less);
    return;
  }
  for (Iterator it = first; it != last; ++it) {
    auto x = std::move(*it);
    Iterator hole = it;
    for (; hole != first && less(x, *(hole - 1)); --hole)
      *hole = std::move(*(hole - 1));
    *hole = std::move(x);
  }
}

}  // namespace contain
