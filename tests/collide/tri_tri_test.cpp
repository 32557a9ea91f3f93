#include "contain/collide/tri_tri.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contain/collide/tri_tri_2d.h"
#include "support/tri_tri_oracle.h"

namespace contain::collide {
namespace {

using test::exact_tri_tri_3d;

// Every relabelling (6 permutations of each triangle) and the swap of a and b give one answer.
void expect_matches_oracle(const Triangle3& a, const Triangle3& b) {
  const bool truth = exact_tri_tri_3d(a, b);
  const Vec3 pa[3] = {a.a, a.b, a.c}, pb[3] = {b.a, b.b, b.c};
  static constexpr int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                     {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& i : perm) {
    for (const auto& j : perm) {
      const Triangle3 x{pa[i[0]], pa[i[1]], pa[i[2]]}, y{pb[j[0]], pb[j[1]], pb[j[2]]};
      ASSERT_EQ(tri_tri(x, y), truth)
          << "a=" << a.a.x << "," << a.a.y << "," << a.a.z << " " << a.b.x << "," << a.b.y << ","
          << a.b.z << " " << a.c.x << "," << a.c.y << "," << a.c.z << " b=" << b.a.x << "," << b.a.y
          << "," << b.a.z << " " << b.b.x << "," << b.b.y << "," << b.b.z << " " << b.c.x << ","
          << b.c.y << "," << b.c.z;
      ASSERT_EQ(tri_tri(y, x), truth);
    }
  }
}

Vec3 random_point(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {u(rng), u(rng), u(rng)};
}

Vec3 grid_point(std::mt19937_64& rng, int n) {
  std::uniform_int_distribution<int> u(-n, n);
  return {double(u(rng)), double(u(rng)), double(u(rng))};
}

TEST(TriTri3, RandomFloatPairsMatchExactOracle) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 1500; ++i) {
    expect_matches_oracle(
        {random_point(rng, -1, 1), random_point(rng, -1, 1), random_point(rng, -1, 1)},
        {random_point(rng, -1, 1), random_point(rng, -1, 1), random_point(rng, -1, 1)});
  }
}

TEST(TriTri3, IntegerGridPairsWithEveryDegeneracyMatchExactOracle) {
  // Coordinates in {-1, 0, 1}: shared vertices and edges, vertices on edges and faces, coplanar
  // and collinear triples, degenerate triangles, all very common.
  std::mt19937_64 rng(2);
  for (int i = 0; i < 8000; ++i) {
    expect_matches_oracle({grid_point(rng, 1), grid_point(rng, 1), grid_point(rng, 1)},
                          {grid_point(rng, 1), grid_point(rng, 1), grid_point(rng, 1)});
  }
}

TEST(TriTri3, CoplanarTrianglesInATiltedLatticePlaneMatchExactOracle) {
  // Points (u, v, u + 2v) with small integers: every triangle lies in the plane z = x + 2y.
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> u(-3, 3);
  auto p = [&] {
    const double x = u(rng), y = u(rng);
    return Vec3{x, y, x + 2 * y};
  };
  for (int i = 0; i < 5000; ++i)
    expect_matches_oracle({p(), p(), p()}, {p(), p(), p()});
}

TEST(TriTri3, SharedVertexAndSharedEdgeIntersect) {
  std::mt19937_64 rng(4);
  for (int i = 0; i < 500; ++i) {
    const Vec3 a = random_point(rng, -1, 1), b = random_point(rng, -1, 1),
               c = random_point(rng, -1, 1), d = random_point(rng, -1, 1),
               e = random_point(rng, -1, 1);
    EXPECT_TRUE(tri_tri({a, b, c}, {a, d, e}));
    EXPECT_TRUE(tri_tri({a, b, c}, {b, a, d}));
    expect_matches_oracle({a, b, c}, {a, d, e});
  }
}

TEST(TriTri3, VertexOnEdgeOrFaceIsExactlyDecided) {
  // Midpoints and quarter points of edges are exact in double for these dyadic coordinates.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> u(-64, 64);
  auto q = [&] { return Vec3{u(rng) / 8.0, u(rng) / 8.0, u(rng) / 8.0}; };
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a = q(), b = q(), c = q(), d = q(), e = q();
    const Vec3 on_edge = 0.5 * (a + b);
    const Vec3 on_face = 0.5 * (0.5 * (a + b) + c);
    EXPECT_TRUE(tri_tri({a, b, c}, {on_edge, d, e}));
    EXPECT_TRUE(tri_tri({a, b, c}, {on_face, d, e}));
    expect_matches_oracle({a, b, c}, {on_edge, d, e});
    expect_matches_oracle({a, b, c}, {on_face, d, e});
  }
}

