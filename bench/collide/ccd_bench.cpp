// Continuous collision of primitives: contain's exact vertex-face and edge-edge queries beside
// Tight Inclusion (Wang et al. 2021; conservative, tolerance 1e-6, the settings of its own
// benchmark: err = {-1, -1, -1}, minimum separation 0, t_max 1, 10^6 iterations) on the same
// queries in one run, one thread: time per query and the contacts each reports where there is
// none (false) or misses. Query sets: every scene of ../shared/corpus/ccd (expected answers in
// the files) and generic random queries (expected answer: contain's exact one, which the test
// suite checks against the GMP oracle). Times are medians of 5 runs over the whole set (Tight
// Inclusion: 1 run), in thread CPU time.
//
// Moving meshes: two tori of 100,000 triangles each, B sweeping past and through A along 24
// straight paths; the build, the time per motion (median) and the discrete MeshPair test of the
// start pose beside it, and FCL 0.7's continuous collision of the same meshes and motions
// (translations: every FCL solver for meshes takes them): sampling (CCDC_NAIVE, its default 10
// poses), conservative advancement on BVHModel<OBBRSS> and the polynomial solver on
// BVHModel<AABB>, each with its time per motion and its answers against contain's exact ones.
//
// Usage: ccd_bench [--quick]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "contain/collide/ccd.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/moving_mesh_pair.h"
#include "contain/io/ccd_queries.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_TIGHT_INCLUSION
#include <tight_inclusion/ccd.hpp>
#endif
#ifdef CONTAIN_BENCH_HAS_FCL
#include "fcl_mesh.h"
#endif

using namespace contain;
using collide::CcdQuery;

namespace {

struct QuerySet {
  std::string name;
  bool vertex_face = true;
  std::vector<CcdQuery> queries;
  std::vector<std::int8_t> expected;  // 1 contact, 0 none
};

// The calling thread's CPU time: the machine is shared, so wall-clock time would count other
// processes' turns; contain and Tight Inclusion are both measured this way, on one thread.
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

template <class F>
double median_seconds(int runs, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const double s = thread_seconds();
    f();
    t.push_back(thread_seconds() - s);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::vector<QuerySet> corpus_sets() {
  std::vector<QuerySet> sets;
  const std::filesystem::path root = std::filesystem::path(CONTAIN_SHARED_DIR) / "corpus/ccd";
  if (!std::filesystem::is_directory(root)) {
    std::printf("../shared/corpus/ccd is absent: corpus sets skipped\n");
    return sets;
  }
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::directory_iterator(root))
    if (e.is_directory()) scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  for (const auto& scene : scenes) {
    for (const char* kind : {"vertex-face", "edge-edge"}) {
      QuerySet set{
          scene.filename().string() + " " + kind, std::strcmp(kind, "vertex-face") == 0, {}, {}};
      std::vector<std::filesystem::path> files;
      for (const auto& f : std::filesystem::directory_iterator(scene / kind))
        files.push_back(f.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) {
        auto q = io::read_ccd_queries(f);
        if (!q) {
          std::printf("%s\n", q.error().what().c_str());
          continue;
        }
        set.queries.insert(set.queries.end(), q->queries.begin(), q->queries.end());
        set.expected.insert(set.expected.end(), q->expected.begin(), q->expected.end());
      }
      sets.push_back(std::move(set));
    }
  }
  return sets;
}

// Generic queries: all eight points independent and uniform in the unit cube (the primitives'
// boxes overlap most of the time and the cubic has roots in [0, 1] in about half of the
// queries), and small primitives (size 0.1) moving by up to 0.3 in a unit cube.
std::vector<QuerySet> random_sets(std::size_t n) {
  std::vector<QuerySet> sets;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-0.05, 0.05), m(-0.15, 0.15);
  for (const bool vf : {true, false}) {
    QuerySet dense{
        std::string("random-unit-cube ") + (vf ? "vertex-face" : "edge-edge"), vf, {}, {}};
    QuerySet small{
        std::string("random-small-moving ") + (vf ? "vertex-face" : "edge-edge"), vf, {}, {}};
    for (std::size_t i = 0; i < n; ++i) {
      CcdQuery q;
      for (Vec3& p : q)
        p = {u(rng), u(rng), u(rng)};
      dense.queries.push_back(q);
      // Two primitives of size ~0.1 near random centres, each translated by its own motion.
      const Vec3 c1{u(rng), u(rng), u(rng)};
      const Vec3 c2 = c1 + Vec3{3 * s(rng), 3 * s(rng), 3 * s(rng)};
      const Vec3 m1{m(rng), m(rng), m(rng)}, m2{m(rng), m(rng), m(rng)};
      const int first_of_b = vf ? 1 : 2;
      for (int k = 0; k < 4; ++k) {
        const Vec3 c = k < first_of_b ? c1 : c2;
        const Vec3 mv = k < first_of_b ? m1 : m2;
        const Vec3 p = c + Vec3{s(rng), s(rng), s(rng)};
        q[static_cast<std::size_t>(k)] = p;
        q[static_cast<std::size_t>(k + 4)] =
            p + mv + Vec3{0.1 * s(rng), 0.1 * s(rng), 0.1 * s(rng)};
      }
      small.queries.push_back(q);
    }
    sets.push_back(std::move(dense));
    sets.push_back(std::move(small));
  }
  for (QuerySet& set : sets) {
    for (const CcdQuery& q : set.queries) {
      const bool hit =
          set.vertex_face ? collide::vertex_face_ccd(q).hit : collide::edge_edge_ccd(q).hit;
      set.expected.push_back(hit ? 1 : 0);
    }
  }
  return sets;
}

