#include "distance/morton_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "contain/values/box.h"

namespace contain::distance::detail {

namespace {

// Spreads the low 10 bits of x to every third bit.
std::uint32_t spread3(std::uint32_t x) {
  x &= 0x3ffU;
  x = (x | (x << 16)) & 0x030000ffU;
  x = (x | (x << 8)) & 0x0300f00fU;
  x = (x | (x << 4)) & 0x030c30c3U;
  x = (x | (x << 2)) & 0x09249249U;
  return x;
}
// Spreads the low 16 bits of x to every second bit.
std::uint32_t spread2(std::uint32_t x) {
  x &= 0xffffU;
  x = (x | (x << 8)) & 0x00ff00ffU;
  x = (x | (x << 4)) & 0x0f0f0f0fU;
  x = (x | (x << 2)) & 0x33333333U;
  x = (x | (x << 1)) & 0x55555555U;
  return x;
}

// Cell of x in [lo, hi] with `cells` cells; halves avoid overflow of hi - lo.
std::uint32_t cell(double x, double lo, double hi, double cells) {
  const double span = hi * 0.5 - lo * 0.5;
  if (!(span > 0)) return 0;
  const double t = (x * 0.5 - lo * 0.5) / span * cells;
  if (!(t >= 0)) return 0;
  return static_cast<std::uint32_t>(std::min(t, cells - 1));
}

template <class Key>
std::vector<std::uint32_t> sorted_by(std::size_t n, Key&& key) {
  std::vector<std::uint64_t> keyed(n);
  for (std::size_t i = 0; i < n; ++i)
    keyed[i] = (static_cast<std::uint64_t>(key(i)) << 32) | i;
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = static_cast<std::uint32_t>(keyed[i] & 0xffffffffU);
  return order;
}

}  // namespace

std::vector<std::uint32_t> morton_order(std::span<const Vec3> points) {
  Box3 box;
  for (const Vec3& p : points)
    if (is_finite(p)) box.expand(p);
  return sorted_by(points.size(), [&](std::size_t i) -> std::uint32_t {
    const Vec3 p = points[i];
    if (!is_finite(p)) return 0xffffffffU;
    return spread3(cell(p.x, box.min.x, box.max.x, 1024)) |
           (spread3(cell(p.y, box.min.y, box.max.y, 1024)) << 1) |
           (spread3(cell(p.z, box.min.z, box.max.z, 1024)) << 2);
  });
}

std::vector<std::uint32_t> morton_order(std::span<const Vec2> points) {
  Box2 box;
  for (const Vec2& p : points)
    if (is_finite(p)) box.expand(p);
  return sorted_by(points.size(), [&](std::size_t i) -> std::uint32_t {
    const Vec2 p = points[i];
    if (!is_finite(p)) return 0xffffffffU;
    return spread2(cell(p.x, box.min.x, box.max.x, 65536)) |
           (spread2(cell(p.y, box.min.y, box.max.y, 65536)) << 1);
  });
}

}  // namespace contain::distance::detail
