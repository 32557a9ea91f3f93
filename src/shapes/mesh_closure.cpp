#include "contain/shapes/mesh_closure.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

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
  // The undirected edge packed in one word (vertex numbers are non-negative int32), compared
  // first: most comparisons of the sort end there.
  const auto edge = [](const EdgeUse& e) {
    return (static_cast<std::uint64_t>(std::min(e.from, e.to)) << 32) |
           static_cast<std::uint64_t>(std::max(e.from, e.to));
  };
  const std::uint64_t ea = edge(a);
  const std::uint64_t eb = edge(b);
  if (ea != eb) return ea < eb;
  return std::tie(a.from, a.triangle, a.corner) < std::tie(b.from, b.triangle, b.corner);
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
  // A counting sort by the lower vertex (vertex numbers are dense), then each vertex's few
  // edges by `before`: the same order as sorting all by `before`, in linear time. The full sort
  // was a quarter of slicing 100 planes through a 131k-triangle sphere.
  std::vector<std::size_t> start(welded.vertices.size() + 1, 0);
  for (const EdgeUse& e : edges)
    ++start[static_cast<std::size_t>(std::min(e.from, e.to)) + 1];
  for (std::size_t v = 1; v < start.size(); ++v)
    start[v] += start[v - 1];
  std::vector<EdgeUse> sorted(edges.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const EdgeUse& e : edges)
    sorted[next[static_cast<std::size_t>(std::min(e.from, e.to))]++] = e;
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[v]),
              sorted.begin() + static_cast<std::ptrdiff_t>(start[v + 1]),
              [](const EdgeUse& a, const EdgeUse& b) { return before(a, b); });
  }
  return sorted;
}

// True when every directed edge occurs as often as its reverse: the answer for most meshes,
// found without the records of directed_edges. Each edge is filed under its lower vertex as
// (upper vertex, direction) in one word (a counting sort), and each vertex's few words are
// sorted and counted. About a fifth of the cost of the full search, which then runs only for
// open meshes, to name their first unbalanced edge.
bool balanced(const Mesh& welded) {
  std::vector<std::size_t> start(welded.vertices.size() + 1, 0);
  const auto each_edge = [&](auto&& f) {
    for (const TriangleIndices& v : welded.triangles) {
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int32_t from = v[k];
        const std::int32_t to = v[(k + 1) % 3];
        if (from != to) f(from, to);
      }
    }
  };
  each_edge([&](std::int32_t a, std::int32_t b) {
    ++start[static_cast<std::size_t>(std::min(a, b)) + 1];
  });
  for (std::size_t v = 1; v < start.size(); ++v)
    start[v] += start[v - 1];
  std::vector<std::uint64_t> filed(start.back());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  each_edge([&](std::int32_t a, std::int32_t b) {
    const auto lo = static_cast<std::size_t>(std::min(a, b));
    const auto hi = static_cast<std::uint64_t>(std::max(a, b));
    filed[next[lo]++] = (hi << 1) | (a < b ? 0U : 1U);
  });
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const auto first = filed.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto last = filed.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last);
    for (auto i = first; i != last;) {
      const std::uint64_t upper = *i >> 1;
      std::ptrdiff_t net = 0;
      for (; i != last && (*i >> 1) == upper; ++i)
        net += (*i & 1U) == 0 ? 1 : -1;
      if (net != 0) return false;
    }
  }
  return true;
}

}  // namespace

std::optional<UnmatchedEdge> unmatched_edge(const Mesh& mesh) {
  return unmatched_edge(weld_vertices(mesh));
}

std::optional<UnmatchedEdge> unmatched_edge(const WeldResult& weld) {
  if (balanced(weld.mesh)) return std::nullopt;
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
