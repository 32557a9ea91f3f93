// libFuzzer target: every predicate on finite doubles biased towards degeneracy (coincident,
// collinear, coplanar points, one-ulp nudges, 2^±1000 scalings, raw bit patterns), checked
// against the GMP rational oracle and against each other: orient2d is orient3d of the lifted
// points, orient2d and orient3d change sign under a swap, cross_dot is symmetric and
// cross_dot(a, b, p, p) >= 0.
#include "contain/predicates/compare_distance.h"
#include "contain/predicates/cross_dot.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/side_of_plane.h"
#include "fuzz_support.h"
#include "support/exact.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  using namespace contain::predicates;
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  const Vec3 a = in.point3(), b = in.point3(), c = in.point3(), d = in.point3();
  const Vec2 a2{a.x, a.y}, b2{b.x, b.y}, c2{c.x, c.y};

  const Sign o2 = orient2d(a2, b2, c2);
  FUZZ_CHECK(o2 == test::exact_orient2d(a2, b2, c2));
  FUZZ_CHECK(orient2d(b2, a2, c2) == -o2);
  FUZZ_CHECK(orient2d(b2, c2, a2) == o2);
  // Lifted to z = 0 with the apex one unit above: ((b - a) x (c - a)).z * 1.
  FUZZ_CHECK(orient3d({a.x, a.y, 0}, {b.x, b.y, 0}, {c.x, c.y, 0}, {d.x, d.y, 1}) == o2);

  const Sign o3 = orient3d(a, b, c, d);
  FUZZ_CHECK(o3 == test::exact_orient3d(a, b, c, d));
  FUZZ_CHECK(orient3d(b, a, c, d) == -o3);
  FUZZ_CHECK(orient3d(b, c, a, d) == o3);

  const Plane plane{b.x, b.y, b.z, c.x};
  FUZZ_CHECK(side_of_plane(plane, a) == test::exact_side_of_plane(plane, a));
  const HalfPlane half_plane{b.x, b.y, b.z};
  FUZZ_CHECK(side_of_line(half_plane, a2) == test::exact_side_of_line(half_plane, a2));

  const Sphere ball{b, c.x};
  FUZZ_CHECK(side_of_sphere(ball, a) == test::exact_side_of_sphere(ball, a));
  const Circle disc{b2, c.y};
  FUZZ_CHECK(side_of_circle(disc, a2) == test::exact_side_of_circle(disc, a2));

  const Sign cd = cross_dot(a, b, c, d);
  FUZZ_CHECK(cd == test::exact_cross_dot(a, b, c, d));
  FUZZ_CHECK(cross_dot(a, b, d, c) == cd);
  FUZZ_CHECK(cross_dot(b, a, c, d) == cd);
  FUZZ_CHECK(cross_dot(a, b, c, c) != Sign::negative);
  return 0;
}
