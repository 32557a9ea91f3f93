// Minimal enclosing sphere of 10^6 random points, uniform in a ball and in a cube:
// contain::bound::bounding_sphere (exact and Ritter) against CGAL's Min_sphere_of_spheres_d with
// zero radii (double number type, Tag_true: square roots allowed; its default Farthest-first
// heuristic and its LP algorithm), on the same points in one run, each library reading its own
// input format prepared outside the timed loop. Answers are checked outside the timed loop:
// exact containment of every point with predicates::side_of_sphere, and the radius against the
// exact (GMP) minimal ball of the 12 points farthest from the center, which bounds the true
// minimal radius from below.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "bound/brute_force_ball.h"
#include "contain/bound/bounding_sphere.h"
#include "contain/predicates/compare_distance.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Min_sphere_of_spheres_d_traits_3.h>
#include <CGAL/Simple_cartesian.h>
#endif

namespace {

using contain::Sphere;
using contain::Vec3;

constexpr std::size_t kPoints = 1'000'000;
constexpr int kRepeats = 9;

std::vector<Vec3> in_ball(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> out;
  out.reserve(kPoints);
  while (out.size() < kPoints) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    if (contain::squared_length(p) <= 1.0) out.push_back(p);
  }
  return out;
}

std::vector<Vec3> in_cube(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> out(kPoints);
  for (Vec3& p : out)
    p = {u(rng), u(rng), u(rng)};
  return out;
}

// Median wall time of `run` in milliseconds; `run` returns the sphere it computed.
double median_ms(const std::function<Sphere()>& run, Sphere& result) {
  std::vector<double> ms;
  for (int i = 0; i < kRepeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    result = run();
    const auto stop = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

std::size_t count_outside(const Sphere& s, const std::vector<Vec3>& points) {
  std::size_t n = 0;
  for (const Vec3& p : points) {
    n += contain::predicates::side_of_sphere(s, p) == contain::Sign::negative ? 1 : 0;
  }
  return n;
}

// A lower bound of the true minimal radius: the exact minimal ball of the 12 points farthest
// from `center` (any subset's minimal ball is no larger than the whole set's).
double radius_lower_bound(const std::vector<Vec3>& points, Vec3 center) {
  std::vector<Vec3> top(points);
  std::partial_sort(top.begin(), top.begin() + 12, top.end(), [&](const Vec3& a, const Vec3& b) {
    return contain::squared_length(a - center) > contain::squared_length(b - center);
  });
  top.resize(12);
  const auto ball = contain::test::brute_force_min_ball(std::span<const Vec3>(top));
  mpf_class r(0, 256);
  r = sqrt(mpf_class(ball.squared_radius, 256));
  return r.get_d();
}

#ifdef CONTAIN_BENCH_HAS_CGAL
using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalSphere = std::pair<CgalKernel::Point_3, double>;

// CGAL's input in its own format (built outside the timed loop, as contain's span is).
std::vector<CgalSphere> cgal_input(const std::vector<Vec3>& points) {
  std::vector<CgalSphere> spheres;
  spheres.reserve(points.size());
  for (const Vec3& p : points)
    spheres.emplace_back(CgalKernel::Point_3(p.x, p.y, p.z), 0.0);
  return spheres;
}

template <class Algorithm>
Sphere cgal_sphere(const std::vector<CgalSphere>& spheres) {
  using Traits =
      CGAL::Min_sphere_of_spheres_d_traits_3<CgalKernel, double, CGAL::Tag_true, Algorithm>;
  CGAL::Min_sphere_of_spheres_d<Traits> ms(spheres.begin(), spheres.end());
  auto c = ms.center_cartesian_begin();
  Sphere s;
  s.center.x = *c++;
  s.center.y = *c++;
  s.center.z = *c;
  s.radius = ms.radius();
  return s;
}
#endif

void row(const char* name, double ms, double base_ms, const Sphere& s, double lower,
         const std::vector<Vec3>& points) {
  std::printf("  %-34s %8.2f ms  x%5.2f  radius %.17g  (r - r_lb)/r_lb %+.2e  outside %zu\n", name,
              ms, ms / base_ms, s.radius, (s.radius - lower) / lower, count_outside(s, points));
}

void scene(const char* name, const std::vector<Vec3>& points) {
  std::printf("%s: %zu points\n", name, points.size());
  Sphere exact;
  const double exact_ms =
      median_ms([&] { return *contain::bound::bounding_sphere(points); }, exact);
  const double lower = radius_lower_bound(points, exact.center);
  row("contain exact (Welzl/Gaertner)", exact_ms, exact_ms, exact, lower, points);
  Sphere ritter;
  const double ritter_ms = median_ms(
      [&] {
        return *contain::bound::bounding_sphere(points,
                                                {.method = contain::bound::SphereMethod::ritter});
      },
      ritter);
  row("contain ritter", ritter_ms, exact_ms, ritter, lower, points);
#ifdef CONTAIN_BENCH_HAS_CGAL
  const std::vector<CgalSphere> spheres = cgal_input(points);
  Sphere ff;
  const double ff_ms =
      median_ms([&] { return cgal_sphere<CGAL::Farthest_first_heuristic>(spheres); }, ff);
  row("CGAL Min_sphere_of_spheres_d (FF)", ff_ms, exact_ms, ff, lower, points);
  Sphere lp;
  const double lp_ms = median_ms([&] { return cgal_sphere<CGAL::LP_algorithm>(spheres); }, lp);
  row("CGAL Min_sphere_of_spheres_d (LP)", lp_ms, exact_ms, lp, lower, points);
  std::printf("  CGAL(FF) / contain exact: time x%.2f, radius difference %+.2e relative\n",
              ff_ms / exact_ms, (ff.radius - exact.radius) / exact.radius);
#else
  std::printf("  (CGAL not found: no peer)\n");
#endif
}

}  // namespace

int main() {
  std::printf(
      "x = time / contain exact; r_lb = exact (GMP) minimal radius of the 12 points farthest from\n"
      "the contain center, a lower bound of the true minimum; outside = points outside the sphere\n"
      "by the exact predicate; times are the median of %d runs\n",
      kRepeats);
  std::mt19937_64 rng(20240601);
  scene("uniform in the unit ball", in_ball(rng));
  scene("uniform in the cube [-1,1]^3", in_cube(rng));
  return 0;
}
