#include "collide/components.h"

#include <numeric>

namespace contain::collide::detail {

std::vector<std::int32_t> component_vertices(const Mesh& mesh) {
  std::vector<std::int32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::int32_t v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      auto& p = parent[static_cast<std::size_t>(v)];
      p = parent[static_cast<std::size_t>(p)];
      v = p;
    }
    return v;
  };
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const TriangleIndices& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k)
      used[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])] = true;
    for (int k = 1; k < 3; ++k) {
      // Union by smaller index keeps each root the smallest vertex of its set.
      const std::int32_t x = find(t[0]), y = find(t[static_cast<std::size_t>(k)]);
      if (x < y) parent[static_cast<std::size_t>(y)] = x;
      if (y < x) parent[static_cast<std::size_t>(x)] = y;
    }
  }
  std::vector<std::int32_t> out;
  for (std::size_t v = 0; v < parent.size(); ++v) {
    if (used[v] && find(static_cast<std::int32_t>(v)) == static_cast<std::int32_t>(v)) {
      out.push_back(static_cast<std::int32_t>(v));
    }
  }
  return out;
}

}  // namespace contain::collide::detail
