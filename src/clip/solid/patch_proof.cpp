// The proofs of patch_proof.h: the boundary chain of a patch by a sort of its half-edges, walked
// as one cycle, then the simplicity of its projection by a sweep over the edges' boxes with
// exact segment tests (predicates::segments_meet, orient2d).

#include "clip/solid/patch_proof.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/predicates/orient2d.h"
#include "contain/predicates/triangles_meet_2d.h"

namespace contain::clip::solid {
namespace {

using predicates::orient2d;

// The projection dropping `axis`, coordinates in cyclic order (orient2d there is the sign of the
// normal's `axis` component).
Vec2 flattened(Vec3 p, int axis) {
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// Bit 2k (2k + 1) when triangle t turns strictly positively (negatively) dropping axis k.
std::uint8_t strict_turns(const Soup& soup, std::int32_t t) {
  const TriangleIndices& v = soup.triangles[static_cast<std::size_t>(t)];
  const Vec3 a = soup.vertices[static_cast<std::size_t>(v[0])];
  const Vec3 b = soup.vertices[static_cast<std::size_t>(v[1])];
  const Vec3 c = soup.vertices[static_cast<std::size_t>(v[2])];
  unsigned bits = 0;
  for (int k = 0; k < 3; ++k) {
    const Sign s = orient2d(flattened(a, k), flattened(b, k), flattened(c, k));
    if (s == Sign::positive) bits |= 1U << (2 * k);
    if (s == Sign::negative) bits |= 1U << (2 * k + 1);
  }
  return static_cast<std::uint8_t>(bits);
}

struct DirectedEdge {
  std::int32_t from, to;
};

// The boundary chain of the patch as one cycle of distinct vertices, in order; empty when it is
// not one (no boundary, an edge left over twice, two cycles, a vertex twice on one).
std::vector<DirectedEdge> boundary_cycle(const Soup& soup, std::span<const std::int32_t> patch) {
  // Each half-edge under its undirected key, +1 when it runs from the lower vertex number.
  std::vector<std::pair<std::uint64_t, int>> halves;
  halves.reserve(3 * patch.size());
  for (const std::int32_t t : patch) {
    const TriangleIndices& v = soup.triangles[static_cast<std::size_t>(t)];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t a = v[k], b = v[(k + 1) % 3];
      halves.emplace_back(edge_key(a, b), a < b ? 1 : -1);
    }
  }
  std::sort(halves.begin(), halves.end());
  std::vector<DirectedEdge> boundary;
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    int net = 0;
    while (j < halves.size() && halves[j].first == halves[i].first)
      net += halves[j++].second;
    const auto lo = static_cast<std::int32_t>(halves[i].first >> 32U);
    const auto hi = static_cast<std::int32_t>(halves[i].first & 0xffffffffU);
    if (net == 1) boundary.push_back({lo, hi});
    if (net == -1) boundary.push_back({hi, lo});
    if (net > 1 || net < -1) return {};
    i = j;
  }
  if (boundary.size() < 3) return {};
  std::sort(boundary.begin(), boundary.end(),
            [](DirectedEdge e, DirectedEdge f) { return e.from < f.from; });
  for (std::size_t i = 1; i < boundary.size(); ++i) {
    if (boundary[i].from == boundary[i - 1].from) return {};
  }
  // From edge 0 along each edge's successor (the one edge leaving its end): back at edge 0 after
  // all of them exactly when they form one cycle (a walk that repeats an edge first never
  // returns to edge 0, each edge having one predecessor on the walk).
  std::vector<DirectedEdge> cycle;
  cycle.reserve(boundary.size());
  std::size_t current = 0;
  for (std::size_t step = 0; step < boundary.size(); ++step) {
    cycle.push_back(boundary[current]);
    const auto next =
        std::lower_bound(boundary.begin(), boundary.end(), boundary[current].to,
                         [](DirectedEdge e, std::int32_t from) { return e.from < from; });
    if (next == boundary.end() || next->from != boundary[current].to) return {};
    current = static_cast<std::size_t>(next - boundary.begin());
    if (current == 0) return step + 1 == boundary.size() ? cycle : std::vector<DirectedEdge>{};
  }
  return {};
}

// Sign of b - a compared by value.
int value_order(double a, double b) {
  return a < b ? 1 : (b < a ? -1 : 0);
}

// Whether consecutive edges a -> b -> c of the projected polygon meet only at b: not when c
// lies on the line of a b on a's side of b (folded back), nor when an edge has no length.
bool turn_apart(Vec2 a, Vec2 b, Vec2 c) {
  if ((a.x == b.x && a.y == b.y) || (c.x == b.x && c.y == b.y)) return false;
  if (orient2d(a, b, c) != Sign::zero) return true;
  // On one line through b: the same direction from b in some coordinate is the same ray.
  return value_order(b.x, a.x) * value_order(b.x, c.x) <= 0 &&
         value_order(b.y, a.y) * value_order(b.y, c.y) <= 0;
}

// Whether the cycle's projection dropping `axis` is a simple polygon: a sweep along the first
// coordinate over the edges' boxes, each pair of boxes that meet tested exactly.
bool simple_polygon(const Soup& soup, const std::vector<DirectedEdge>& cycle, int axis) {
  const std::size_t m = cycle.size();
  struct ProjectedEdge {
    Vec2 p, q;
    double x_min, x_max, y_min, y_max;
  };
  std::vector<ProjectedEdge> pieces(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2 p = flattened(soup.vertices[static_cast<std::size_t>(cycle[i].from)], axis);
    const Vec2 q = flattened(soup.vertices[static_cast<std::size_t>(cycle[i].to)], axis);
    pieces[i] = {
        p, q, std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y)};
  }
  std::vector<std::uint32_t> order(m);
  for (std::size_t i = 0; i < m; ++i)
    order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
    return pieces[i].x_min < pieces[j].x_min || (pieces[i].x_min == pieces[j].x_min && i < j);
  });
  std::vector<std::uint32_t> active;
  for (const std::uint32_t i : order) {
    const ProjectedEdge& e = pieces[i];
    std::erase_if(active, [&](std::uint32_t j) { return pieces[j].x_max < e.x_min; });
    for (const std::uint32_t j : active) {
      const ProjectedEdge& f = pieces[j];
      if (f.y_max < e.y_min || e.y_max < f.y_min) continue;
      if (j == (i + 1) % m) {
        if (!turn_apart(e.p, e.q, f.q)) return false;
      } else if (i == (j + 1) % m) {
        if (!turn_apart(f.p, f.q, e.q)) return false;
      } else if (predicates::segments_meet({e.p, e.q}, {f.p, f.q})) {
        return false;
      }
    }
    active.push_back(i);
  }
  return true;
}

