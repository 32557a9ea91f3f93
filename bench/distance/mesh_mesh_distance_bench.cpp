// Distance between two meshes of ~100k triangles, single-threaded, contain beside FCL 0.7
// (BVHModel<OBBRSS>, fcl::distance) on the same meshes and poses:
//   A  armadillo (../shared/corpus/meshes/armadillo.obj, 86,482 triangles; without ../shared
//      a torus of 100,000 triangles), fixed;
//   B  a torus of 100,000 triangles (major 0.25, minor 0.08 of A's size), placed by 100 random
//      rigid poses around A (separated, touching or crossing: all non-convex pairs);
// then the nested case FCL cannot see: B shrunk into the middle of a closed torus A' of 100,000
// triangles, no surface contact (true distance 0: B lies inside the solid A').
// Times are thread CPU milliseconds of one run over all poses. Answers are compared outside
// the timed loops: FCL's distance against contain's (exact, rounded once) within 1e-9 relative,
// and the poses where FCL reports a positive distance but the solids touch or nest are counted
// as FCL wrong.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "contain/distance/mesh_pair_distance.h"
#include "contain/io/mesh_io.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_FCL
#include <fcl/fcl.h>
#endif

namespace {

using contain::Mesh;
using contain::Transform;
using contain::Vec3;
using contain::distance::PairDistance3;

double thread_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}
double timed_ms(const std::function<void()>& f) {
  const double t0 = thread_ms();
  f();
  return thread_ms() - t0;
}

// "separate n a ms, touching n b ms, nested n c ms": poses of each kind (contain's answer) and
// their mean time.
std::string by_kind(const std::vector<PairDistance3>& answers, const std::vector<double>& ms) {
  using contain::inside::PairWitness;
  std::size_t n[3] = {0, 0, 0};
  double sum[3] = {0, 0, 0};
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const PairWitness c = answers[i].contact;
    const int k = c == PairWitness::none ? 0 : c == PairWitness::triangles ? 1 : 2;
    ++n[k];
    sum[k] += ms[i];
  }
  std::string out;
  const char* names[3] = {"separate", "touching", "nested"};
  for (int k = 0; k < 3; ++k) {
    char part[96];
    std::snprintf(part, sizeof part, "%s%s %zu %.3f ms", k ? ", " : "", names[k], n[k],
                  n[k] ? sum[k] / static_cast<double>(n[k]) : 0.0);
    out += part;
  }
  return out;
}

#ifdef CONTAIN_BENCH_HAS_FCL
std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl_model(const Mesh& m) {
  auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> v;
  std::vector<fcl::Triangle> t;
  for (const Vec3& p : m.vertices)
    v.emplace_back(p.x, p.y, p.z);
  for (const auto& f : m.triangles)
    t.emplace_back(static_cast<std::size_t>(f[0]), static_cast<std::size_t>(f[1]),
                   static_cast<std::size_t>(f[2]));
  bvh->beginModel();
  bvh->addSubModel(v, t);
  bvh->endModel();
  return bvh;
}
fcl::Transform3d fcl_pose(const Transform& p) {
  fcl::Transform3d t;
  t.setIdentity();
  fcl::Matrix3d r;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      r(x, y) = p.r[static_cast<std::size_t>(x)][static_cast<std::size_t>(y)];
  t.linear() = r;
  t.translation() = fcl::Vector3d(p.t.x, p.t.y, p.t.z);
  return t;
}
#endif

void run(const char* name, const Mesh& a, const Mesh& b, const std::vector<Transform>& poses) {
  std::printf("%s: A %zu triangles, B %zu triangles, %zu poses\n", name, a.triangles.size(),
              b.triangles.size(), poses.size());
  std::vector<PairDistance3> ours(poses.size());
  const double build = timed_ms([&] {
    const contain::distance::MeshPairDistance pair(a, b);
    (void)pair;
  });
  const contain::distance::MeshPairDistance pair(a, b);
  // One pose at a time, each timed, so that the time per kind of pose (separate, touching,
  // nested) shows where it goes.
  std::vector<double> ours_ms(poses.size());
  const double query = timed_ms([&] {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const double t0 = thread_ms();
      ours[i] = pair.distance(poses[i]);
      ours_ms[i] = thread_ms() - t0;
    }
  });
  std::size_t node_pairs = 0, contenders = 0;
  for (const PairDistance3& d : ours) {
    node_pairs += d.node_pairs;
    contenders += d.contenders;
  }
  std::printf(
      "  contain MeshPairDistance (exact)      build %8.1f ms  query %8.1f ms  %7.3f ms/pose"
      "  %s; per pose %.0f box pairs, %.1f exact pairs\n",
      build, query, query / static_cast<double>(poses.size()), by_kind(ours, ours_ms).c_str(),
      static_cast<double>(node_pairs) / static_cast<double>(poses.size()),
      static_cast<double>(contenders) / static_cast<double>(poses.size()));
