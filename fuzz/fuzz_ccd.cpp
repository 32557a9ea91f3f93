// libFuzzer target: exact continuous collision of primitives (vertex-face and edge-edge) on
// random and degenerate motions (shared points, zero motion, coplanar and collinear motion,
// touching at t = 0 or t = 1, 2^+-1000 scalings, raw double bits). Claims checked: hit and time
// equal the GMP oracle of the tests (a different route: Sturm sequences over the rationals,
// inclusion in a projection chosen at each root), the time lies in [0, 1], and the answer does
// not depend on the order of the triangle's corners, on the direction of the edges or on which
// edge comes first.
#include "collide/ccd_oracle.h"
#include "contain/collide/ccd.h"
#include "fuzz_support.h"

#include <algorithm>
#include <cmath>

namespace {

using contain::collide::CcdQuery;
using contain::collide::Impact;

bool same(const Impact& a, const Impact& b) {
  return a.hit == b.hit && (!a.hit || a.time == b.time);
}

void check(const Impact& got, const std::optional<double>& expected) {
  FUZZ_CHECK(got.hit == expected.has_value());
  if (got.hit) {
    FUZZ_CHECK(got.time == *expected);
    FUZZ_CHECK(got.time >= 0.0 && got.time <= 1.0);
  }
}

// Coordinates more than 2^400 below the largest become 0: the GMP oracle's rationals grow with
// the exponent spread of a query (seconds per query beyond ~2^1000 at -O0), the library's
// exact stage does not mind (tests/collide/ccd_test.cpp compares the whole range with the
// oracle, optimised); the fuzzer's budget is better spent on degenerate structure.
void limit_spread(CcdQuery& q) {
  int top = -2000;
  for (const auto& v : q) {
    for (const double c : {v.x, v.y, v.z}) {
      if (c != 0.0) top = std::max(top, std::ilogb(c));
    }
  }
  for (auto& v : q) {
    for (double* c : {&v.x, &v.y, &v.z}) {
      if (*c != 0.0 && std::ilogb(*c) < top - 400) *c = 0.0;
    }
  }
}

// Point i at t = 0 and t = 1 reordered by `order`.
CcdQuery permuted(const CcdQuery& q, const int (&order)[4]) {
  CcdQuery r;
  for (int i = 0; i < 4; ++i) {
    r[static_cast<std::size_t>(i)] = q[static_cast<std::size_t>(order[i])];
    r[static_cast<std::size_t>(i + 4)] = q[static_cast<std::size_t>(order[i] + 4)];
  }
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  CcdQuery q;
  for (std::size_t i = 0; i < 8; ++i) {
    const std::uint8_t how = in.byte();
    if (i >= 4 && how % 5 == 0) {
      q[i] = q[i - 4];  // this point does not move
    } else if (i > 0 && how % 7 == 0) {
      q[i] = q[how / 7 % i];  // the same position as an earlier point
    } else {
      q[i] = in.point3();
    }
  }
  switch (in.byte() % 8) {
    case 0:  // all in one plane z = c at both times
      for (Vec3& v : q)
        v.z = q[0].z;
      break;
    case 1:  // one plane per time: coplanar motion in a moving plane
      for (std::size_t i = 0; i < 8; ++i)
        q[i].y = q[i < 4 ? 0 : 4].y;
      break;
    default:
      break;
  }
  limit_spread(q);
  const Impact vf = collide::vertex_face_ccd(q);
  check(vf, test::exact_vertex_face_time(q));
  FUZZ_CHECK(same(vf, collide::vertex_face_ccd(permuted(q, {0, 2, 3, 1}))));
  FUZZ_CHECK(same(vf, collide::vertex_face_ccd(permuted(q, {0, 1, 3, 2}))));

  const Impact ee = collide::edge_edge_ccd(q);
  check(ee, test::exact_edge_edge_time(q));
  FUZZ_CHECK(same(ee, collide::edge_edge_ccd(permuted(q, {2, 3, 0, 1}))));
  FUZZ_CHECK(same(ee, collide::edge_edge_ccd(permuted(q, {1, 0, 2, 3}))));
  FUZZ_CHECK(same(ee, collide::edge_edge_ccd(permuted(q, {0, 1, 3, 2}))));
  return 0;
}
