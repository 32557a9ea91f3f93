#pragma once
// Small helpers shared by the arrangement's stages (arrangement.cpp, extract.cpp); their
// union-find is core's. Private to the boolean engine.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "contain/values/vec.h"

namespace contain::clip::detail::graph {

inline constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

inline bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// 0 for directions in [0, pi), 1 for [pi, 2 pi).
inline int half_of(Vec2 o, Vec2 p) {
  return (p.y > o.y || (p.y == o.y && p.x > o.x)) ? 0 : 1;
}

}  // namespace contain::clip::detail::graph
