// Whole-process peer of `contain collide A.off B.off --poses POSES --threads 1`: reads both OFF
// meshes and the poses (peer_points.h: the fastest plain reader), builds FCL's BVHModel<OBBRSS> of
// each (one thread) and answers each pose of B by fcl::collide, the first contact of the two
// surfaces ("intersect" or "disjoint" a line; FCL has no solids, so a nested pose is "disjoint"
// where contain says "intersect"). Kernel times on stderr.
//   fcl_collide A.off B.off POSES.txt > answers.txt

#include <fcl/fcl.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench/peers/peer_driver.h"
#include "bench/peers/peer_points.h"

namespace {

using contain::bench::OffMesh;

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> model_of(const OffMesh& mesh) {
  std::vector<fcl::Vector3d> vertices;
  vertices.reserve(mesh.vertices.size() / 3);
  for (std::size_t i = 0; i + 2 < mesh.vertices.size(); i += 3)
    vertices.emplace_back(mesh.vertices[i], mesh.vertices[i + 1], mesh.vertices[i + 2]);
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size() / 3);
  for (std::size_t i = 0; i + 2 < mesh.triangles.size(); i += 3)
    triangles.emplace_back(mesh.triangles[i], mesh.triangles[i + 1], mesh.triangles[i + 2]);
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  return model;
}

// Twelve numbers a pose, the rows of [R|t] (the contract's transform).
std::vector<fcl::Transform3d> poses_of(const std::vector<double>& numbers) {
  if (numbers.size() % 12 != 0) {
    std::fprintf(stderr, "the poses are not 12 numbers each\n");
    std::exit(3);
  }
  std::vector<fcl::Transform3d> poses(numbers.size() / 12);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const double* n = &numbers[12 * i];
    fcl::Matrix3d r;
    r << n[0], n[1], n[2], n[4], n[5], n[6], n[8], n[9], n[10];
    poses[i].setIdentity();
    poses[i].linear() = r;
    poses[i].translation() = fcl::Vector3d(n[3], n[7], n[11]);
  }
  return poses;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace contain::bench;
  if (argc != 4) {
    std::fprintf(stderr, "usage: fcl_collide A.off B.off POSES.txt\n");
    return 2;
  }
  const OffMesh a = read_off(argv[1]);
  const OffMesh b = read_off(argv[2]);
  const std::vector<fcl::Transform3d> poses = poses_of(read_numbers(argv[3]));
  const KernelClock build_clock;
  const auto model_a = model_of(a);
  const auto model_b = model_of(b);
  build_clock.report("build");
  const KernelClock query_clock;
  const fcl::CollisionObjectd object_a(model_a, fcl::Transform3d::Identity());
  std::string text;
  text.reserve(10 * poses.size());
  for (const fcl::Transform3d& pose : poses) {
    fcl::CollisionObjectd object_b(model_b, pose);
    const fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::collide(&object_a, &object_b, request, result);
    text += result.isCollision() ? "intersect\n" : "disjoint\n";
  }
  query_clock.report("query");
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}
