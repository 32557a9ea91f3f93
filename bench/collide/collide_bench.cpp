// Collision benchmarks, contain and its peers on the same input in one run:
//  1. triangle-triangle in 3D: 10^7 random pairs (vertices uniform in the unit cube):
//     contain exact, a non-robust Guigue-Devillers test (plain double determinants, written
//     here), CGAL do_intersect on Epick triangles (exact predicates);
//  2. mesh against mesh: 1000 random rigid poses of B (rocker-arm, 20k triangles) against A (a
//     torus of 40k triangles, scaled to the same size): contain MeshPair (solid semantics:
//     nesting counts) against FCL 0.7 BVHModel<OBBRSS> (surface contact only, first contact).
//  3. broad phase: pair_search (sweep and prune) on 10^4 boxes against the all-pairs loop.
// Answers are compared outside the timed loops; times are medians of several runs.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "contain/collide/mesh_mesh.h"
#include "contain/collide/pair_search.h"
#include "contain/collide/tri_tri.h"
#include "contain/io/mesh_io.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#endif
#ifdef CONTAIN_BENCH_HAS_FCL
#include "fcl_mesh.h"
#endif

using namespace contain;

namespace {

template <class F>
double median_ms(int runs, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto s = std::chrono::steady_clock::now();
    f();
    t.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// ---- the fastest non-robust reference: Guigue-Devillers with double determinants ----------
double det3(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return dot(cross(b - a, c - a), d - a);
}
int sgn(double v) {
  return (v > 0) - (v < 0);
}

bool gd_float(const Triangle3& A, const Triangle3& B) {
  Vec3 t1[3] = {A.a, A.b, A.c}, t2[3] = {B.a, B.b, B.c};
  int d1[3], d2[3];
  {
    const Vec3 n = cross(t2[1] - t2[0], t2[2] - t2[0]);
    for (int i = 0; i < 3; ++i)
      d1[i] = sgn(dot(n, t1[i] - t2[0]));
  }
  if (d1[0] * d1[1] > 0 && d1[0] * d1[2] > 0) return false;
  {
    const Vec3 n = cross(t1[1] - t1[0], t1[2] - t1[0]);
    for (int i = 0; i < 3; ++i)
      d2[i] = sgn(dot(n, t2[i] - t1[0]));
  }
  if (d2[0] * d2[1] > 0 && d2[0] * d2[2] > 0) return false;
  if ((d1[0] | d1[1] | d1[2]) == 0) return collide::tri_tri(A, B);  // coplanar: rare
  auto canon = [](const int d[3], bool& flip) {
    for (int f = 1; f >= -1; f -= 2)
      for (int k = 0; k < 3; ++k)
        if (f * d[k] > 0 && f * d[(k + 1) % 3] <= 0 && f * d[(k + 2) % 3] <= 0) {
          flip = f < 0;
          return k;
        }
    flip = false;
    return -1;
  };
  bool flip = false;
  int k = canon(d1, flip);
  if (k < 0) return true;  // lone vertex on the plane: counted as touching
  Vec3 p1 = t1[k], q1 = t1[(k + 1) % 3], r1 = t1[(k + 2) % 3];
  if (flip) {
    std::swap(t2[1], t2[2]);
    std::swap(d2[1], d2[2]);
  }
  k = canon(d2, flip);
  if (k < 0) return true;
  const Vec3 p2 = t2[k], q2 = t2[(k + 1) % 3], r2 = t2[(k + 2) % 3];
  if (flip) std::swap(q1, r1);
  return det3(p1, q1, p2, q2) <= 0 && det3(p1, r1, r2, p2) <= 0;
}

void bench_tri_tri() {
  const std::size_t pairs = 1'000'000, reps = 10;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Triangle3> a(pairs), b(pairs);
  auto p = [&] { return Vec3{u(rng), u(rng), u(rng)}; };
  for (std::size_t i = 0; i < pairs; ++i) {
    a[i] = {p(), p(), p()};
    b[i] = {p(), p(), p()};
  }
  std::vector<unsigned char> r_contain(pairs), r_gd(pairs), r_cgal(pairs);
  std::printf("triangle-triangle 3D: %zu pairs (%zu distinct, vertices uniform in [0,1]^3)\n",
              pairs * reps, pairs);
  const double t_contain = median_ms(5, [&] {
    for (std::size_t r = 0; r < reps; ++r)
      for (std::size_t i = 0; i < pairs; ++i)
        r_contain[i] = collide::tri_tri(a[i], b[i]);
  });
  const double t_gd = median_ms(5, [&] {
    for (std::size_t r = 0; r < reps; ++r)
      for (std::size_t i = 0; i < pairs; ++i)
        r_gd[i] = gd_float(a[i], b[i]);
  });
  std::size_t hits = 0, gd_wrong = 0;
  for (std::size_t i = 0; i < pairs; ++i) {
    hits += r_contain[i];
    gd_wrong += r_contain[i] != r_gd[i];
  }
  const double n = double(pairs * reps);
  std::printf("  %-38s %8.1f ms  %6.1f M pairs/s  x %.2f\n", "contain exact (orient3d)", t_contain,
              n / t_contain / 1e3, 1.0);
  std::printf("  %-38s %8.1f ms  %6.1f M pairs/s  x %.2f  (answers differing: %zu)\n",
              "non-robust Guigue-Devillers (double)", t_gd, n / t_gd / 1e3, t_gd / t_contain,
              gd_wrong);
#ifdef CONTAIN_BENCH_HAS_CGAL
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Triangle_3> ca(pairs), cb(pairs);
  auto cp = [](Vec3 v) { return K::Point_3(v.x, v.y, v.z); };
  for (std::size_t i = 0; i < pairs; ++i) {
    ca[i] = K::Triangle_3(cp(a[i].a), cp(a[i].b), cp(a[i].c));
    cb[i] = K::Triangle_3(cp(b[i].a), cp(b[i].b), cp(b[i].c));
  }
  const double t_cgal = median_ms(3, [&] {
    for (std::size_t r = 0; r < reps; ++r)
      for (std::size_t i = 0; i < pairs; ++i)
        r_cgal[i] = CGAL::do_intersect(ca[i], cb[i]);
  });
  std::size_t cgal_wrong = 0;
  for (std::size_t i = 0; i < pairs; ++i)
    cgal_wrong += r_contain[i] != r_cgal[i];
  std::printf("  %-38s %8.1f ms  %6.1f M pairs/s  x %.2f  (answers differing: %zu)\n",
              "CGAL do_intersect (Epick)", t_cgal, n / t_cgal / 1e3, t_cgal / t_contain,
              cgal_wrong);
#endif
  std::printf("  intersecting pairs: %.1f%%\n", 100.0 * double(hits) / double(pairs));
}

Transform random_pose(std::mt19937_64& rng, double spread, Vec3 centre) {
  std::normal_distribution<double> g(0.0, 1.0);
  double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  const double len = std::sqrt(w * w + x * x + y * y + z * z);
  w /= len, x /= len, y /= len, z /= len;
  Transform t;
  t.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
  // Rotate B about its own centre, then move it by a random offset.
  std::uniform_real_distribution<double> u(-spread, spread);
  const Vec3 rc{t.r[0][0] * centre.x + t.r[0][1] * centre.y + t.r[0][2] * centre.z,
                t.r[1][0] * centre.x + t.r[1][1] * centre.y + t.r[1][2] * centre.z,
                t.r[2][0] * centre.x + t.r[2][1] * centre.y + t.r[2][2] * centre.z};
  t.t = Vec3{u(rng), u(rng), u(rng)} - rc;
  return t;
}

void bench_mesh_mesh() {
  auto file = io::read_mesh(CONTAIN_SHARED_DIR "/corpus/meshes/rocker-arm.obj");
  if (!file) {
    std::printf("rocker-arm.obj not found: mesh benchmark skipped\n");
    return;
  }
  Mesh b = file->mesh;
  Box3 bb;
  for (const Vec3& v : b.vertices)
    bb.expand(v);
  const Vec3 centre = 0.5 * (bb.min + bb.max);
  const double size = length(bb.max - bb.min);
  // A: a torus of 40,000 triangles, about as large as B.
  const Mesh a = scenes::torus(0.35 * size, 0.12 * size, 200, 100);
  const std::size_t poses_n = 1000;
  std::mt19937_64 rng(7);
  std::vector<Transform> poses;
  for (std::size_t i = 0; i < poses_n; ++i)
    poses.push_back(random_pose(rng, 0.6 * size, centre));
  std::printf(
      "\nmesh-mesh: A torus %zu triangles, B rocker-arm %zu triangles, %zu random rigid "
      "poses of B (translation uniform in [-0.6, 0.6] x B's diagonal)\n",
      a.triangles.size(), b.triangles.size(), poses_n);
  std::vector<collide::Contact> out(poses_n);
  const auto s0 = std::chrono::steady_clock::now();
  const collide::MeshPair pair(a, b);
  const double build =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s0).count();
  const double t_contain = median_ms(7, [&] { pair.collide(poses, out, {.threads = 1}); });
  std::size_t hits = 0, nested = 0;
  for (const auto& c : out) {
    hits += c.intersect;
    nested += c.intersect && c.witness != inside::PairWitness::triangles;
  }
  std::printf(
      "  %-38s %8.2f ms  (%.2f us/pose; build %.1f ms)  x 1.00  intersect %zu (nested %zu)\n",
      "contain MeshPair (exact, solids)", t_contain, 1e3 * t_contain / double(poses_n), build, hits,
      nested);
#ifdef CONTAIN_BENCH_HAS_FCL
  auto model = [](const Mesh& m) { return bench::fcl_model<fcl::OBBRSSd>(m); };
  const auto s1 = std::chrono::steady_clock::now();
  auto ma = model(a), mb = model(b);
  const double fbuild =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s1).count();
  std::vector<fcl::Transform3d> ftf(poses_n);
  for (std::size_t i = 0; i < poses_n; ++i) {
    fcl::Matrix3d r;
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y)
        r(x, y) = poses[i].r[std::size_t(x)][std::size_t(y)];
    ftf[i].setIdentity();
    ftf[i].linear() = r;
    ftf[i].translation() = fcl::Vector3d(poses[i].t.x, poses[i].t.y, poses[i].t.z);
  }
  std::vector<unsigned char> fr(poses_n);
  const double t_fcl = median_ms(7, [&] {
    fcl::CollisionObjectd oa(ma, fcl::Transform3d::Identity());
    for (std::size_t i = 0; i < poses_n; ++i) {
      fcl::CollisionObjectd ob(mb, ftf[i]);
      fcl::CollisionRequestd req;
      fcl::CollisionResultd res;
      fcl::collide(&oa, &ob, req, res);
      fr[i] = res.isCollision();
    }
  });
  std::size_t fhits = 0, surface_disagree = 0;
  for (std::size_t i = 0; i < poses_n; ++i) {
    fhits += fr[i];
    const bool surface = out[i].intersect && out[i].witness == inside::PairWitness::triangles;
    surface_disagree += surface != bool(fr[i]);
  }
  std::printf(
      "  %-38s %8.2f ms  (%.2f us/pose; build %.1f ms)  x %.2f  intersect %zu "
      "(surface answers differing from contain: %zu)\n",
      "FCL 0.7 BVHModel<OBBRSS> (surface)", t_fcl, 1e3 * t_fcl / double(poses_n), fbuild,
      t_fcl / t_contain, fhits, surface_disagree);
