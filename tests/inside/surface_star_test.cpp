// A point on the surface of a closed mesh read from the star of triangles through it
// (src/inside/surface_star.cpp), against an exact GMP oracle that samples every open cell of the
// arrangement of the planes through the point at concrete rational offsets: vertices of degree 3
// to 128 (cone apexes, flat fans), pinched vertices (two cones touching at their apex), vertices
// buried in another shell, folded fans (the link runs round twice and crosses itself), points on
// edges shared by 4 to 12 triangles, shells turned inside out. MeshIndex's answers on and off the
// grid, and CsgSolid's (the plane arrangement of csg_local.h) on small stars, must all agree.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "contain/inside/csg.h"
#include "contain/inside/mesh_index.h"
#include "support/exact.h"

namespace contain::inside {
namespace {

using test::exact;
using test::qcross;
using test::qdot;
using test::qsub;
using test::QVec3;
using test::qzero;

mpq_class power_of_two(int k) {  // 2^k, k may be negative
  mpz_class m = 1;
  m <<= static_cast<unsigned>(std::abs(k));
  return k >= 0 ? mpq_class(m) : mpq_class(mpz_class(1), m);
}

QVec3 qadd(const QVec3& a, const QVec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
QVec3 qscale(const mpq_class& s, const QVec3& a) {
  return {s * a.x, s * a.y, s * a.z};
}

// Does the ray from (q.x, q.y + e, q.z + e^2) along +x, e = 2^-400, cross triangle t, and with
// which sign (the triangle's normal along x)? q is rational; for the test meshes (integers below
// 2^10) and samples (offsets down to 2^-270) the concrete e decides as the symbolic rule.
int oracle_crossing(const Triangle3& t, const QVec3& q) {
  // Speed only: q's coordinates differ from the triangle's box bounds by 0 or at least 2^-270,
  // far more than e, so a q outside the box's (y, z) span, or beyond its x, is never crossed.
  const auto below = [](const mpq_class& v, double u, double w, double x) {
    return v < std::min({u, w, x});
  };
  const auto above = [](const mpq_class& v, double u, double w, double x) {
    return v > std::max({u, w, x});
  };
  if (below(q.y, t.a.y, t.b.y, t.c.y) || above(q.y, t.a.y, t.b.y, t.c.y) ||
      below(q.z, t.a.z, t.b.z, t.c.z) || above(q.z, t.a.z, t.b.z, t.c.z) ||
      above(q.x, t.a.x, t.b.x, t.c.x)) {
    return 0;
  }
  const QVec3 a = exact(t.a), b = exact(t.b), c = exact(t.c);
  static const mpq_class e = power_of_two(-400);
  const mpq_class py = q.y + e, pz = q.z + e * e;
  const auto orient = [](const QVec3& u, const QVec3& v, const mpq_class& y,
                         const mpq_class& z) -> mpq_class {
    return (v.y - u.y) * (z - u.z) - (v.z - u.z) * (y - u.y);
  };
  const int s = sgn(orient(a, b, c.y, c.z));
  if (s == 0) return 0;
  if (sgn(orient(a, b, py, pz)) != s || sgn(orient(b, c, py, pz)) != s ||
      sgn(orient(c, a, py, pz)) != s) {
    return 0;
  }
  const QVec3 n = qcross(qsub(b, a), qsub(c, a));
  const mpq_class x = a.x - (n.y * (py - a.y) + n.z * (pz - a.z)) / n.x;
  return x > q.x ? s : 0;
}

int oracle_winding(const Mesh& mesh, const QVec3& q) {
  int w = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    w += oracle_crossing(mesh.triangle(t), q);
  return w;
}

bool on_closed_triangle(const Triangle3& t, const QVec3& p) {
  const QVec3 a = exact(t.a), b = exact(t.b), c = exact(t.c);
  const QVec3 n = qcross(qsub(b, a), qsub(c, a));
  if (qzero(n) || qdot(n, qsub(p, a)) != 0) return false;  // zero-area triangles hold no cell
  return qdot(qcross(qsub(b, a), qsub(p, a)), n) >= 0 &&
         qdot(qcross(qsub(c, b), qsub(p, b)), n) >= 0 &&
         qdot(qcross(qsub(a, c), qsub(p, c)), n) >= 0;
}

// The solid at p: off the surface the sign of the winding number; on it, one sample in every
// open cell of the arrangement of the planes of the triangles through p. Every such cell has on
// its boundary a ray r = +-(n_i x n_j) (or, all planes one, is a half space); around r the planes
// through r are lines in the plane normal to r, and the samples p + t (r + h (+-u + h (+-n))),
// u = r x n along each line, lie in every sector beside each line. With integer coordinates
// below 2^10 (normals below 2^21, r below 2^43, u below 2^64), t = 2^-70 keeps the samples clear
// of every triangle not through p (at least 2^-21 away), h = 2^-100 lets each term dominate the
// next.
Location star_oracle_solid(const Mesh& mesh, Vec3 point) {
  const QVec3 p = exact(point);
  std::vector<QVec3> normals;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    if (!on_closed_triangle(tri, p)) continue;
    const QVec3 a = exact(tri.a);
    const QVec3 n = qcross(qsub(exact(tri.b), a), qsub(exact(tri.c), a));
    // One normal per plane: the samples beside a plane take both of its sides.
    const bool seen = std::any_of(normals.begin(), normals.end(),
                                  [&](const QVec3& m) { return qzero(qcross(m, n)); });
    if (!seen) normals.push_back(n);
  }
  if (normals.empty()) return oracle_winding(mesh, p) > 0 ? Location::inside : Location::outside;
  std::vector<QVec3> rays;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    for (std::size_t j = i + 1; j < normals.size(); ++j) {
      const QVec3 r = qcross(normals[i], normals[j]);
      if (!qzero(r)) rays.push_back(r);
    }
  }
  if (rays.empty()) {  // one plane: any direction in it
    for (const QVec3& axis : {QVec3{1, 0, 0}, QVec3{0, 1, 0}}) {
      const QVec3 r = qcross(normals[0], axis);
      if (!qzero(r)) {
        rays.push_back(r);
        break;
      }
    }
  }
  const mpq_class t = power_of_two(-70), h = power_of_two(-100);
  bool in = false, out = false;
  for (const QVec3& ray : rays) {
    for (const QVec3& r : {ray, qscale(-1, ray)}) {
      for (const QVec3& n : normals) {
        if (qdot(n, r) != 0) continue;
        const QVec3 u = qcross(r, n);
        for (int s = 0; s < 4; ++s) {
          const QVec3 across = qscale(h * (s & 1 ? 1 : -1), n);
          const QVec3 off = qadd(qscale(s & 2 ? 1 : -1, u), across);
          const QVec3 q = qadd(p, qscale(t, qadd(r, qscale(h, off))));
          (oracle_winding(mesh, q) > 0 ? in : out) = true;
          if (in && out) return Location::boundary;
        }
      }
    }
  }
  return in ? Location::inside : Location::outside;
}

// Appends the closed mesh of a cone: apex, the ring (in the order given, which may run round
// more than once: a folded fan) and a base vertex joined to the ring. Outward for a ring
// counter-clockwise seen from +z, the apex above it and the base below; `inverted` flips every
// triangle.
void add_cone(Mesh& m, Vec3 apex, Vec3 base, const std::vector<Vec3>& ring, bool inverted) {
  const auto first = static_cast<std::int32_t>(m.vertices.size());
  m.vertices.push_back(apex);
  m.vertices.push_back(base);
  for (const Vec3& v : ring)
    m.vertices.push_back(v);
  const auto n = static_cast<std::int32_t>(ring.size());
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t a = first + 2 + i, b = first + 2 + (i + 1) % n;
    if (inverted) {
      m.triangles.push_back({first, b, a});
      m.triangles.push_back({first + 1, a, b});
    } else {
      m.triangles.push_back({first, a, b});
      m.triangles.push_back({first + 1, b, a});
    }
  }
}