// The embedded-patch test of patch_proof.h given the directions in which every triangle of the
// patch turns strictly (bits as `strict_turns`).
bool embedded_in(const Soup& soup, std::span<const std::int32_t> patch, unsigned directions) {
  if (directions == 0) return false;
  const std::vector<DirectedEdge> cycle = boundary_cycle(soup, patch);
  if (cycle.empty()) return false;
  for (int k = 0; k < 3; ++k) {
    if ((directions >> (2 * k) & 3U) != 0 && simple_polygon(soup, cycle, k)) return true;
  }
  return false;
}

}  // namespace

bool embedded_patch(const Soup& soup, std::span<const std::int32_t> patch) {
  unsigned directions = 0x3f;
  for (const std::int32_t t : patch)
    directions &= strict_turns(soup, t);
  return !patch.empty() && embedded_in(soup, patch, directions);
}

PatchProofs::PatchProofs(const Soup& soup, std::span<const std::uint8_t> corners) : soup_(soup) {
  const std::span<const bvh::Node> nodes = soup.tree.nodes();
  const std::span<const std::int32_t> items = soup.tree.items();
  directions_.assign(nodes.size(), 0);
  // Children after their parent: bottom up in reverse.
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const bvh::Node& n = nodes[i];
    if (n.is_leaf()) {
      unsigned bits = 0x3f;
      for (std::int32_t k = n.first; k < n.first + n.count && bits != 0; ++k) {
        const std::int32_t t = items[static_cast<std::size_t>(k)];
        bits &= corners[static_cast<std::size_t>(t)] == 7 ? strict_turns(soup, t) : 0U;
      }
      directions_[i] = static_cast<std::uint8_t>(bits);
    } else {
      directions_[i] = static_cast<std::uint8_t>(directions_[i + 1] &
                                                 directions_[static_cast<std::size_t>(n.first)]);
    }
  }
}

bool PatchProofs::settled(std::int32_t node) const {
  const std::span<const bvh::Node> nodes = soup_.tree.nodes();
  const unsigned directions = directions_[static_cast<std::size_t>(node)];
  if (directions == 0 || nodes[static_cast<std::size_t>(node)].is_leaf()) return false;
  // The subtree's items are contiguous in leaf order: from its first leaf to its last.
  std::int32_t first = node, last = node;
  while (!nodes[static_cast<std::size_t>(first)].is_leaf())
    ++first;
  while (!nodes[static_cast<std::size_t>(last)].is_leaf())
    last = nodes[static_cast<std::size_t>(last)].first;
  const bvh::Node& a = nodes[static_cast<std::size_t>(first)];
  const bvh::Node& b = nodes[static_cast<std::size_t>(last)];
  const std::span<const std::int32_t> patch = soup_.tree.items().subspan(
      static_cast<std::size_t>(a.first), static_cast<std::size_t>(b.first + b.count - a.first));
  const bool embedded = embedded_in(soup_, patch, directions);
  ++(embedded ? settled_ : failed_);
  return embedded;
}

}  // namespace contain::clip::solid
