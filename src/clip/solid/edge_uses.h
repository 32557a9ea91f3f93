#pragma once
// The edge uses of a set of faces, grouped by edge: the adjacency that the labels (patches),
// the merging of coplanar faces (regions) and the sheets (fans) walk. Private to clip.
//
// The uses are bucketed by the edge's lower point (a counting sort), and each bucket holds
// 8-byte entries (the edge's higher point, the face), sorted as integers: the order is that of
// (edge, face), the key's lower half being the bucket. A face's corner at the edge is found
// again from its three corners when needed instead of being stored: half the memory of entries
// of (edge key, face, corner), each fresh page of which costs a fault, and integer compares in
// the buckets' insertion sorts.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "clip/solid/scratch.h"
#include "contain/core/sort_few.h"

namespace contain::clip::solid {

/// Every edge use of some faces: for point p, `entry[start[p] .. start[p + 1])` are the uses of
/// the edges whose lower point is p, each (higher point << 32) | face, ascending.
struct EdgeUses {
  ScratchVector<std::size_t> start;
  ScratchVector<std::uint64_t> entry;

  [[nodiscard]] static std::int32_t higher(std::uint64_t e) {
    return static_cast<std::int32_t>(e >> 32U);
  }
  [[nodiscard]] static std::uint32_t face(std::uint64_t e) {
    return static_cast<std::uint32_t>(e & 0xffffffffU);
  }
};

/// The corner k of `v` where its `nth` use (0-based, in order of k) of the undirected edge
/// {a, b} starts (the edge runs from corner k to corner k + 1); 0 when there is none.
[[nodiscard]] inline int corner_of_edge(const std::array<std::int32_t, 3>& v, std::int32_t a,
                                        std::int32_t b, int nth) {
  for (int k = 0; k < 3; ++k) {
    const std::int32_t p = v[static_cast<std::size_t>(k)];
    const std::int32_t q = v[static_cast<std::size_t>((k + 1) % 3)];
    if (((p == a && q == b) || (p == b && q == a)) && nth-- == 0) return k;
  }
  return 0;
}

/// Each point's corners, 3 face + k, by a counting sort of the corners by point: after it,
/// `corner[end[p - 1] .. end[p])` (from 0 for p = 0) are p's corners in face order. The walks
/// around points (the labels' patches, the sheets' umbrellas) start from it.
struct CornersByPoint {
  std::size_t points = 0;               ///< the highest point + 1
  ScratchVector<std::uint32_t> end;     ///< points + 1 entries
  ScratchVector<std::uint32_t> corner;  ///< 3 F entries
};

/// The corners by point of `faces` faces (`corners(face)` as for edge_uses). Faces are numbered
/// in 32 bits (fewer than 2^32 / 3).
template <class Corners>
[[nodiscard]] CornersByPoint corners_by_point(std::size_t faces, Corners&& corners) {
  CornersByPoint out;
  for (std::size_t f = 0; f < faces; ++f) {
    for (const std::int32_t p : corners(f))
      out.points = std::max(out.points, static_cast<std::size_t>(p) + 1);
  }
  out.end.assign(out.points + 1, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    for (const std::int32_t p : corners(f))
      ++out.end[static_cast<std::size_t>(p) + 1];
  }
  for (std::size_t p = 0; p < out.points; ++p)
    out.end[p + 1] += out.end[p];
  out.corner.resize(out.end[out.points]);  // each written next
  for (std::size_t f = 0; f < faces; ++f) {
    const auto& v = corners(f);
    for (std::size_t k = 0; k < 3; ++k)
      out.corner[out.end[static_cast<std::size_t>(v[k])]++] = static_cast<std::uint32_t>(3 * f + k);
  }
  return out;
}

/// The edge uses of `faces` faces (indexable: `corners(face)` returns the face's three corner
/// numbers, non-negative). Faces are numbered in 32 bits.
template <class Corners>
[[nodiscard]] EdgeUses edge_uses(std::size_t faces, Corners&& corners) {
  std::size_t points = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    for (const std::int32_t p : corners(f))
      points = std::max(points, static_cast<std::size_t>(p) + 1);
  }
  EdgeUses out;
  out.start.assign(points + 1, 0);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto& v = corners(f);
    for (std::size_t k = 0; k < 3; ++k)
      ++out.start[static_cast<std::size_t>(std::min(v[k], v[(k + 1) % 3])) + 1];
  }
  for (std::size_t i = 1; i < out.start.size(); ++i)
    out.start[i] += out.start[i - 1];
  out.entry.resize(out.start.back());
  ScratchVector<std::size_t> next(out.start.begin(), out.start.end() - 1);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto& v = corners(f);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t a = v[k], b = v[(k + 1) % 3];
      out.entry[next[static_cast<std::size_t>(std::min(a, b))]++] =
          (std::uint64_t{static_cast<std::uint32_t>(std::max(a, b))} << 32U) |
          static_cast<std::uint32_t>(f);
    }
  }
  // Each point's uses (about six on a mesh; a fan's apex more).
  for (std::size_t i = 0; i + 1 < out.start.size(); ++i) {
    sort_few(out.entry.begin() + static_cast<std::ptrdiff_t>(out.start[i]),
             out.entry.begin() + static_cast<std::ptrdiff_t>(out.start[i + 1]), 16);
  }
  return out;
}

/// Calls `visit(a, b, uses)` for each edge a < b, in ascending order of (a, b), with its uses
/// (entries of EdgeUses, ascending by face; a face using the edge twice is there twice).
template <class Visit>
void for_each_edge(const EdgeUses& uses, Visit&& visit) {
  for (std::size_t p = 0; p + 1 < uses.start.size(); ++p) {
    const std::size_t end = uses.start[p + 1];
    for (std::size_t i = uses.start[p]; i < end;) {
      const std::int32_t q = EdgeUses::higher(uses.entry[i]);
      std::size_t j = i + 1;
      while (j < end && EdgeUses::higher(uses.entry[j]) == q)
        ++j;
      visit(static_cast<std::int32_t>(p), q,
            std::span<const std::uint64_t>(uses.entry.data() + i, j - i));
      i = j;
    }
  }
}

}  // namespace contain::clip::solid