// k integer points round a circle of radius `radius` in the plane z = `z` about (cx, cy), each
// visited `turns` times as k grows (turns > 1 with k coprime folds the fan into a star).
std::vector<Vec3> ring(int k, double radius, double z, int turns = 1, double cx = 0,
                       double cy = 0) {
  std::vector<Vec3> out;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * 3.141592653589793 * i * turns / k;
    out.push_back(
        {cx + std::round(radius * std::cos(a)), cy + std::round(radius * std::sin(a)), z});
  }
  return out;
}

// The closed box [lo, hi] as 12 triangles (outward unless inverted).
void add_star_box(Mesh& m, Vec3 lo, Vec3 hi, bool inverted) {
  const auto base = static_cast<std::int32_t>(m.vertices.size());
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.push_back(inverted ? TriangleIndices{base + f[0], base + f[2], base + f[1]}
                                   : TriangleIndices{base + f[0], base + f[1], base + f[2]});
  }
}

// MeshIndex with its grid, without one (a single query), and on a coarse grid: one answer.
Location locate_everywhere(const Mesh& mesh, Vec3 p) {
  const Location answer = MeshIndex(mesh).locate(p);
  EXPECT_EQ(MeshIndex(mesh, {.queries = 1}).locate(p), answer);
  EXPECT_EQ(MeshIndex(mesh, {.cells_per_triangle = 0.1, .min_cells = 1, .max_cells = 8}).locate(p),
            answer);
  return answer;
}