struct Row {
  double seconds = 0;
  int hits = 0, false_hits = 0, missed = 0;
};

template <class Method>
Row measure(const QuerySet& set, Method&& method, int runs) {
  Row row;
  std::vector<char> answers(set.queries.size());
  row.seconds = median_seconds(runs, [&] {
    for (std::size_t i = 0; i < set.queries.size(); ++i)
      answers[i] = method(set.queries[i]) ? 1 : 0;
  });
  for (std::size_t i = 0; i < set.queries.size(); ++i) {
    row.hits += answers[i];
    if (answers[i] && set.expected[i] != 1) ++row.false_hits;
    if (!answers[i] && set.expected[i] == 1) ++row.missed;
  }
  return row;
}

#ifdef CONTAIN_BENCH_HAS_TIGHT_INCLUSION
bool tight_inclusion(const CcdQuery& q, bool vertex_face) {
  ticcd::Vector3 p[8];
  for (int i = 0; i < 8; ++i)
    p[i] = {q[static_cast<std::size_t>(i)].x, q[static_cast<std::size_t>(i)].y,
            q[static_cast<std::size_t>(i)].z};
  double toi = 0, output_tolerance = 0;
  const ticcd::Array3 err(-1, -1, -1);
  if (vertex_face) {
    return ticcd::vertexFaceCCD(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], err, 0.0, toi, 1e-6,
                                1.0, 1000000, output_tolerance);
  }
  return ticcd::edgeEdgeCCD(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], err, 0.0, toi, 1e-6,
                            1.0, 1000000, output_tolerance);
}
#endif

#ifdef CONTAIN_BENCH_HAS_FCL
using bench::fcl_model;

fcl::Transform3d fcl_translation(const Vec3& t) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.translation() = fcl::Vector3d(t.x, t.y, t.z);
  return tf;
}

// FCL's answers beside contain's exact ones: per motion its time, whether it reports a contact,
// and its time of contact; 'missed' and 'false' count motions where FCL's hit differs from the
// exact one, 'late' hits whose time is after the exact first contact (a simulation advancing to
// it passes through), 'max |dt|' the largest time difference on common hits.
void fcl_report(const char* name, const std::vector<double>& ms,
                const std::vector<std::pair<bool, double>>& answers,
                const std::vector<collide::MeshImpact>& exact, double build_ms) {
  int hits = 0, missed = 0, false_hits = 0, late = 0;
  double max_dt = 0.0;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const auto [hit, toc] = answers[i];
    hits += hit ? 1 : 0;
    missed += (exact[i].hit && !hit) ? 1 : 0;
    false_hits += (!exact[i].hit && hit) ? 1 : 0;
    if (hit && exact[i].hit) {
      late += toc > exact[i].time ? 1 : 0;
      max_dt = std::max(max_dt, std::abs(toc - exact[i].time));
    }
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  std::printf(
      "  %-40s build %7.1f ms; per motion median %9.2f ms, max %9.2f ms; %2d hit, %d missed, %d "
      "false, %d late, max |dt| %.2g\n",
      name, build_ms, sorted[sorted.size() / 2], sorted.back(), hits, missed, false_hits, late,
      max_dt);
  std::fflush(stdout);
}