#ifdef CONTAIN_BENCH_HAS_FCL
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> ma, mb;
  const double fbuild = timed_ms([&] {
    ma = fcl_model(a);
    mb = fcl_model(b);
  });
  std::vector<double> theirs(poses.size()), theirs_ms(poses.size());
  const double fquery = timed_ms([&] {
    fcl::CollisionObjectd oa(ma, fcl::Transform3d::Identity());
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const double t0 = thread_ms();
      fcl::CollisionObjectd ob(mb, fcl_pose(poses[i]));
      fcl::DistanceRequestd request;
      fcl::DistanceResultd result;
      fcl::distance(&oa, &ob, request, result);
      theirs[i] = result.min_distance;
      theirs_ms[i] = thread_ms() - t0;
    }
  });
  std::size_t differ = 0, wrong_nested = 0, wrong_touch = 0;
  double worst = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const double want = ours[i].distance;
    const double got = std::max(theirs[i], 0.0);
    const double rel = std::fabs(got - want) / std::max(want, 1e-300);
    if (want > 0) worst = std::max(worst, rel);
    if (want > 0 && rel > 1e-9) ++differ;
    if (want == 0 && got > 0) {
      if (ours[i].contact == contain::inside::PairWitness::triangles)
        ++wrong_touch;
      else
        ++wrong_nested;
    }
  }
  std::printf(
      "  FCL 0.7 BVHModel<OBBRSS> distance     build %8.1f ms  query %8.1f ms  %7.3f ms/pose"
      "  %s; x %.2f; differs (>1e-9 rel) on %zu separated poses (worst %.1e); positive where "
      "touching %zu, where nested %zu\n",
      fbuild, fquery, fquery / static_cast<double>(poses.size()), by_kind(ours, theirs_ms).c_str(),
      fquery / query, differ, worst, wrong_touch, wrong_nested);
#endif
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::stoul(argv[1]) : 100;
  Mesh a;
  std::string name = "armadillo";
  if (auto file = contain::io::read_mesh(CONTAIN_SHARED_DIR "/corpus/meshes/armadillo.obj")) {
    a = std::move(file->mesh);
  } else {
    name = "torus (no ../shared)";
    a = contain::scenes::torus(50.0, 20.0, 500, 100);
  }
  contain::Box3 box;
  for (const Vec3& v : a.vertices)
    box.expand(v);
  const Vec3 size = box.max - box.min;
  const double s = std::max({size.x, size.y, size.z});
  const Vec3 c = 0.5 * (box.min + box.max);
  // A centred at the origin, so that poses around it are symmetric.
  for (Vec3& v : a.vertices)
    v = v - c;
  const Mesh b = contain::scenes::torus(0.25 * s, 0.08 * s, 500, 100);
  const std::vector<Transform> poses = contain::scenes::random_poses(count, 0.8 * s, 11);
  run((name + " and a 100k torus, random rigid poses").c_str(), a, b, poses);

  // Nested: a closed torus A' (100k triangles) with B shrunk inside its tube, no contact.
  const Mesh big = contain::scenes::torus(1.0, 0.4, 500, 100);
  const Mesh small = contain::scenes::torus(0.1, 0.03, 500, 100);
  std::vector<Transform> inside;
  for (std::size_t i = 0; i < std::min<std::size_t>(count, 20); ++i) {
    Transform t;
    const double angle = 6.283185307179586 * static_cast<double>(i) / 20.0;
    t.t = {std::cos(angle), std::sin(angle), 0.0};  // on the tube's centre circle
    inside.push_back(t);
  }
  run("torus 100k inside the tube of a torus 100k (nested, no contact)", big, small, inside);
  return 0;
}