std::string where(Vec3 p) {
  return std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z);
}

TEST(SurfaceStar, ConeApexesOfDegree3To128AreBoundaryAloneInsideBuriedAndOutsideInverted) {
  // Checked against the oracle up to degree 12; degrees 64 and 128 took seconds to minutes
  // before the star (the arrangement of their planes, sampled in big numbers).
  for (const int k : {3, 4, 5, 7, 8, 12, 16, 32, 64, 128}) {
    const double radius = k < 16 ? 8 : 300;
    const std::vector<Vec3> r = ring(k, radius, 0);
    Mesh alone, buried, inverted;
    add_cone(alone, {0, 0, 20}, {0, 0, -1}, r, false);
    buried = alone;
    add_star_box(buried, {-2, -2, 18}, {2, 2, 22}, false);  // the apex deep in a box
    add_cone(inverted, {0, 0, 20}, {0, 0, -1}, r, true);
    const std::array<std::pair<const Mesh*, Location>, 3> cases{{{&alone, Location::boundary},
                                                                 {&buried, Location::inside},
                                                                 {&inverted, Location::outside}}};
    for (const auto& [mesh, expected] : cases) {
      const Location got = locate_everywhere(*mesh, {0, 0, 20});
      EXPECT_EQ(got, expected) << "degree " << k;
      if (k <= 12) {  // the oracle's samples grow with the square of the degree
        EXPECT_EQ(got, star_oracle_solid(*mesh, {0, 0, 20})) << "degree " << k;
      }
    }
  }
}

TEST(SurfaceStar, FlatFansOfDegree3To128MatchTheOracleUpToDegree16) {
  // The base vertex: k coplanar triangles round it, on the surface of the cone, buried in a box,
  // or covered by a second, inverted cone on the same base (the two bases cancel: interior).
  for (const int k : {3, 6, 16, 64, 128}) {
    const std::vector<Vec3> r = ring(k, k < 16 ? 8 : 300, 0);
    Mesh alone, buried, cancelled;
    add_cone(alone, {0, 0, 20}, {0, 0, 0}, r, false);
    buried = alone;
    add_star_box(buried, {-2, -2, -2}, {2, 2, 2}, false);
    cancelled = alone;
    std::vector<Vec3> reversed(r.rbegin(), r.rend());
    add_cone(cancelled, {0, 0, -20}, {0, 0, 0}, reversed, false);
    EXPECT_EQ(locate_everywhere(alone, {0, 0, 0}), Location::boundary) << k;
    EXPECT_EQ(locate_everywhere(buried, {0, 0, 0}), Location::inside) << k;
    EXPECT_EQ(locate_everywhere(cancelled, {0, 0, 0}), Location::inside) << k;
    if (k <= 16) {
      for (const Mesh* m : {&alone, &buried, &cancelled})
        EXPECT_EQ(locate_everywhere(*m, {0, 0, 0}), star_oracle_solid(*m, {0, 0, 0})) << k;
    }
  }
}

