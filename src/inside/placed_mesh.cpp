#include "contain/inside/placed_mesh.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <utility>

#include "contain/bvh/triangle_boxes.h"
#include "contain/inside/placed_ray.h"
#include "contain/shapes/mesh_components.h"
#include "contain/shapes/mesh_validation.h"
#include "contain/values/max_abs.h"

namespace contain::inside {

namespace {

// Everything but the solidity, which the pair takes from A's index instead of validating A.
void prepare(PlacedMesh& side, const bvh::BuildOptions& options) {
  side.bvh = bvh::Bvh(bvh::triangle_boxes(side.mesh), options);
  side.components = component_vertices(side.mesh);
  side.max_abs = std::max(side.max_abs, max_abs(std::span<const Vec3>(side.mesh.vertices)));
}

}  // namespace

Mesh placed_solid(const Mesh& mesh, const Transform& transform) {
  Mesh out = placed(mesh, transform);
  if (transform_orientation(transform) == Sign::negative) {
    for (TriangleIndices& t : out.triangles)
      std::swap(t[1], t[2]);
  }
  return out;
}

PlacedMesh::PlacedMesh(Mesh m, const bvh::BuildOptions& options) : mesh(std::move(m)) {
  prepare(*this, options);
  rule = solid_rule(mesh, validate_mesh(mesh));
}

// A's index, built once where the rays have cost as much (rent or buy: the total is then at
// most twice the better of the two choices made in hindsight). The cost model: building
// `MeshIndex` takes about kIndexCost a triangle (mesh_index.cpp's kGridCost; 0.6-1.1 us a
// triangle measured again on the 100k-triangle torus as a whole process), a step of a ray
// through the hierarchy (a node's box or a triangle's crossing test) about kRayStepCost, an
// estimate: 1000 nested poses of the torus in the torus, a ray each, do not change the query
// time measurably (docs/benchmarks.md, "Preparing in proportion to the work").
constexpr double kIndexCost = 1300.0, kRayStepCost = 10.0;

struct PlacedMeshPair::LazyIndex {
  MeshIndexOptions options;
  bool reflected = false;    // transform_a reflects: the index reads A's triangles reversed
  std::uint64_t budget = 0;  // ray steps that cost as much as the index
  std::atomic<std::uint64_t> steps{0};
  std::atomic<bool> built{false};
  std::once_flag once;
  MeshIndex index;

  void build(const Mesh& world) {
    std::call_once(once, [&] {
      if (reflected) {
        Mesh reversed = world;
        for (TriangleIndices& t : reversed.triangles)
          std::swap(t[1], t[2]);
        index = MeshIndex(std::move(reversed), options);
      } else {
        index = MeshIndex(world, options);
      }
      built.store(true, std::memory_order_release);
    });
  }
};

PlacedMeshPair::PlacedMeshPair(const Mesh& mesh_a, const Mesh& mesh_b,
                               const MeshPairOptions& options)
    : b(mesh_b, options.bvh) {
  a.mesh = placed(mesh_a, options.transform_a);
  prepare(a, options.bvh);
  if (a.mesh.triangles.empty()) return;
  // A's rule is the one its index would take (the same closedness test), so that the rays and
  // the index read the crossings alike. A reflection turns the placed triangles inside out: the
  // placed solid, the image of A's, is the solid of the placed mesh with its triangles reversed
  // (as locate_by_ray negates B's counts under a reflecting pose); A's triangles themselves keep
  // their corners (witnesses, features).
  a.rule = solid_rule(a.mesh, validate_mesh(a.mesh));
  lazy_a_ = std::make_shared<LazyIndex>();
  lazy_a_->options = options.index;
  lazy_a_->reflected = transform_orientation(options.transform_a) == Sign::negative;
  lazy_a_->budget = static_cast<std::uint64_t>(kIndexCost / kRayStepCost *
                                               static_cast<double>(a.mesh.triangles.size()));
}

const MeshIndex& PlacedMeshPair::index_a() const {
  static const MeshIndex empty;
  if (!lazy_a_) return empty;
  if (!lazy_a_->built.load(std::memory_order_acquire)) lazy_a_->build(a.mesh);
  return lazy_a_->index;
}

bool PlacedMeshPair::index_a_built() const {
  return lazy_a_ && lazy_a_->built.load(std::memory_order_acquire);
}

bool PlacedMeshPair::a_holds(Vec3 q) const {
  if (!lazy_a_) return false;
  if (lazy_a_->built.load(std::memory_order_acquire)) {
    return lazy_a_->index.locate(q) == Location::inside;
  }
  const Sign orientation = lazy_a_->reflected ? Sign::negative : Sign::positive;
  std::uint64_t steps = 0;
  const Location location = locate_by_ray(
      a.bvh, q, a.rule, orientation,
      [&](const Box3& box) -> const Box3& {
        ++steps;
        return box;
      },
      [&](std::int32_t t) {
        ++steps;
        return a.mesh.triangle(static_cast<std::size_t>(t));
      });
  const std::uint64_t total = lazy_a_->steps.fetch_add(steps, std::memory_order_relaxed) + steps;
  if (location == Location::boundary) return index_a().locate(q) == Location::inside;
  if (total >= lazy_a_->budget) lazy_a_->build(a.mesh);
  return location == Location::inside;
}

}  // namespace contain::inside