// One call of fcl::continuousCollide, B translated from m.from to m.to (A at rest), timed; the
// request keeps FCL's defaults (10 iterations, toc_err 1e-4) but for the motion and the solver.
template <class Model>
std::pair<bool, double> fcl_first_contact(const Model& a, const Model& b, const collide::Motion& m,
                                          fcl::CCDSolverType solver, std::vector<double>& ms) {
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  fcl::ContinuousCollisionRequestd request;
  request.ccd_motion_type = fcl::CCDM_TRANS;
  request.ccd_solver_type = solver;
  fcl::ContinuousCollisionResultd result;
  const double s = thread_seconds();
  fcl::continuousCollide(a.get(), identity, identity, b.get(), fcl_translation(m.from.t),
                         fcl_translation(m.to.t), request, result);
  ms.push_back(1e3 * (thread_seconds() - s));
  return {result.is_collide, result.time_of_contact};
}

void fcl_moving_meshes(const Mesh& a, const Mesh& b, const std::vector<collide::Motion>& motions,
                       const std::vector<collide::MeshImpact>& exact) {
  std::printf("  FCL 0.7 continuous collision of the same meshes and motions (CCDM_TRANS):\n");
  double s0 = thread_seconds();
  auto oa = fcl_model<fcl::OBBRSSd>(a), ob = fcl_model<fcl::OBBRSSd>(b);
  const double obbrss_build_ms = 1e3 * (thread_seconds() - s0);
  for (const fcl::CCDSolverType solver : {fcl::CCDC_NAIVE, fcl::CCDC_CONSERVATIVE_ADVANCEMENT}) {
    std::vector<double> ms;
    std::vector<std::pair<bool, double>> answers;
    for (const collide::Motion& m : motions)
      answers.push_back(fcl_first_contact(oa, ob, m, solver, ms));
    fcl_report(solver == fcl::CCDC_NAIVE ? "naive (10 sampled poses), OBBRSS"
                                         : "conservative advancement, OBBRSS",
               ms, answers, exact, obbrss_build_ms);
  }
  // The polynomial solver moves the models' vertices in place (it const_casts them), so each
  // motion gets fresh models, built outside the timed call.
  std::vector<double> ms;
  std::vector<std::pair<bool, double>> answers;
  double aabb_build_ms = 0.0;
  for (const collide::Motion& m : motions) {
    s0 = thread_seconds();
    auto pa = fcl_model<fcl::AABBd>(a), pb = fcl_model<fcl::AABBd>(b);
    aabb_build_ms = 1e3 * (thread_seconds() - s0);
    answers.push_back(fcl_first_contact(pa, pb, m, fcl::CCDC_POLYNOMIAL_SOLVER, ms));
  }
  fcl_report("polynomial solver, AABB (fresh models)", ms, answers, exact, aabb_build_ms);
}
#endif

}  // namespace

void moving_meshes(bool quick) {
  const int n = quick ? 50 : 250;  // rings; sides = 200: 2 * n * 200 triangles
  const Mesh a = scenes::torus(2.0, 0.6, n, 200);
  Mesh b = scenes::torus(0.8, 0.25, n, 200);
  std::vector<collide::Motion> motions;
  for (int i = 0; i < 24; ++i) {
    // B (lying in the plane z = 0 around the z axis) moves along x from -6 to +6 at a height
    // and sideways offset that varies: most paths run into A's tube; those at height 0.9 pass
    // over it (B's tube reaches down to 0.65, A's up to 0.6) and miss.
    const double y = -3.0 + 0.25 * i, z = 0.3 * (i % 4);
    collide::Motion m;
    m.from.t = {-6.0, y, z};
    m.to.t = {6.0, y, z};
    motions.push_back(m);
  }
  const double s0 = thread_seconds();
  const collide::MovingMeshPair pair(a, b);
  const double build_ms = 1e3 * (thread_seconds() - s0);
  const collide::MeshPair discrete(a, b);
  std::vector<double> ccd_ms, discrete_ms, discrete_mid_ms;
  int hits = 0;
  std::size_t node_pairs = 0, tests = 0;
  for (const collide::Motion& m : motions) {
    collide::MeshImpact impact;
    ccd_ms.push_back(1e3 * median_seconds(3, [&] { impact = pair.first_contact(m); }));
    hits += impact.hit ? 1 : 0;
    node_pairs += impact.node_pairs;
    tests += impact.primitive_tests;
    discrete_ms.push_back(1e3 * median_seconds(3, [&] { (void)discrete.collide(m.from); }));
    // The pose halfway, where the shapes overlap or nearly touch: the discrete test's hard case.
    Transform mid = m.from;
    mid.t = 0.5 * (m.from.t + m.to.t);
    discrete_mid_ms.push_back(1e3 * median_seconds(3, [&] { (void)discrete.collide(mid); }));
  }
  std::vector<collide::MeshImpact> exact;
  for (const collide::Motion& m : motions)
    exact.push_back(pair.first_contact(m));
  std::sort(ccd_ms.begin(), ccd_ms.end());
  std::sort(discrete_ms.begin(), discrete_ms.end());
  std::sort(discrete_mid_ms.begin(), discrete_mid_ms.end());
  std::printf(
      "\nmoving meshes: torus %zu x torus %zu triangles, %zu straight motions of B, %d hit\n"
      "  MovingMeshPair build %.1f ms; first_contact per motion: median %.2f ms, max %.2f ms "
      "(%zu box pairs, %zu primitive tests in all)\n"
      "  discrete MeshPair::collide: start pose median %.3f ms, max %.3f ms; pose at t = 1/2 "
      "median %.3f ms, max %.3f ms\n",
      a.triangles.size(), b.triangles.size(), motions.size(), hits, build_ms,
      ccd_ms[ccd_ms.size() / 2], ccd_ms.back(), node_pairs, tests,
      discrete_ms[discrete_ms.size() / 2], discrete_ms.back(),
      discrete_mid_ms[discrete_mid_ms.size() / 2], discrete_mid_ms.back());
#ifdef CONTAIN_BENCH_HAS_FCL
  fcl_moving_meshes(a, b, motions, exact);
#else
  std::printf("  FCL not found: its continuous collision is not measured\n");
#endif
}

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int runs = quick ? 1 : 5;
  std::vector<QuerySet> sets = corpus_sets();
  for (QuerySet& s : random_sets(quick ? 10000 : 100000))
    sets.push_back(std::move(s));
