// Every intersecting pair in a scene of 500 solids, contain and FCL on the same scene in one run:
//   scene: the five closed meshes of ../shared/corpus/meshes (spot, fandisk, rocker-arm,
//   fertility, armadillo; 5,856 to 86,482 triangles), each scaled by a power of two (exact) to a
//   size in [0.5, 1), 500 objects choosing a mesh in turn, under random rotations (uniform
//   quaternions) and translations uniform in a cube of side --side (default 9: about one
//   contact per object).
//   contain: collide::MeshScene (one hierarchy per distinct mesh, sweep and prune over the exact
//   world boxes, the exact MeshPair test per candidate; solid semantics: touching and nesting
//   count), on 1 thread and on all.
//   FCL 0.7: one BVHModel<OBBRSS> per distinct mesh, a CollisionObject per object,
//   DynamicAABBTreeCollisionManager (the broad phase FCL recommends), and fcl::collide with one
//   contact per broad-phase pair (surface contact only: a solid nested in another is not
//   reported).
// Timed: building everything from the meshes in memory, then the query; medians of 5 to 7 runs
// of the thread's CPU time (the machine is shared), and the all-threads query by the wall clock.
// Answers compared outside the timed part: FCL's pairs against contain's pairs whose witness is
// a pair of triangles (surface contact); nested pairs are contain's alone.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "contain/collide/mesh_scene.h"
#include "contain/io/mesh_io.h"

#ifdef CONTAIN_BENCH_HAS_FCL
#include <fcl/fcl.h>
#endif

using namespace contain;

namespace {

// The machine is shared (load 8-10 while these figures were taken): single-threaded work is
// timed by the thread's CPU clock, which preemption does not advance; the multi-threaded run by
// the wall clock.
double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

template <class F>
double median_cpu_ms(int runs, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const double s = thread_cpu_ms();
    f();
    t.push_back(thread_cpu_ms() - s);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

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

// Scales by the power of two that brings the largest extent into [0.5, 1): exact.
Mesh normalised(Mesh mesh) {
  Box3 box;
  for (const Vec3& v : mesh.vertices)
    box.expand(v);
  const double extent =
      std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
  const Vec3 centre{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y),
                    0.5 * (box.min.z + box.max.z)};
  int exponent = 0;
  (void)std::frexp(extent, &exponent);  // extent = m 2^exponent, m in [0.5, 1)
  const double scale = std::ldexp(1.0, -exponent);
  // Centre first (rounded once), then the exact power-of-two scaling.
  const Vec3 shift{std::ldexp(std::round(std::ldexp(centre.x, 20 - exponent)), exponent - 20),
                   std::ldexp(std::round(std::ldexp(centre.y, 20 - exponent)), exponent - 20),
                   std::ldexp(std::round(std::ldexp(centre.z, 20 - exponent)), exponent - 20)};
  for (Vec3& v : mesh.vertices)
    v = {(v.x - shift.x) * scale, (v.y - shift.y) * scale, (v.z - shift.z) * scale};
  return mesh;
}

Transform random_pose(std::mt19937_64& rng, double side) {
  std::normal_distribution<double> n;
  double q[4];
  double norm = 0;
  for (double& c : q) {
    c = n(rng);
    norm += c * c;
  }
  norm = std::sqrt(norm);
  for (double& c : q)
    c /= norm;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Transform t;
  t.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
  std::uniform_real_distribution<double> u(0.0, side);
  t.t = {u(rng), u(rng), u(rng)};
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  double side = 9.0;
  std::size_t objects_n = 500;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--side") == 0) side = std::atof(argv[i + 1]);
    if (std::strcmp(argv[i], "--objects") == 0) objects_n = std::strtoul(argv[i + 1], nullptr, 10);
  }
  const std::filesystem::path corpus = std::filesystem::path(CONTAIN_SHARED_DIR) / "corpus/meshes";
  std::vector<Mesh> meshes;
  std::size_t triangles = 0;
  for (const char* name :
       {"spot.obj", "fandisk.obj", "rocker-arm.obj", "fertility.off", "armadillo.obj"}) {
    auto file = io::read_mesh(corpus / name);
    if (!file) {
      std::printf("scene_bench: %s (../shared/corpus/meshes is needed)\n",
                  file.error().what().c_str());
      return 1;
    }
    meshes.push_back(normalised(std::move(file->mesh)));
  }
  std::mt19937_64 rng(500);
  std::vector<inside::SceneObject> objects;
  for (std::size_t k = 0; k < objects_n; ++k) {
    objects.push_back({static_cast<std::int32_t>(k % meshes.size()), random_pose(rng, side)});
    triangles += meshes[k % meshes.size()].triangles.size();
  }
  std::printf(
      "scene: %zu objects of %zu closed corpus meshes (%zu triangles placed), cube side %g\n",
      objects.size(), meshes.size(), triangles, side);

