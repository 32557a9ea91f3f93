#include "clip/boolean/chains.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace contain::clip::detail {

std::vector<Chain> monotone_chains(std::span<const NodingInput> segments,
                                   std::span<const char> links) {
  std::vector<Chain> chains;
  const auto n = static_cast<std::uint32_t>(segments.size());
  for (std::uint32_t c = 0; c < n;) {
    // The directions so far: 0 while every segment was flat in that coordinate.
    const Vec2 d = segments[c].b - segments[c].a;
    int sx = (d.x > 0) - (d.x < 0), sy = (d.y > 0) - (d.y < 0);
    std::uint32_t e = c + 1;
    for (; e < n && links[e - 1] != 0; ++e) {
      const Vec2 t = segments[e].b - segments[e].a;
      if ((sx > 0 && t.x < 0) || (sx < 0 && t.x > 0) || (sy > 0 && t.y < 0) || (sy < 0 && t.y > 0))
        break;
      if (sx == 0) sx = (t.x > 0) - (t.x < 0);
      if (sy == 0) sy = (t.y > 0) - (t.y < 0);
    }
    const Vec2 p = segments[c].a, q = segments[e - 1].b;
    chains.push_back(
        {c, e, std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y)});
    c = e;
  }
  return chains;
}

}  // namespace contain::clip::detail
