#include "contain/collide/mesh_scene.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "collide/mesh_sides.h"
#include "collide/placed_boxes.h"
#include "collide/separating_axes.h"
#include "contain/collide/pair_search.h"

namespace contain::collide {

MeshScene::MeshScene(std::span<const Mesh> meshes, std::span<const inside::SceneObject> objects,
                     const MeshSceneOptions& options)
    : objects_(objects.begin(), objects.end()) {
  // Only the meshes some object places are prepared.
  std::vector<char> used(meshes.size(), 0);
  for (const inside::SceneObject& o : objects_) {
    if (o.mesh >= 0 && static_cast<std::size_t>(o.mesh) < meshes.size()) {
      used[static_cast<std::size_t>(o.mesh)] = 1;
    }
  }
  models_.resize(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    if (used[m] && !meshes[m].triangles.empty())
      models_[m] = inside::PlacedMesh(meshes[m], options.bvh);
  }
  // World boxes for the broad phase: the union of the placed boxes of the nodes a few levels
  // down each hierarchy (at most 2^kLevels of them), which hold every placed triangle. Placing
  // the vertices themselves took 40 million transforms for 500 corpus meshes; this is tight
  // enough and costs a few hundred boxes an object.
  constexpr int kLevels = 8;
  boxes_.resize(objects_.size());
  for (std::size_t k = 0; k < objects_.size(); ++k) {
    const inside::SceneObject& o = objects_[k];
    if (o.mesh < 0 || static_cast<std::size_t>(o.mesh) >= models_.size()) continue;
    const inside::PlacedMesh& model = models_[static_cast<std::size_t>(o.mesh)];
    if (model.bvh.empty()) continue;
    const detail::PlacedBoxes place(o.transform, model.max_abs);
    const std::span<const bvh::Node> nodes = model.bvh.nodes();
    std::vector<std::pair<std::int32_t, int>> stack{{0, 0}};
    while (!stack.empty()) {
      const auto [index, level] = stack.back();
      stack.pop_back();
      const bvh::Node& node = nodes[static_cast<std::size_t>(index)];
      if (node.is_leaf() || level == kLevels) {
        boxes_[k].expand(place(node.box));
      } else {
        stack.emplace_back(index + 1, level + 1);
        stack.emplace_back(node.first, level + 1);
      }
    }
  }
}

bool MeshScene::is_solid(std::size_t k) const {
  const std::int32_t m = objects_[k].mesh;
  return m >= 0 && static_cast<std::size_t>(m) < models_.size() &&
         models_[static_cast<std::size_t>(m)].solid();
}

std::vector<std::pair<std::int32_t, std::int32_t>> MeshScene::candidates() const {
  return pair_search(boxes_);
}

Contact MeshScene::collide(std::size_t i, std::size_t j) const {
  const inside::SceneObject& oi = objects_[i];
  const inside::SceneObject& oj = objects_[j];
  if (boxes_[i].empty() || boxes_[j].empty()) return {};
  const auto mi = static_cast<std::size_t>(oi.mesh), mj = static_cast<std::size_t>(oj.mesh);
  const inside::PlacedMesh& a = models_[mi];
  const inside::PlacedMesh& b = models_[mj];
  const detail::Placed pa{detail::PlacedBoxes(oi.transform, models_[mi].max_abs)};
  const detail::Placed pb{detail::PlacedBoxes(oj.transform, models_[mj].max_abs)};
  const detail::SeparatingAxes axes(pa.boxes, pb.boxes);
  return detail::collide_sides(
      a, pa, b, pb, [&](const Box3& x, const Box3& y) { return axes.may_meet(x, y); },
      [&](Vec3 p) { return detail::strictly_inside(a, pa, p); });
}

std::vector<ScenePair> MeshScene::pairs(const BatchOptions& options) const {
  return pairs(candidates(), options);
}

std::vector<ScenePair> MeshScene::pairs(
    std::span<const std::pair<std::int32_t, std::int32_t>> candidate,
    const BatchOptions& options) const {
  std::vector<Contact> contacts(candidate.size());
  // Pair tests differ in cost by orders of magnitude: threads take the next candidate as they
  // free up; each result goes to its own slot, so the answer does not depend on the threads.
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next.fetch_add(1); k < candidate.size(); k = next.fetch_add(1)) {
      contacts[k] = collide(static_cast<std::size_t>(candidate[k].first),
                            static_cast<std::size_t>(candidate[k].second));
    }
  };
  const int threads = thread_count(options, candidate.size(), 1);
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
    workers.emplace_back(work);
  work();
  for (std::thread& w : workers)
    w.join();
  std::vector<ScenePair> out;
  for (std::size_t k = 0; k < candidate.size(); ++k) {
    if (contacts[k].intersect)
      out.push_back({candidate[k].first, candidate[k].second, contacts[k]});
  }
  return out;
}

std::vector<ScenePair> scene_pairs(std::span<const Mesh> meshes,
                                   std::span<const inside::SceneObject> objects,
                                   const BatchOptions& options) {
  return MeshScene(meshes, objects).pairs(options);
}

}  // namespace contain::collide
