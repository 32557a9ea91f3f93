// libFuzzer target: exact distances against the GMP oracle. A point and a small mesh of 1-4
// triangles (shared corners, collinear and coincident ones, 2^+-1000 scalings from
// fuzz_support.h), and a point and a segment in the plane. Claims checked: MeshDistance's
// distance, closest point and closest triangle (ties to the lowest) are the oracle's rounded
// once; `within` is exact at the rounded distance and its neighbours; point_triangle agrees;
// the 2D segment distance is the oracle's rounded. Then two meshes of 1-3 triangles, B placed by
// a transform (rotation entries from a small set, any translation): MeshPairDistance's distance
// is the rounded exact least triangle-pair distance, its triangles the oracle's (ties to the
// lowest of A, then of B), and its `within` exact at the distance and its neighbours.
#include <cfloat>
#include <cmath>

#include "contain/distance/mesh_distance.h"
#include "contain/distance/mesh_pair_distance.h"
#include "contain/distance/point_primitive.h"
#include "distance/mesh_oracle.h"
#include "fuzz_support.h"
#include "support/exact_distance.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  const int n = 1 + in.byte() % 4;
  std::vector<Vec3> v;
  std::vector<TriangleIndices> t;
  for (int i = 0; i < 3 * n; ++i) {
    const std::uint8_t how = in.byte();
    v.push_back((i > 0 && how % 5 == 0) ? v[how / 5 % static_cast<unsigned>(i)] : in.point3());
  }
  for (int i = 0; i < n; ++i)
    t.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  const std::uint8_t where = in.byte();
  const Vec3 p = where % 4 == 0 ? v[where / 4 % v.size()] : in.point3();
  auto mesh = Mesh::from_arrays(v, t);
  FUZZ_CHECK(static_cast<bool>(mesh));

  // oracle: least exact squared distance, lowest triangle
  mpq_class best;
  test::QVec3 best_point;
  int best_t = -1;
  for (int i = 0; i < n; ++i) {
    const Triangle3 tri{v[static_cast<std::size_t>(3 * i)], v[static_cast<std::size_t>(3 * i + 1)],
                        v[static_cast<std::size_t>(3 * i + 2)]};
    const test::ExactClosest3 c = test::exact_closest(p, tri);
    if (best_t < 0 || c.squared_distance < best) {
      best = c.squared_distance;
      best_point = c.point;
      best_t = i;
    }
    const distance::Closest3 one = distance::point_triangle(tri, p);
    FUZZ_CHECK(one.distance == test::nearest_double_sqrt(c.squared_distance));
  }
  const distance::MeshDistance prepared(*mesh, {.signs = false});
  const distance::Closest3 got = prepared.distance(p);
  FUZZ_CHECK(got.distance == test::nearest_double_sqrt(best));
  FUZZ_CHECK(got.feature == best_t);
  FUZZ_CHECK(got.point.x == test::nearest_double(best_point.x));
  FUZZ_CHECK(got.point.y == test::nearest_double(best_point.y));
  FUZZ_CHECK(got.point.z == test::nearest_double(best_point.z));
  for (const double d :
       {got.distance, std::nextafter(got.distance, 0.0), std::nextafter(got.distance, DBL_MAX)}) {
    if (!std::isfinite(d)) continue;
    const mpq_class q(d);
    FUZZ_CHECK(prepared.within(p, d) == (best <= q * q));
  }

  const Vec2 a = in.point2(), b = in.point2(), q2 = in.point2();
  const test::ExactClosest2 c2 = test::exact_closest(q2, Segment2{a, b});
  FUZZ_CHECK(distance::point_segment(Segment2{a, b}, q2).distance ==
             test::nearest_double_sqrt(c2.squared_distance));

  // Two small meshes, B placed.
  const auto small_mesh = [&](int count) {
    std::vector<Vec3> corners;
    std::vector<TriangleIndices> faces;
    for (int i = 0; i < 3 * count; ++i) {
      const std::uint8_t how = in.byte();
      corners.push_back((i > 0 && how % 5 == 0) ? corners[how / 5 % static_cast<unsigned>(i)]
                                                : in.point3());
    }
    for (int i = 0; i < count; ++i)
      faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    return Mesh::from_arrays(corners, faces);
  };
  const auto ma = small_mesh(1 + in.byte() % 3);
  const auto mb = small_mesh(1 + in.byte() % 3);
  FUZZ_CHECK(static_cast<bool>(ma) && static_cast<bool>(mb));
  constexpr double kEntries[] = {0.0, 1.0, -1.0, 0.5, -0.5, 0.6, -0.8, 0x1p-30};
  Transform tb;
  for (auto& row : tb.r)
    for (double& x : row)
      x = kEntries[in.byte() % 8];
  tb.t = in.point3();
  Mesh placed = *mb;
  for (Vec3& x : placed.vertices) {
    x = tb.apply(x);
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) return 0;
  }
  const test::PairOracle want = test::pair_oracle(*ma, placed);
  const distance::MeshPairDistance pair(*ma, *mb);
  const distance::PairDistance3 d = pair.distance(tb);
  FUZZ_CHECK(d.distance == test::nearest_double_sqrt(want.d2));
  FUZZ_CHECK(d.triangle_a == want.a && d.triangle_b == want.b);
  for (const double x :
       {d.distance, std::nextafter(d.distance, 0.0), std::nextafter(d.distance, DBL_MAX)}) {
    if (!std::isfinite(x)) continue;
    const mpq_class q(x);
    FUZZ_CHECK(pair.within(tb, x) == (want.d2 <= q * q));
  }
  return 0;
}
