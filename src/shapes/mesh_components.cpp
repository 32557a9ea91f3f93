#include "contain/shapes/mesh_components.h"

#include "contain/core/union_find.h"

namespace contain::shapes {

std::vector<std::int32_t> component_vertices(const Mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  // The representative of a set is its smallest element, so each root is the vertex to report.
  UnionFind<std::uint32_t> sets(n);
  std::vector<char> used(n, 0);
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::int32_t v : t)
      used[static_cast<std::size_t>(v)] = 1;
    sets.unite(static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]));
    sets.unite(static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[2]));
  }
  std::vector<std::int32_t> out;
  for (std::size_t v = 0; v < n; ++v)
    if (used[v] && sets.find(static_cast<std::uint32_t>(v)) == v)
      out.push_back(static_cast<std::int32_t>(v));
  return out;
}

}  // namespace contain::shapes
