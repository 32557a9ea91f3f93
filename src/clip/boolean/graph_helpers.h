#pragma once
// Small helpers shared by the arrangement's stages (arrangement.cpp, extract.cpp). Private to
// the boolean engine.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "contain/geometry/vec.h"

namespace contain::clip::detail::graph {

inline constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

inline bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// 0 for directions in [0, pi), 1 for [pi, 2 pi).
inline int half_of(Vec2 o, Vec2 p) {
  return (p.y > o.y || (p.y == o.y && p.x > o.x)) ? 0 : 1;
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace contain::clip::detail::graph
