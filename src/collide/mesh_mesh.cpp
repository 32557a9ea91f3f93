#include "contain/collide/mesh_mesh.h"

#include <algorithm>

#include "collide/mesh_sides.h"

namespace contain::collide {
MeshPair::MeshPair(const Mesh& a, const Mesh& b, const MeshPairOptions& options)
    : pair_(a, b, options) {}

Contact MeshPair::collide(const Transform& tb) const {
  const detail::Placed pb{detail::PlacedBoxes(tb, pair_.b.max_abs)};
  return detail::collide_sides(
      pair_.a, detail::InWorld{}, pair_.b, pb,
      [&](const Box3& x, const Box3& y) { return x.overlaps(pb(y)); },
      [&](Vec3 p) { return pair_.a_holds(p); });
}

void MeshPair::collide(std::span<const Transform> poses, std::span<Contact> out,
                       const BatchOptions& options) const {
  batch_map(poses, out, options, 4096, [&](const Transform& pose) { return collide(pose); });
}

Contact mesh_mesh(const Mesh& a, const Mesh& b, const Transform& transform_a,
                  const Transform& transform_b) {
  return MeshPair(a, b, {.transform_a = transform_a}).collide(transform_b);
}

}  // namespace contain::collide
