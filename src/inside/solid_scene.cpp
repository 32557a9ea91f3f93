#include "contain/inside/solid_scene.h"

#include "inside/holder_batch.h"

namespace contain::inside {

SolidScene::SolidScene(std::span<const Mesh> meshes, std::span<const SceneObject> objects,
                       const SolidSceneOptions& options) {
  indexes_.reserve(objects.size());
  std::vector<Box3> boxes;
  boxes.reserve(objects.size());
  for (const SceneObject& object : objects) {
    if (object.mesh < 0 || static_cast<std::size_t>(object.mesh) >= meshes.size()) {
      indexes_.emplace_back();
      boxes.emplace_back();
      continue;
    }
    // A reflecting transform places the image of the solid, as collide::MeshScene reads it.
    const Mesh world =
        placed_solid(meshes[static_cast<std::size_t>(object.mesh)], object.transform);
    const MeshIndex& index = world.triangles.empty() ? indexes_.emplace_back()
                                                     : indexes_.emplace_back(world, options.index);
    boxes.push_back(world.triangles.empty() ? Box3{} : index.bounds());
  }
  tree_ = bvh::Bvh(boxes, {.max_leaf_items = 2});
}

void SolidScene::locate(Vec3 point, std::vector<Holder>& out) const {
  detail::append_holders(
      tree_, indexes_, point, [&](const Box3& box) { return box.contains(point); }, out);
}

std::vector<Holder> SolidScene::locate(Vec3 point) const {
  std::vector<Holder> out;
  locate(point, out);
  return out;
}

HolderTable SolidScene::locate(std::span<const Vec3> points, const BatchOptions& options) const {
  return detail::holder_table(points, options,
                              [&](Vec3 p, std::vector<Holder>& out) { locate(p, out); });
}

std::vector<Holder> point_in_solids(std::span<const Mesh> meshes,
                                    std::span<const SceneObject> objects, Vec3 point,
                                    const SolidSceneOptions& options) {
  return SolidScene(meshes, objects, options).locate(point);
}

}  // namespace contain::inside
