#include "contain/shapes/mesh_closure.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <tuple>
#include <vector>

#include "contain/core/sort_few.h"

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

std::vector<EdgeUse> directed_edges(std::size_t vertices,
                                    std::span<const TriangleIndices> triangles) {
  std::vector<EdgeUse> edges;
  edges.reserve(triangles.size() * 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const TriangleIndices& v = triangles[t];
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
  std::vector<std::size_t> start(vertices + 1, 0);
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

// Every directed edge filed under its lower vertex by its number 3t + k (a counting sort, in
// 32-bit words: the table and the fill cursor are one array), then each vertex's few edges as
// words (upper vertex, direction, half-edge) from the high bits down, sorted: the uses of an edge
// and of its reverse are then one run, for `balanced` to count and pair. About a fifth of the
// cost of the full search (directed_edges), which then runs only for open meshes, to name their
// first unbalanced edge. False when the mesh is too large for the word.
template <class Run>
bool each_edge_run(std::span<const TriangleIndices> triangles, std::size_t vertices, Run&& run) {
  if (3 * triangles.size() >= (std::size_t{1} << 31)) return false;
  const auto lower = [&](std::size_t half) {
    const TriangleIndices& v = triangles[half / 3];
    const std::size_t k = half % 3;
    return static_cast<std::size_t>(std::min(v[k], v[k == 2 ? 0 : k + 1]));
  };
  // end[v]: one past the last slot of vertex v's edges, counted down to its first slot while
  // filing; end[vertices] is the total.
  std::vector<std::uint32_t> end(vertices + 1, 0);
  for (const TriangleIndices& v : triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (v[k] != v[k == 2 ? 0 : k + 1])
        ++end[static_cast<std::size_t>(std::min(v[k], v[k == 2 ? 0 : k + 1]))];
    }
  }
  for (std::size_t v = 1; v <= vertices; ++v)
    end[v] += end[v - 1];
  // Every slot is written by the filing below: no zeroing pass over 6 MB at 524k triangles.
  const std::unique_ptr<std::uint32_t[]> filed =
      std::make_unique_for_overwrite<std::uint32_t[]>(end[vertices]);
  for (std::size_t half = 3 * triangles.size(); half-- > 0;) {
    const TriangleIndices& v = triangles[half / 3];
    const std::size_t k = half % 3;
    if (v[k] != v[k == 2 ? 0 : k + 1]) filed[--end[lower(half)]] = static_cast<std::uint32_t>(half);
  }
  std::vector<std::uint64_t> words;
  for (std::size_t v = 0; v < vertices; ++v) {
    words.clear();
    for (std::uint32_t i = end[v]; i < end[v + 1]; ++i) {
      const std::size_t half = filed[i];
      const TriangleIndices& t = triangles[half / 3];
      const std::int32_t a = t[half % 3];
      const std::int32_t b = t[half % 3 == 2 ? 0 : half % 3 + 1];
      const auto hi = static_cast<std::uint64_t>(std::max(a, b));
      words.push_back((hi << 32) | (a < b ? 0U : std::uint64_t{1} << 31) | half);
    }
    // A vertex's few edge words in increasing order (distinct: each holds its half-edge).
    sort_few(words.begin(), words.end(), 32);
    for (auto i = words.begin(); i != words.end();) {
      const auto begin = i;
      const std::uint64_t upper = *i >> 32;
      for (; i != words.end() && (*i >> 32) == upper; ++i) {
      }
      if (!run(std::span<const std::uint64_t>(&*begin, static_cast<std::size_t>(i - begin))))
        return false;
    }
  }
  return true;
}

// The uses of one edge (a run of each_edge_run): as many up (lower to upper vertex, first in the
// run) as down.
bool balanced_run(std::span<const std::uint64_t> uses) {
  std::ptrdiff_t net = 0;
  for (const std::uint64_t use : uses)
    net += (use & (std::uint64_t{1} << 31)) == 0 ? 1 : -1;
  return net == 0;
}

bool balanced(std::span<const Vec3> vertices, std::span<const TriangleIndices> triangles) {
  return each_edge_run(triangles, vertices.size(), balanced_run);
}

}  // namespace

std::optional<UnmatchedEdge> unmatched_edge(const Mesh& mesh) {
  return unmatched_edge(weld_vertices(mesh));
}

std::optional<UnmatchedEdge> unmatched_edge(const WeldResult& weld) {
  return unmatched_edge(weld.mesh.vertices, weld.mesh.triangles);
}

std::optional<std::vector<std::int32_t>> paired_half_edges(const Mesh& welded) {
  return paired_half_edges(welded.triangles, welded.vertices.size());
}

std::optional<std::vector<std::int32_t>> paired_half_edges(
    std::span<const TriangleIndices> triangles, std::size_t vertices) {
  std::vector<std::int32_t> twin(3 * triangles.size(), -1);
  const auto pair = [&](std::span<const std::uint64_t> uses) {
    if (!balanced_run(uses)) return false;
    if (uses.size() == 2) {
      constexpr std::uint64_t kHalf = (std::uint64_t{1} << 31) - 1;
      const auto a = static_cast<std::int32_t>(uses[0] & kHalf);
      const auto b = static_cast<std::int32_t>(uses[1] & kHalf);
      if (a / 3 != b / 3) {
        twin[static_cast<std::size_t>(a)] = b;
        twin[static_cast<std::size_t>(b)] = a;
      }
    }
    return true;
  };
  if (!each_edge_run(triangles, vertices, pair)) return std::nullopt;
  return twin;
}

std::optional<UnmatchedEdge> unmatched_edge(std::span<const Vec3> vertices,
                                            std::span<const TriangleIndices> triangles) {
  if (balanced(vertices, triangles)) return std::nullopt;
  const std::vector<EdgeUse> edges = directed_edges(vertices.size(), triangles);
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
  return UnmatchedEdge{vertices[static_cast<std::size_t>(worst->from)],
                       vertices[static_cast<std::size_t>(worst->to)], worst->triangle, worst_count,
                       worst_reverse};
}

}  // namespace contain::shapes
