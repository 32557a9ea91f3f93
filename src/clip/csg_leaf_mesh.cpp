// CSG leaves to meshes: bounded polyhedra give their own triangles, possibly unbounded ones the
// part of them inside a box, cut by mesh_clip with caps.

#include "contain/clip/csg_leaf_mesh.h"

#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "contain/clip/mesh_clip.h"
#include "contain/shapes/convex_polyhedron.h"

namespace contain::clip {
namespace {

Mesh polyhedron_mesh(const ConvexPolyhedron& p) {
  return {p.vertices(), p.face_indices()};
}

Mesh box_mesh(const Box3& box) {
  if (box.empty()) return {};
  return polyhedron_mesh(ConvexPolyhedron::from_box(box));
}

// The planes' region inside the box: the box's surface cut and capped, one plane at a time.
Mesh planes_in_box(std::span<const Plane> planes, const Box3& bounds) {
  return clip_mesh(box_mesh(bounds), planes, {.cut = MeshCut::cap});
}

}  // namespace

Result<Mesh> csg_leaf_mesh(const CsgLeaf& leaf, const Box3& bounds) {
  return std::visit(
      [&](const auto& solid) -> Result<Mesh> {
        using T = std::decay_t<decltype(solid)>;
        if constexpr (std::is_same_v<T, Box3>) {
          return box_mesh(solid);
        } else if constexpr (std::is_same_v<T, CsgMesh>) {
          return solid.mesh();
        } else if constexpr (std::is_same_v<T, ConvexPolyhedron>) {
          if (!solid.vertices().empty()) return polyhedron_mesh(solid);
          return planes_in_box(solid.planes(), bounds);
        } else if constexpr (std::is_same_v<T, Plane>) {
          return planes_in_box(std::span<const Plane>(&solid, 1), bounds);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return Error{ErrorKind::unsupported,
                       "a sphere is not polyhedral: a mesh boolean takes meshes, boxes, "
                       "half-spaces within a box and convex polyhedra"};
        } else {
          static_assert(std::is_same_v<T, ImplicitFunction>);
          return Error{ErrorKind::unsupported,
                       "an implicit function is not polyhedral: a mesh boolean takes meshes, "
                       "boxes, half-spaces within a box and convex polyhedra"};
        }
      },
      leaf);
}

std::optional<Box3> csg_leaf_box(const CsgLeaf& leaf) {
  return std::visit(
      [](const auto& solid) -> std::optional<Box3> {
        using T = std::decay_t<decltype(solid)>;
        if constexpr (std::is_same_v<T, Box3>) {
          return solid;
        } else {
          const std::vector<Vec3>* points = nullptr;
          if constexpr (std::is_same_v<T, CsgMesh>) points = &solid.mesh().vertices;
          if constexpr (std::is_same_v<T, ConvexPolyhedron>) {
            if (!solid.vertices().empty()) points = &solid.vertices();
          }
          if (points == nullptr) return std::nullopt;
          Box3 box;
          for (const Vec3& p : *points)
            box.expand(p);
          return box;
        }
      },
      leaf);
}

}  // namespace contain::clip