  // contain
  std::vector<collide::ScenePair> pairs;
  const double build = median_cpu_ms(5, [&] { const collide::MeshScene scene(meshes, objects); });
  const collide::MeshScene scene(meshes, objects);
  const std::size_t candidates = scene.candidates().size();
  const double one = median_cpu_ms(7, [&] { pairs = scene.pairs({.threads = 1}); });
  const double all = median_ms(5, [&] { pairs = scene.pairs({.threads = 0}); });
  std::size_t nested = 0;
  std::set<std::pair<int, int>> surface;
  for (const collide::ScenePair& p : pairs) {
    if (p.contact.witness == inside::PairWitness::triangles) {
      surface.insert({p.a, p.b});
    } else {
      ++nested;
    }
  }
  std::printf(
      "contain MeshScene (CPU time of one thread): build %.1f ms, pairs %.1f ms (%.1f ms build + "
      "query); pairs on %u threads %.1f ms wall; %zu broad-phase candidates, %zu intersecting "
      "pairs (%zu nested, no surface contact)\n",
      build, one, build + one, std::thread::hardware_concurrency(), all, candidates, pairs.size(),
      nested);

#ifdef CONTAIN_BENCH_HAS_FCL
  using Model = fcl::BVHModel<fcl::OBBRSSd>;
  std::vector<std::shared_ptr<Model>> models;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> fcl_objects;
  auto build_fcl = [&] {
    models.clear();
    for (const Mesh& m : meshes) {
      auto bvh = std::make_shared<Model>();
      std::vector<fcl::Vector3d> v;
      std::vector<fcl::Triangle> t;
      for (const Vec3& p : m.vertices)
        v.emplace_back(p.x, p.y, p.z);
      for (const auto& f : m.triangles)
        t.emplace_back(f[0], f[1], f[2]);
      bvh->beginModel();
      bvh->addSubModel(v, t);
      bvh->endModel();
      models.push_back(bvh);
    }
    fcl_objects.clear();
    for (const inside::SceneObject& o : objects) {
      fcl::Transform3d tf;
      tf.setIdentity();
      fcl::Matrix3d r;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
          r(x, y) = o.transform.r[std::size_t(x)][std::size_t(y)];
      tf.linear() = r;
      tf.translation() = fcl::Vector3d(o.transform.t.x, o.transform.t.y, o.transform.t.z);
      auto obj = std::make_unique<fcl::CollisionObjectd>(models[std::size_t(o.mesh)], tf);
      obj->computeAABB();
      fcl_objects.push_back(std::move(obj));
    }
  };
  struct Found {
    std::vector<std::pair<int, int>> pairs;
  };
  Found found;
  double fcl_build = 0, fcl_query = 0;
  {
    fcl_build = median_cpu_ms(5, build_fcl);
    build_fcl();
    for (std::size_t k = 0; k < fcl_objects.size(); ++k)
      fcl_objects[k]->setUserData(reinterpret_cast<void*>(k));
    fcl_query = median_cpu_ms(7, [&] {
      fcl::DynamicAABBTreeCollisionManagerd manager;
      std::vector<fcl::CollisionObjectd*> raw;
      for (auto& o : fcl_objects)
        raw.push_back(o.get());
      manager.registerObjects(raw);
      manager.setup();
      found.pairs.clear();
      manager.collide(&found, [](fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
        auto* f = static_cast<Found*>(data);
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        fcl::collide(a, b, request, result);
        if (result.isCollision()) {
          const int i = int(reinterpret_cast<std::size_t>(a->getUserData()));
          const int j = int(reinterpret_cast<std::size_t>(b->getUserData()));
          f->pairs.emplace_back(std::min(i, j), std::max(i, j));
        }
        return false;  // keep going: every pair
      });
    });
  }
  std::set<std::pair<int, int>> fcl_pairs(found.pairs.begin(), found.pairs.end());
  std::size_t only_fcl = 0, only_contain = 0;
  for (const auto& p : fcl_pairs)
    only_fcl += surface.count(p) == 0;
  for (const auto& p : surface)
    only_contain += fcl_pairs.count(p) == 0;
  std::printf(
      "FCL 0.7 DynamicAABBTree + BVHModel<OBBRSS> (CPU time of one thread): build %.1f ms, broad "
      "phase and pairs %.1f ms (%.1f ms build + query); %zu intersecting pairs (surface contact "
      "only)\n",
      fcl_build, fcl_query, fcl_build + fcl_query, fcl_pairs.size());
  std::printf(
      "ratio FCL / contain (1 thread): query %.2fx, build + query %.2fx; surface pairs found by "
      "FCL only: %zu, by contain only: %zu\n",
      fcl_query / one, (fcl_build + fcl_query) / (build + one), only_fcl, only_contain);
#else
  std::printf("FCL not found (libfcl-dev): no comparison\n");
#endif
  return 0;
}
