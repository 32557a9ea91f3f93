#include "contain/predicates/orient2d.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

// det[b - a, c - a] from the differences (b - a, c - a) as exact numbers.
template <class D>
Sign orient2d_of(const std::array<D, 4>& d) {
  return (d[0] * d[3] - d[1] * d[2]).sign();
}

}  // namespace

namespace {

// Differences with tails. Kept out of line: building its arrays at the entry of the caller would
// cost the fast path a store-to-load forwarding stall on every call.
[[gnu::noinline]] Sign orient2d_general(Vec2 a, Vec2 b, Vec2 c) {
  std::array<Expansion<2>, 4> d;
  (void)differences(std::array{b.x, b.y, c.x, c.y}, std::array{a.x, a.y, a.x, a.y}, d);
  return orient2d_of(d);
}

}  // namespace

Sign orient2d_expansion(Vec2 a, Vec2 b, Vec2 c) {
  std::array<double, 4> head;
  std::array<double, 4> tail;
  two_diff(b.x, a.x, head[0], tail[0]);
  two_diff(b.y, a.y, head[1], tail[1]);
  two_diff(c.x, a.x, head[2], tail[2]);
  two_diff(c.y, a.y, head[3], tail[3]);
  if (tail[0] == 0.0 && tail[1] == 0.0 && tail[2] == 0.0 && tail[3] == 0.0) {
    // Exact differences (Shewchuk's stage B): the determinant is the four-component
    // Two-Two-Diff of two Two-Products, computed without branches.
    double l1, l0, r1, r0;
    two_product(head[0], head[3], l1, l0);
    two_product(head[1], head[2], r1, r0);
    std::array<double, 4> x;
    two_two_diff(l1, l0, r1, r0, x[3], x[2], x[1], x[0]);
    return sign_of_largest(x);
  }
  return orient2d_general(a, b, c);
}

Sign orient2d_big(Vec2 a, Vec2 b, Vec2 c) {
  const BigFloat ax(a.x), ay(a.y);
  return orient2d_of(
      std::array{BigFloat(b.x) - ax, BigFloat(b.y) - ay, BigFloat(c.x) - ax, BigFloat(c.y) - ay});
}

namespace {

// Inputs beyond the expansion range: rescaled into it if their exponents allow, else big
// numbers. Out of line so that the fast path does not pay for packing these arrays.
[[gnu::noinline]] Sign orient2d_extreme(Vec2 a, Vec2 b, Vec2 c) {
  std::array v{a.x, a.y, b.x, b.y, c.x, c.y};
  if (scale_into_expansion_range<2>(v)) {
    return orient2d_expansion({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]});
  }
  return orient2d_big(a, b, c);
}

}  // namespace

Sign orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  if (in_expansion_range<2>(a.x, a.y, b.x, b.y, c.x, c.y)) return orient2d_expansion(a, b, c);
  return orient2d_extreme(a, b, c);
}

}  // namespace detail

}  // namespace contain::predicates