TEST(SurfaceStar, PinchedApexesOfTwoConesMatchTheOracle) {
  // Two cones touching at their apex: opposite (an hourglass: boundary), nested one in the other
  // (boundary), the inner one inverted (a hollow cone: boundary), the same cone twice with one
  // inverted (nothing: outside), and both inside a box (inside).
  for (const int k : {3, 5, 8, 64}) {
    const std::vector<Vec3> wide = ring(k, 8, 10), narrow = ring(k, 3, 10);
    const std::vector<Vec3> below = ring(k, 8, -10);
    std::vector<Mesh> meshes(5);
    // A cone opening upwards is outward with `inverted` set, one opening downwards without.
    add_cone(meshes[0], {0, 0, 0}, {0, 0, 11}, wide, true);
    add_cone(meshes[0], {0, 0, 0}, {0, 0, -11}, below, false);
    add_cone(meshes[1], {0, 0, 0}, {0, 0, 11}, wide, true);
    add_cone(meshes[1], {0, 0, 0}, {0, 0, 12}, narrow, true);
    add_cone(meshes[2], {0, 0, 0}, {0, 0, 11}, wide, true);
    add_cone(meshes[2], {0, 0, 0}, {0, 0, 11}, narrow, false);
    add_cone(meshes[3], {0, 0, 0}, {0, 0, 11}, wide, true);
    add_cone(meshes[3], {0, 0, 0}, {0, 0, 11}, wide, false);
    meshes[4] = meshes[0];
    add_star_box(meshes[4], {-1, -1, -1}, {1, 1, 1}, false);
    const Location expected[5] = {Location::boundary, Location::boundary, Location::boundary,
                                  Location::outside, Location::inside};
    for (std::size_t i = 0; i < meshes.size(); ++i) {
      const Location got = locate_everywhere(meshes[i], {0, 0, 0});
      EXPECT_EQ(got, expected[i]) << "case " << i << " degree " << k;
      if (k <= 8) {
        EXPECT_EQ(got, star_oracle_solid(meshes[i], {0, 0, 0})) << "case " << i << " " << k;
      }
    }
  }
}

TEST(SurfaceStar, FoldedFansWhoseLinkCrossesItselfMatchTheOracle) {
  // The ring visited two or three times round (a star polygon): winding numbers 0, 1, 2 (3)
  // around the apex; shifted by an inverted shell round the apex, so that only the innermost
  // cell is inside, or none is.
  for (const auto& [k, turns] : std::vector<std::pair<int, int>>{{5, 2}, {7, 2}, {7, 3}, {9, 4}}) {
    const std::vector<Vec3> r = ring(k, 8, 0, turns);
    Mesh star, shifted, deeper;
    add_cone(star, {0, 0, 10}, {0, 0, -1}, r, false);
    shifted = star;
    add_star_box(shifted, {-1, -1, 9}, {1, 1, 11}, true);
    deeper = shifted;
    add_star_box(deeper, {-2, -2, 8}, {2, 2, 12}, true);
    for (const Mesh* m : {&star, &shifted, &deeper}) {
      for (const Vec3 p : {Vec3{0, 0, 10}, Vec3{0, 0, -1}, r[0], r[1]})
        EXPECT_EQ(locate_everywhere(*m, p), star_oracle_solid(*m, p))
            << k << "/" << turns << " " << where(p);
    }
  }
}

TEST(SurfaceStar, EdgesSharedBy4To24TrianglesMatchTheOracle) {
  // Up to 12 tetrahedra round the edge from (0, 0, 0) to (0, 0, 4), two faces each on it, some
  // turned inside out: the edge's midpoint sees half circles only.
  std::mt19937_64 rng(24);
  for (const int k : {2, 3, 4, 6}) {
    for (int trial = 0; trial < 6; ++trial) {
      const std::vector<Vec3> r = ring(2 * k, 8, 0);
      Mesh m;
      for (int i = 0; i < 2 * k; ++i) {
        if (rng() % 3 == 0) continue;
        const auto base = static_cast<std::int32_t>(m.vertices.size());
        m.vertices.insert(m.vertices.end(), {{0, 0, 0},
                                             {0, 0, 4},
                                             r[static_cast<std::size_t>(i)],
                                             r[static_cast<std::size_t>((i + 1) % (2 * k))]});
        const bool flip = rng() % 2 == 0;
        const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        for (const auto& f : faces) {
          const TriangleIndices t{base + f[0], base + f[1], base + f[2]};
          m.triangles.push_back(flip ? TriangleIndices{t[0], t[2], t[1]} : t);
        }
      }
      if (m.triangles.empty()) continue;
      for (const Vec3 p : {Vec3{0, 0, 2}, Vec3{0, 0, 0}, Vec3{0, 0, 4}})
        EXPECT_EQ(locate_everywhere(m, p), star_oracle_solid(m, p))
            << k << " " << trial << " " << where(p);
    }
  }
}