TEST(TriTri3, EdgeEdgeTouchGapAndTinyPenetrationAreDistinguished) {
  // Two triangles whose edges cross at the origin in perpendicular planes, then moved apart or
  // together by 2^-30.
  const double h = std::ldexp(1.0, -30);
  for (double shift : {0.0, h, -h}) {
    const Triangle3 a{{-1, 0, 0}, {1, 0, 0}, {0, 0, 1}};  // bottom edge along x at z = 0
    const Triangle3 b{{0, -1, shift}, {0, 1, shift}, {0, 0, shift - 1}};  // top edge along y
    const bool truth = shift >= 0.0;
    EXPECT_EQ(tri_tri(a, b), truth) << shift;
    expect_matches_oracle(a, b);
  }
}

TEST(TriTri3, PiercingByTinyAmountsMatchesOracle) {
  std::mt19937_64 rng(6);
  const double h = std::ldexp(1.0, -30);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 a = random_point(rng, -1, 1), b = random_point(rng, -1, 1),
               c = random_point(rng, -1, 1);
    // A vertex of the second triangle at a point of the face, nudged along z by +-2^-30.
    const Vec3 f = (1.0 / 3.0) * (a + b + c);
    const Vec3 d = f + Vec3{0, 0, (i % 2 ? h : -h)};
    expect_matches_oracle({a, b, c}, {d, d + Vec3{0.3, 0.1, 1}, d + Vec3{-0.2, 0.3, 1}});
    expect_matches_oracle({a, b, c}, {d, d + Vec3{0.3, 0.1, -1}, d + Vec3{-0.2, 0.3, 1}});
  }
}

TEST(TriTri3, DegenerateTrianglesAreTheSegmentOrPointTheySpan) {
  const Triangle3 t{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  EXPECT_TRUE(tri_tri(t, {{1, 1, -1}, {1, 1, 1}, {1, 1, 0}}));             // segment through edge
  EXPECT_TRUE(tri_tri(t, {{0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0}}));  // point
  EXPECT_FALSE(tri_tri(t, {{1, 1.5, 0}, {1, 1.5, 0}, {1, 1.5, 0}}));
  EXPECT_TRUE(tri_tri(t, {{-1, 1, 0}, {3, 1, 0}, {1, 1, 0}}));  // coplanar segment
  EXPECT_FALSE(tri_tri(t, {{-1, 3, 0}, {3, 3, 0}, {1, 3, 0}}));
  EXPECT_TRUE(segment_triangle({{0.2, 0.2, 1}, {0.2, 0.2, -1}}, t));
  EXPECT_FALSE(segment_triangle({{0.2, 0.2, 1}, {0.2, 0.2, 0.5}}, t));
  EXPECT_TRUE(segment_triangle({{0.2, 0.2, 1}, {0.2, 0.2, 0}}, t));
}

TEST(TriTri2, RandomAndGridPairsMatchExactOracle) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> g(-2, 2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 10000; ++i) {
    Triangle2 a, b;
    if (i % 2) {
      a = {{double(g(rng)), double(g(rng))},
           {double(g(rng)), double(g(rng))},
           {double(g(rng)), double(g(rng))}};
      b = {{double(g(rng)), double(g(rng))},
           {double(g(rng)), double(g(rng))},
           {double(g(rng)), double(g(rng))}};
    } else {
      a = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
      b = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    }
    const bool truth = test::exact_tri_tri_2d(a, b);
    ASSERT_EQ(tri_tri(a, b), truth) << i;
    ASSERT_EQ(tri_tri(b, a), truth) << i;
    ASSERT_EQ(tri_tri(Triangle2{a.c, a.b, a.a}, b), truth) << i;
  }
}

TEST(TriTri2, StarOfDavidTrianglesIntersectWithNoVertexInsideTheOther) {
  const Triangle2 up{{0, 2}, {-1.7, -1}, {1.7, -1}}, down{{0, -2}, {1.7, 1}, {-1.7, 1}};
  EXPECT_TRUE(tri_tri(up, down));
  EXPECT_TRUE(tri_tri(Triangle2{{0, 0}, {1, 0}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}}));
  EXPECT_FALSE(tri_tri(Triangle2{{0, 0}, {1, 0}, {0, 1}}, {{0.6, 0.6}, {2, 0}, {2, 1}}));
}

}  // namespace
}  // namespace contain::collide
