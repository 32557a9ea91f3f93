// Stage 3 of slicing: the crossing segments chained into closed paths.
//
// On a closed mesh every key is left as often as it is entered (a mesh edge crossing the plane
// is used up and down equally often by its triangles; at a vertex on the plane the same holds
// for its edges to the other side), so a walk that takes any unused segment leaving its current
// key can only stop where it started. The paths need not be the section's rings: the 2D engine
// reads them only through their winding numbers (`Fill::positive`).

#include <algorithm>
#include <numeric>

#include "clip/slice/stages.h"

namespace contain::clip::slice {

std::vector<Ring> chain_rings(std::span<const CrossingSegment> segments,
                              std::vector<std::vector<std::int32_t>>* triangles) {
  // Segments sorted by the key they leave; next[g] is the first unused one of each run.
  std::vector<std::int32_t> by_from;
  by_from.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (segments[i].from_key != segments[i].to_key) by_from.push_back(static_cast<std::int32_t>(i));
  }
  const auto from_of = [&](std::int32_t i) {
    return segments[static_cast<std::size_t>(i)].from_key;
  };
  std::stable_sort(by_from.begin(), by_from.end(),
                   [&](std::int32_t a, std::int32_t b) { return from_of(a) < from_of(b); });
  std::vector<std::size_t> cursor(by_from.size());
  std::iota(cursor.begin(), cursor.end(), std::size_t{0});  // valid at each run's first slot
  std::vector<char> used(segments.size(), 0);

  // The first unused segment leaving `key`, or -1.
  const auto take = [&](std::uint64_t key) -> std::int32_t {
    const auto it =
        std::lower_bound(by_from.begin(), by_from.end(), key,
                         [&](std::int32_t i, std::uint64_t k) { return from_of(i) < k; });
    if (it == by_from.end() || from_of(*it) != key) return -1;
    const std::size_t run = static_cast<std::size_t>(it - by_from.begin());
    std::size_t& c = cursor[run];
    while (c < by_from.size() && from_of(by_from[c]) == key &&
           used[static_cast<std::size_t>(by_from[c])])
      ++c;
    if (c == by_from.size() || from_of(by_from[c]) != key) return -1;
    return by_from[c];
  };

  std::vector<Ring> rings;
  for (const std::int32_t start : by_from) {
    if (used[static_cast<std::size_t>(start)]) continue;
    Ring ring;
    std::vector<std::int32_t> under;  // the triangle of each edge, recorded while chaining
    for (std::int32_t s = start; s >= 0; s = take(segments[static_cast<std::size_t>(s)].to_key)) {
      used[static_cast<std::size_t>(s)] = 1;
      ring.push_back(segments[static_cast<std::size_t>(s)].from);
      if (triangles != nullptr) under.push_back(segments[static_cast<std::size_t>(s)].triangle);
    }
    if (ring.size() < 3) continue;
    rings.push_back(std::move(ring));
    if (triangles != nullptr) triangles->push_back(std::move(under));
  }
  return rings;
}

}  // namespace contain::clip::slice