// Random closed meshes of small integer cones and boxes, some inverted, some sharing an apex or
// a vertex position with another shell, and folded rings: every vertex and some edge midpoints
// against the oracle, and against CsgSolid's plane arrangement (the mesh united with itself).
TEST(SurfaceStar, RandomDegenerateStarsMatchTheOracleAndTheCsgSampler) {
  std::mt19937_64 rng(2401);
  std::uniform_int_distribution<int> coord(-4, 4), degree(3, 7), count(1, 3);
  const auto point = [&] {
    return Vec3{static_cast<double>(coord(rng)), static_cast<double>(coord(rng)),
                static_cast<double>(coord(rng))};
  };
  int checked = 0;
  for (int trial = 0; trial < 8; ++trial) {
    Mesh m;
    const Vec3 shared = point();
    for (int s = count(rng); s > 0; --s) {
      std::vector<Vec3> r;
      for (int i = degree(rng); i > 0; --i)
        r.push_back(point());
      add_cone(m, rng() % 2 == 0 ? shared : point(), point(), r, rng() % 3 == 0);
    }
    if (rng() % 2 == 0) {
      const Vec3 lo = point();
      add_star_box(m, lo, {lo.x + 2, lo.y + 2, lo.z + 2}, rng() % 3 == 0);
    }
    const MeshIndex index(m), direct(m, {.queries = 1}),
        coarse(m, {.cells_per_triangle = 0.1, .min_cells = 1, .max_cells = 8});
    if (index.regime() != MeshRegime::closed_exact) continue;
    // The mesh united with itself: two leaves on whose boundary p lies, so that CsgSolid samples
    // the arrangement of their planes (csg_local.h) wherever p is on the surface.
    std::vector<Csg> twice;
    twice.push_back(Csg::leaf(CsgMesh(m)));
    twice.push_back(Csg::leaf(CsgMesh(m)));
    auto solid = CsgSolid::prepare(Csg::unite(std::move(twice)));
    ASSERT_TRUE(solid.ok()) << solid.error().what();
    std::vector<Vec3> probes(m.vertices.begin(), m.vertices.end());
    for (std::size_t t = 0; t < m.triangles.size(); t += 7) {
      const Triangle3 tri = m.triangle(t);
      probes.push_back({(tri.a.x + tri.b.x) / 2, (tri.a.y + tri.b.y) / 2, (tri.a.z + tri.b.z) / 2});
    }
    for (const Vec3 p : probes) {
      const Location got = index.locate(p);
      ASSERT_EQ(direct.locate(p), got) << trial << ": " << where(p);
      ASSERT_EQ(coarse.locate(p), got) << trial << ": " << where(p);
      ASSERT_EQ(got, star_oracle_solid(m, p)) << trial << ": " << where(p);
      ASSERT_EQ(got, solid->locate(p)) << trial << ": " << where(p);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100) << checked;
}

TEST(SurfaceStar, ACsgMeshLeafAtAnApexOfDegree64ReadsTheStarOfItsIndex) {
  // The one leaf on whose boundary p lies decides the tree near p: a boundary of the leaf is one
  // of the tree wherever the tree depends on it (alone, complemented, cut from a box), and a
  // buried apex is inside the leaf, so the tree needs no neighbourhood analysis at all.
  const std::vector<Vec3> r = ring(64, 300, 0);
  Mesh alone, buried;
  add_cone(alone, {0, 0, 20}, {0, 0, -1}, r, false);
  buried = alone;
  add_star_box(buried, {-2, -2, 18}, {2, 2, 22}, false);
  const Box3 around{{-400, -400, -10}, {400, 400, 30}};
  const Vec3 apex{0, 0, 20};
  for (const Mesh* m : {&alone, &buried}) {
    const bool on = m == &alone;
    auto leaf = CsgSolid::prepare(Csg::leaf(CsgMesh(*m)));
    auto outside_it = CsgSolid::prepare(Csg::complement(Csg::leaf(CsgMesh(*m))));
    auto cut = CsgSolid::prepare(Csg::difference(Csg::leaf(around), Csg::leaf(CsgMesh(*m))));
    ASSERT_TRUE(leaf.ok() && outside_it.ok() && cut.ok());
    EXPECT_EQ(leaf->locate(apex), on ? Location::boundary : Location::inside);
    EXPECT_EQ(outside_it->locate(apex), on ? Location::boundary : Location::outside);
    EXPECT_EQ(cut->locate(apex), on ? Location::boundary : Location::outside);
  }
}

}  // namespace
}  // namespace contain::inside
