#include "distance/components.h"

#include <numeric>

namespace contain::distance::detail {

std::vector<std::int32_t> component_vertices(const Mesh& mesh) {
  std::vector<std::int32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::int32_t v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      parent[static_cast<std::size_t>(v)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
      v = parent[static_cast<std::size_t>(v)];
    }
    return v;
  };
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::int32_t v : t)
      used[static_cast<std::size_t>(v)] = 1;
    for (int k = 1; k < 3; ++k) {
      const std::int32_t x = find(t[0]), y = find(t[static_cast<std::size_t>(k)]);
      // the smaller index becomes the root, so a root is its component's smallest vertex
      if (x < y) parent[static_cast<std::size_t>(y)] = x;
      if (y < x) parent[static_cast<std::size_t>(x)] = y;
    }
  }
  std::vector<std::int32_t> out;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (used[v] && find(static_cast<std::int32_t>(v)) == static_cast<std::int32_t>(v))
      out.push_back(static_cast<std::int32_t>(v));
  return out;
}

}  // namespace contain::distance::detail
