#include "contain/shapes/mesh_closure.h"

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <vector>

#include "contain/shapes/mesh_validation.h"

namespace contain::shapes {
namespace {

// One directed edge of a triangle, on welded vertex numbers, with where it came from.
struct EdgeUse {
  std::int32_t from = 0;
  std::int32_t to = 0;
  std::int32_t triangle = 0;
  std::int32_t corner = 0;
};

// The undirected edge {from, to} first, then the direction, then the file order, so that the
// uses of one edge and of its reverse are neighbours and each run starts at its first triangle.
bool before(const EdgeUse& a, const EdgeUse& b) {
  const auto key = [](const EdgeUse& e) {
    return std::make_tuple(std::min(e.from, e.to), std::max(e.from, e.to), e.from, e.triangle,
                           e.corner);
  };
  return key(a) < key(b);
}

std::vector<EdgeUse> directed_edges(const Mesh& welded) {
  std::vector<EdgeUse> edges;
  edges.reserve(welded.triangles.size() * 3);
  for (std::size_t t = 0; t < welded.triangles.size(); ++t) {
    const TriangleIndices& v = welded.triangles[t];
    for (std::int32_t k = 0; k < 3; ++k) {
      const std::int32_t from = v[static_cast<std::size_t>(k)];
      const std::int32_t to = v[static_cast<std::size_t>((k + 1) % 3)];
      if (from != to) {
        edges.push_back({from, to, static_cast<std::int32_t>(t), k});
      }
    }
  }
  std::sort(edges.begin(), edges.end(), before);
  return edges;
}

}  // namespace

std::optional<UnmatchedEdge> unmatched_edge(const Mesh& mesh) {
  const WeldResult weld = weld_vertices(mesh);
  const std::vector<EdgeUse> edges = directed_edges(weld.mesh);
  std::optional<EdgeUse> worst;  // the unbalanced direction whose first triangle comes first
  std::int64_t worst_count = 0;
  std::int64_t worst_reverse = 0;
  for (std::size_t i = 0; i < edges.size();) {
    const std::int32_t lo = std::min(edges[i].from, edges[i].to);
    const std::int32_t hi = std::max(edges[i].from, edges[i].to);
    std::size_t j = i;
    while (j < edges.size() && edges[j].from == lo && edges[j].to == hi) {
      ++j;
    }
    std::size_t k = j;
    while (k < edges.size() && edges[k].from == hi && edges[k].to == lo) {
      ++k;
    }
    const auto up = static_cast<std::int64_t>(j - i);    // lo -> hi
    const auto down = static_cast<std::int64_t>(k - j);  // hi -> lo
    if (up != down) {
      const EdgeUse& first = up > down ? edges[i] : edges[j];
      if (!worst ||
          std::tie(first.triangle, first.corner) < std::tie(worst->triangle, worst->corner)) {
        worst = first;
        worst_count = std::max(up, down);
        worst_reverse = std::min(up, down);
      }
    }
    i = k;
  }
  if (!worst) {
    return std::nullopt;
  }
  return UnmatchedEdge{weld.mesh.vertex(worst->from), weld.mesh.vertex(worst->to), worst->triangle,
                       worst_count, worst_reverse};
}

}  // namespace contain::shapes