#ifndef CONTAIN_BENCH_HAS_TIGHT_INCLUSION
  std::printf(
      "Tight Inclusion not built in (configure with -DCONTAIN_TIGHT_INCLUSION_DIR=<folder of "
      "libtight_inclusion.a from ../shared/peers/tight-inclusion/build.sh>): its columns are "
      "empty\n");
#endif
  std::printf("%-44s %7s %5s | %10s %6s %6s | %10s %6s %6s %6s | %7s\n", "query set", "queries",
              "hits", "contain us", "false", "missed", "TI us", "false", "missed", "hits",
              "TI/cont");
  for (const QuerySet& set : sets) {
    const bool vf = set.vertex_face;
    const Row c = measure(
        set,
        [vf](const CcdQuery& q) {
          return vf ? collide::vertex_face_ccd(q).hit : collide::edge_edge_ccd(q).hit;
        },
        runs);
    const double n = static_cast<double>(set.queries.size());
    const int expected_hits =
        static_cast<int>(std::count(set.expected.begin(), set.expected.end(), 1));
#ifdef CONTAIN_BENCH_HAS_TIGHT_INCLUSION
    // Tight Inclusion takes up to seconds per query on some degenerate sets: fewer runs there.
    const Row t = measure(
        set, [vf](const CcdQuery& q) { return tight_inclusion(q, vf); }, 1);
    std::printf("%-44s %7zu %5d | %10.3f %6d %6d | %10.3f %6d %6d %6d | %7.2f\n", set.name.c_str(),
                set.queries.size(), expected_hits, 1e6 * c.seconds / n, c.false_hits, c.missed,
                1e6 * t.seconds / n, t.false_hits, t.missed, t.hits, t.seconds / c.seconds);
#else
    std::printf("%-44s %7zu %5d | %10.3f %6d %6d |\n", set.name.c_str(), set.queries.size(),
                expected_hits, 1e6 * c.seconds / n, c.false_hits, c.missed);
#endif
    std::fflush(stdout);
  }
  // Which stage decided the queries of each set (contain).
  std::printf("\n%-44s %8s %8s %8s %8s\n", "stage that decided (contain)", "boxes", "cubic",
              "filter", "exact");
  for (const QuerySet& set : sets) {
    int count[4] = {0, 0, 0, 0};
    for (const CcdQuery& q : set.queries) {
      const collide::Impact i =
          set.vertex_face ? collide::vertex_face_ccd(q) : collide::edge_edge_ccd(q);
      ++count[static_cast<int>(i.stage)];
    }
    std::printf("%-44s %8d %8d %8d %8d\n", set.name.c_str(), count[0], count[1], count[2],
                count[3]);
  }
  moving_meshes(quick);
  return 0;
}
