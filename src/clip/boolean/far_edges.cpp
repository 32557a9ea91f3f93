#include "clip/boolean/far_edges.h"

#include <algorithm>
#include <cmath>

namespace contain::clip::detail {

Operand measure(std::span<const Ring> rings) {
  Operand o;
  for (const Ring& ring : rings) {
    // Every point of a ring with an edge is the start of an edge or equal to one.
    const std::size_t n = ring.size();
    if (n == 0) continue;
    std::size_t edges = 0;
    Box2 box;
    Vec2 a = ring[n - 1];
    for (const Vec2 b : ring) {
      edges += a != b ? 1 : 0;
      box.expand(b);
      a = b;
    }
    if (edges == 0) continue;
    o.edges += edges;
    o.box.expand(box);
    o.magnitude = std::max({o.magnitude, std::fabs(box.min.x), std::fabs(box.max.x),
                            std::fabs(box.min.y), std::fabs(box.max.y)});
  }
  return o;
}

}  // namespace contain::clip::detail
