// A contain Mesh as FCL's BVHModel, for the benchmarks that run FCL beside contain (include only
// where CONTAIN_BENCH_HAS_FCL is defined).
#pragma once

#include <fcl/fcl.h>

#include <memory>
#include <vector>

#include "contain/shapes/mesh.h"

namespace contain::bench {

template <class BV>
std::shared_ptr<fcl::BVHModel<BV>> fcl_model(const Mesh& m) {
  auto bvh = std::make_shared<fcl::BVHModel<BV>>();
  std::vector<fcl::Vector3d> v;
  std::vector<fcl::Triangle> t;
  for (const Vec3& p : m.vertices)
    v.emplace_back(p.x, p.y, p.z);
  for (const auto& f : m.triangles)
    t.emplace_back(f[0], f[1], f[2]);
  bvh->beginModel();
  bvh->addSubModel(v, t);
  bvh->endModel();
  return bvh;
}

}  // namespace contain::bench