#endif
}

}  // namespace

// Broad phase: 10^4 boxes, centres uniform in the unit cube, half-sizes uniform in [0, 0.01];
// sweep and prune against the all-pairs loop (answers compared).
void bench_pair_search() {
  const std::size_t n = 10'000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), h(0.0, 0.01);
  std::vector<Box3> boxes(n);
  for (Box3& b : boxes) {
    const Vec3 c{u(rng), u(rng), u(rng)}, e{h(rng), h(rng), h(rng)};
    b = {c - e, c + e};
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> got, want;
  const double t_sap = median_ms(7, [&] { got = collide::pair_search(boxes); });
  const double t_brute = median_ms(3, [&] {
    want.clear();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (boxes[i].overlaps(boxes[j]))
          want.emplace_back(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
  });
  std::printf(
      "\nbroad phase: %zu boxes (centres uniform in [0,1]^3, half-sizes uniform in [0, 0.01])\n",
      n);
  std::printf("  %-38s %8.2f ms  pairs %zu  x %.2f\n", "contain pair_search (sweep and prune)",
              t_sap, got.size(), 1.0);
  std::printf("  %-38s %8.2f ms  pairs %zu  x %.1f  (same pairs: %s)\n",
              "all pairs (n^2/2 box tests)", t_brute, want.size(), t_brute / t_sap,
              got == want ? "yes" : "NO");
}

int main() {
  bench_tri_tri();
  bench_mesh_mesh();
  bench_pair_search();
  return 0;
}
