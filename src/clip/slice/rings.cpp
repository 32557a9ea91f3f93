// Stage 3 of slicing: the crossing segments chained into closed paths.
//
// On a closed mesh every key is left as often as it is entered (a mesh edge crossing the plane
// is used up and down equally often by its triangles; at a vertex on the plane the same holds
// for its edges to the other side), so a walk that takes any unused segment leaving its current
// key can only stop where it started. The paths need not be the section's rings: the 2D engine
// reads them only through their winding numbers (`Fill::positive`).
//
// Most planes leave every key by one segment (a manifold mesh, no vertex on the plane): the
// walks are then the cycles of a permutation, found in linear time through a hash of the keys;
// the walks of the general rule start at each cycle's least key, in increasing order of it, and
// that is how the cycles are written. Otherwise the segments are sorted by (from_key, triangle)
// and walked by the general rule.

#include <algorithm>
#include <numeric>

#include "clip/slice/stages.h"

namespace contain::clip::slice {

namespace {

using Triangles = std::vector<std::vector<std::int32_t>>;

void add_ring(std::span<const CrossingSegment> segments, std::span<const std::int32_t> walk,
              std::vector<Ring>& rings, Triangles* triangles) {
  if (walk.size() < 3) return;
  Ring& ring = rings.emplace_back();
  ring.reserve(walk.size());
  for (const std::int32_t s : walk)
    ring.push_back(segments[static_cast<std::size_t>(s)].from);
  if (triangles == nullptr) return;
  std::vector<std::int32_t>& under = triangles->emplace_back();
  under.reserve(walk.size());
  for (const std::int32_t s : walk)
    under.push_back(segments[static_cast<std::size_t>(s)].triangle);
}

// The cycles when every key is left by at most one segment and every walk closes on itself;
// false (nothing written) when that does not hold.
bool chain_cycles(std::span<const CrossingSegment> segments, std::vector<Ring>& rings,
                  Triangles* triangles, ChainScratch& scratch) {
  KeyTable<std::int32_t>& leaving = scratch.leaving;
  leaving.reset(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const CrossingSegment& s = segments[i];
    if (s.from_key == s.to_key) continue;
    const auto [slot, fresh] = leaving.insert(s.from_key);
    if (!fresh) return false;
    *slot = static_cast<std::int32_t>(i);
  }
  scratch.used.assign(segments.size(), 0);
  scratch.walk.clear();
  std::vector<ChainCycle>& cycles = scratch.cycles;
  cycles.clear();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (scratch.used[i] != 0 || segments[i].from_key == segments[i].to_key) continue;
    ChainCycle cycle{segments[i].from_key, scratch.walk.size(), 0, 0};
    for (auto s = static_cast<std::int32_t>(i);;) {
      const auto u = static_cast<std::size_t>(s);
      scratch.used[u] = 1;
      if (segments[u].from_key < cycle.least) {
        cycle.least = segments[u].from_key;
        cycle.first = cycle.size;
      }
      scratch.walk.push_back(s);
      ++cycle.size;
      const std::int32_t* next = leaving.find(segments[u].to_key);
      if (next == nullptr) return false;  // a walk that stops: the general rule decides
      if (*next == static_cast<std::int32_t>(i)) break;
      if (scratch.used[static_cast<std::size_t>(*next)] != 0) return false;
      s = *next;
    }
    cycles.push_back(cycle);
  }
  write_cycles(segments, scratch.walk, cycles, rings, triangles, scratch.rotated);
  return true;
}

// The general rule: segments by (from_key, triangle), each walk taking at its key the first
// unused segment leaving it in that order.
void chain_general(std::span<const CrossingSegment> segments, std::vector<Ring>& rings,
                   Triangles* triangles, ChainScratch& scratch) {
  std::vector<std::int32_t>& by_from = scratch.by_from;
  by_from.clear();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (segments[i].from_key != segments[i].to_key) by_from.push_back(static_cast<std::int32_t>(i));
  }
  const auto from_of = [&](std::int32_t i) {
    return segments[static_cast<std::size_t>(i)].from_key;
  };
  std::stable_sort(by_from.begin(), by_from.end(), [&](std::int32_t a, std::int32_t b) {
    const CrossingSegment& sa = segments[static_cast<std::size_t>(a)];
    const CrossingSegment& sb = segments[static_cast<std::size_t>(b)];
    return sa.from_key != sb.from_key ? sa.from_key < sb.from_key : sa.triangle < sb.triangle;
  });
  std::vector<std::size_t>& cursor = scratch.cursor;
  cursor.resize(by_from.size());
  std::iota(cursor.begin(), cursor.end(), std::size_t{0});  // valid at each run's first slot
  std::vector<char>& used = scratch.used;
  used.assign(segments.size(), 0);

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

  std::vector<std::int32_t>& walk = scratch.walk;
  for (const std::int32_t start : by_from) {
    if (used[static_cast<std::size_t>(start)]) continue;
    walk.clear();
    for (std::int32_t s = start; s >= 0; s = take(segments[static_cast<std::size_t>(s)].to_key)) {
      used[static_cast<std::size_t>(s)] = 1;
      walk.push_back(s);
    }
    add_ring(segments, walk, rings, triangles);
  }
}

}  // namespace

void write_cycles(std::span<const CrossingSegment> segments, std::span<const std::int32_t> walk,
                  std::vector<ChainCycle>& cycles, std::vector<Ring>& rings, Triangles* triangles,
                  std::vector<std::int32_t>& rotated) {
  std::sort(cycles.begin(), cycles.end(),
            [](const ChainCycle& a, const ChainCycle& b) { return a.least < b.least; });
  for (const ChainCycle& cycle : cycles) {
    const auto begin = walk.begin() + static_cast<std::ptrdiff_t>(cycle.begin);
    const auto first = begin + static_cast<std::ptrdiff_t>(cycle.first);
    rotated.assign(first, begin + static_cast<std::ptrdiff_t>(cycle.size));
    rotated.insert(rotated.end(), begin, first);
    add_ring(segments, rotated, rings, triangles);
  }
}

std::vector<Ring> chain_rings(std::span<const CrossingSegment> segments, Triangles* triangles,
                              ChainScratch& scratch) {
  std::vector<Ring> rings;
  // chain_cycles writes nothing when it declines.
  if (!chain_cycles(segments, rings, triangles, scratch)) {
    chain_general(segments, rings, triangles, scratch);
  }
  return rings;
}

std::vector<Ring> chain_rings(std::span<const CrossingSegment> segments, Triangles* triangles) {
  ChainScratch scratch;
  return chain_rings(segments, triangles, scratch);
}

}  // namespace contain::clip::slice
