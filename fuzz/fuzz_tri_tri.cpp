// libFuzzer target: exact triangle-triangle tests (3D and 2D) on random and degenerate pairs
// (coplanar, sharing a vertex or an edge, touching at a point, collinear or coincident corners,
// 2^±1000 scalings). Claims checked: the answer agrees with the GMP rational oracle of the tests
// (a different route: edges against triangles in exact rationals), is symmetric in the two
// triangles, does not depend on the order of the corners, and the 3D test on triangles in the
// plane z = 0 agrees with the 2D test.
#include "contain/collide/tri_tri.h"
#include "contain/collide/tri_tri_2d.h"
#include "fuzz_support.h"
#include "support/tri_tri_oracle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  Vec3 p[6];
  for (int i = 0; i < 6; ++i) {
    const std::uint8_t how = in.byte();
    p[i] = (i > 0 && how % 6 == 0) ? p[how / 6 % i] : in.point3();  // shared corners
  }
  const bool flat = in.byte() % 4 == 0;
  if (flat) {
    for (Vec3& v : p)
      v.z = 0.0;
  }
  const Triangle3 a{p[0], p[1], p[2]}, b{p[3], p[4], p[5]};
  const bool hit = collide::tri_tri(a, b);
  FUZZ_CHECK(hit == test::exact_tri_tri_3d(a, b));
  FUZZ_CHECK(collide::tri_tri(b, a) == hit);
  FUZZ_CHECK(collide::tri_tri(Triangle3{a.b, a.c, a.a}, b) == hit);
  FUZZ_CHECK(collide::tri_tri(a, Triangle3{b.a, b.c, b.b}) == hit);
  if (flat) {
    const Triangle2 a2{{a.a.x, a.a.y}, {a.b.x, a.b.y}, {a.c.x, a.c.y}};
    const Triangle2 b2{{b.a.x, b.a.y}, {b.b.x, b.b.y}, {b.c.x, b.c.y}};
    FUZZ_CHECK(collide::tri_tri(a2, b2) == hit);
    FUZZ_CHECK(test::exact_tri_tri_2d(a2, b2) == hit);
  }
  return 0;
}
