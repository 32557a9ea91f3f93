#include "bound/ball_checks.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "bound/brute_force_ball.h"
#include "support/exact.h"

namespace contain::test {
namespace {

template <class P, class Ball>
double relative_excess_impl(const Ball& ball, std::span<const P> points) {
  // Distinct points only: repeated copies of one far point would crowd out the support.
  std::vector<P> candidates(points.begin(), points.end());
  std::sort(candidates.begin(), candidates.end(),
            [](const P& a, const P& b) { return std::memcmp(&a, &b, sizeof(P)) < 0; });
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  constexpr std::size_t kAll = 14;
  constexpr std::size_t kTop = 12;
  if (candidates.size() > kAll) {
    std::partial_sort(candidates.begin(), candidates.begin() + kTop, candidates.end(),
                      [&](const P& a, const P& b) {
                        return squared_length(a - ball.center) > squared_length(b - ball.center);
                      });
    candidates.resize(kTop);
  }
  const ExactBall truth = brute_force_min_ball(std::span<const P>(candidates));
  const mpq_class r2 = exact_square(ball.radius);
  if (sgn(truth.squared_radius) == 0) {
    return ball.radius == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  const mpq_class ratio = r2 / truth.squared_radius;  // (r / r_min)^2, exactly
  if (ratio < 1) return -1.0;
  // sqrt(1 + t) - 1 = t / (sqrt(1 + t) + 1) keeps the tiny difference accurate.
  const double t = mpq_class(ratio - 1).get_d();
  return t / (std::sqrt(1.0 + t) + 1.0);
}

}  // namespace

std::size_t count_outside(const Sphere& sphere, std::span<const Vec3> points) {
  std::size_t n = 0;
  for (const Vec3& p : points)
    n += exact_side_of_sphere(sphere, p) == Sign::negative ? 1 : 0;
  return n;
}

std::size_t count_outside(const Circle& circle, std::span<const Vec2> points) {
  std::size_t n = 0;
  for (const Vec2& p : points)
    n += exact_side_of_circle(circle, p) == Sign::negative ? 1 : 0;
  return n;
}

double relative_excess(const Sphere& sphere, std::span<const Vec3> points) {
  return relative_excess_impl(sphere, points);
}

double relative_excess(const Circle& circle, std::span<const Vec2> points) {
  return relative_excess_impl(circle, points);
}

}  // namespace contain::test
