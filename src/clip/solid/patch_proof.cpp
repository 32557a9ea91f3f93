// The proofs of patch_proof.h: the boundary chain of a patch (through the neighbours across
// edges for a subtree, by a sort of its half-edges for any set), its connection by union-find,
// then in each projection its triangles all turn in, the edges' meetings by a sweep over their
// boxes with exact segment tests (predicates::segments_meet, orient2d), and the alternation of
// in and out around its pinches.

#include "clip/solid/patch_proof.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/core/union_find.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/triangles_meet_2d.h"

namespace contain::clip::solid {
namespace {

using predicates::orient2d;

// Bit 2k (2k + 1) when triangle t turns strictly positively (negatively) dropping axis k.
std::uint8_t strict_turns(const Soup& soup, std::int32_t t) {
  const TriangleIndices& v = soup.triangles[static_cast<std::size_t>(t)];
  const Vec3 a = soup.vertices[static_cast<std::size_t>(v[0])];
  const Vec3 b = soup.vertices[static_cast<std::size_t>(v[1])];
  const Vec3 c = soup.vertices[static_cast<std::size_t>(v[2])];
  unsigned bits = 0;
  for (int k = 0; k < 3; ++k) {
    const Sign s = orient2d(drop_axis(a, k), drop_axis(b, k), drop_axis(c, k));
    if (s == Sign::positive) bits |= 1U << (2 * k);
    if (s == Sign::negative) bits |= 1U << (2 * k + 1);
  }
  return static_cast<std::uint8_t>(bits);
}

// The boundary chain of the patch by a sort of its half-edges (each under its undirected key,
// +1 when it runs from the lower vertex number); empty when an edge is left over twice.
std::vector<BoundaryEdge> sorted_boundary(const Soup& soup, std::span<const std::int32_t> patch) {
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
  std::vector<BoundaryEdge> boundary;
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
  return boundary;
}

// Sign of b - a compared by value.
int value_order(double a, double b) {
  return a < b ? 1 : (b < a ? -1 : 0);
}

// Whether two edges from a common end s to p and to q meet only at s: not when one lies along
// the other (on one line through s, the same way in some coordinate), nor when one has no length.
bool apart_at(Vec2 s, Vec2 p, Vec2 q) {
  if ((p.x == s.x && p.y == s.y) || (q.x == s.x && q.y == s.y)) return false;
  if (orient2d(s, p, q) != Sign::zero) return true;
  return value_order(s.x, p.x) * value_order(s.x, q.x) <= 0 &&
         value_order(s.y, p.y) * value_order(s.y, q.y) <= 0;
}

// Whether the boundary's projected edges meet only at the ends they share by number: a sweep
// along the first coordinate over the edges' boxes, each pair of boxes that meet tested exactly.
bool edges_apart(PatchScratch& scratch) {
  const std::vector<BoundaryEdge>& boundary = scratch.boundary;
  const std::vector<Vec2>& from = scratch.from;
  const std::vector<Vec2>& to = scratch.to;
  const std::size_t m = boundary.size();
  std::vector<std::uint32_t>& order = scratch.order;
  order.resize(m);
  for (std::size_t i = 0; i < m; ++i)
    order[i] = static_cast<std::uint32_t>(i);
  const auto x_min = [&](std::uint32_t i) { return std::min(from[i].x, to[i].x); };
  std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
    return x_min(i) < x_min(j) || (x_min(i) == x_min(j) && i < j);
  });
  std::vector<std::uint32_t>& active = scratch.active;
  active.clear();
  for (const std::uint32_t i : order) {
    const double x = x_min(i);
    std::erase_if(active, [&](std::uint32_t j) { return std::max(from[j].x, to[j].x) < x; });
    const double y_lo = std::min(from[i].y, to[i].y), y_hi = std::max(from[i].y, to[i].y);
    for (const std::uint32_t j : active) {
      if (std::max(from[j].y, to[j].y) < y_lo || y_hi < std::min(from[j].y, to[j].y)) continue;
      const BoundaryEdge e = boundary[i], f = boundary[j];
      bool apart = true;
      if (e.from == f.from) {
        apart = apart_at(from[i], to[i], to[j]);
      } else if (e.from == f.to) {
        apart = apart_at(from[i], to[i], from[j]);
      } else if (e.to == f.from) {
        apart = apart_at(to[i], from[i], to[j]);
      } else if (e.to == f.to) {
        apart = apart_at(to[i], from[i], from[j]);
      } else {
        apart = !predicates::segments_meet({from[i], to[i]}, {from[j], to[j]});
      }
      if (!apart) return false;
    }
    active.push_back(i);
  }
  return true;
}

// Whether ray r from o lies strictly inside the counter-clockwise sector from ray a to ray b
// (three directions pairwise different).
bool in_sector(Vec2 o, Vec2 a, Vec2 b, Vec2 r) {
  const Sign ab = orient2d(o, a, b);
  if (ab == Sign::positive) {
    return orient2d(o, a, r) == Sign::positive && orient2d(o, r, b) == Sign::positive;
  }
  if (ab == Sign::zero) return orient2d(o, a, r) == Sign::positive;  // a and b opposite
  return orient2d(o, a, r) != Sign::negative || orient2d(o, r, b) != Sign::negative;
}

// Whether the boundary (sorted by `from`) is connected: each edge joined to the first edge
// leaving each of its ends (a chain's boundary leaves every vertex it enters).
bool connected(const std::vector<BoundaryEdge>& boundary, UnionFind<std::uint32_t>& sets) {
  const std::size_t m = boundary.size();
  const auto first_out = [&](std::int32_t v) {
    return static_cast<std::size_t>(
        std::lower_bound(boundary.begin(), boundary.end(), v,
                         [](BoundaryEdge e, std::int32_t x) { return e.from < x; }) -
        boundary.begin());
  };
  sets.reset(m);
  std::size_t components = m;
  for (std::size_t i = 0; i < m; ++i) {
    for (const std::int32_t v : {boundary[i].from, boundary[i].to}) {
      const std::size_t f = first_out(v);
      if (f == m || boundary[f].from != v) return false;
      const std::uint32_t a = sets.find(static_cast<std::uint32_t>(i));
      const std::uint32_t b = sets.find(static_cast<std::uint32_t>(f));
      if (a != b) {
        sets.unite(a, b);
        --components;
      }
    }
  }
  return components == 1;
}

// The boundary conditions of patch_proof.h in the projection dropping `axis`.
bool boundary_embeds(const Soup& soup, PatchScratch& scratch, int axis) {
  const std::vector<BoundaryEdge>& boundary = scratch.boundary;
  const std::size_t m = boundary.size();
  std::vector<Vec2>& from = scratch.from;
  std::vector<Vec2>& to = scratch.to;
  from.resize(m);
  to.resize(m);
  bool pinched = false;
  for (std::size_t i = 0; i < m; ++i) {
    from[i] = drop_axis(soup.vertices[static_cast<std::size_t>(boundary[i].from)], axis);
    to[i] = drop_axis(soup.vertices[static_cast<std::size_t>(boundary[i].to)], axis);
    pinched = pinched || (i > 0 && boundary[i].from == boundary[i - 1].from);
  }
  if (!edges_apart(scratch)) return false;
  if (!pinched) return true;
  // Each vertex's edges alternate in and out around it (boundary sorted by `from`; a chain's
  // boundary has as many in as out at each vertex): two out, then the two in one on each side.
  std::vector<std::uint32_t>& by_to = scratch.by_to;
  by_to.resize(m);
  for (std::size_t i = 0; i < m; ++i)
    by_to[i] = static_cast<std::uint32_t>(i);
  std::sort(by_to.begin(), by_to.end(),
            [&](std::uint32_t i, std::uint32_t j) { return boundary[i].to < boundary[j].to; });
  std::size_t k = 0;
  for (std::size_t i = 0; i < m;) {
    std::size_t j = i;
    while (j < m && boundary[j].from == boundary[i].from)
      ++j;
    while (k < m && boundary[by_to[k]].to < boundary[i].from)
      ++k;
    const std::size_t outs = j - i;
    if (outs > 2) return false;
    if (outs == 2) {
      if (k + 1 >= m || boundary[by_to[k]].to != boundary[i].from ||
          boundary[by_to[k + 1]].to != boundary[i].from) {
        return false;
      }
      const Vec2 o = from[i];
      if (in_sector(o, to[i], to[i + 1], from[by_to[k]]) ==
          in_sector(o, to[i], to[i + 1], from[by_to[k + 1]])) {
        return false;
      }
    }
    i = j;
  }
  return true;
}

// The embedded-patch test of patch_proof.h given the patch's boundary chain and the directions
// in which every triangle of the patch turns strictly (bits as `strict_turns`).
bool embedded_in(const Soup& soup, PatchScratch& scratch, unsigned directions) {
  std::vector<BoundaryEdge>& boundary = scratch.boundary;
  if (directions == 0 || boundary.size() < 3) return false;
  std::sort(boundary.begin(), boundary.end(), [](BoundaryEdge e, BoundaryEdge f) {
    return e.from < f.from || (e.from == f.from && e.to < f.to);
  });
  if (!connected(boundary, scratch.sets)) return false;
  for (int k = 0; k < 3; ++k) {
    if ((directions >> (2 * k) & 3U) != 0 && boundary_embeds(soup, scratch, k)) return true;
  }
  return false;
}

}  // namespace

bool embedded_patch(const Soup& soup, std::span<const std::int32_t> patch) {
  unsigned directions = 0x3f;
  for (const std::int32_t t : patch)
    directions &= strict_turns(soup, t);
  PatchScratch scratch;
  scratch.boundary = sorted_boundary(soup, patch);
  return !patch.empty() && embedded_in(soup, scratch, directions);
}

PatchProofs::PatchProofs(const Soup& soup, const ProvenStars& stars) : soup_(soup) {
  const std::span<const std::int32_t> items = soup.tree.items();
  const std::size_t triangles = soup.triangles.size();
  std::vector<std::int32_t> position(triangles, -1);
  for (std::size_t k = 0; k < items.size(); ++k)
    position[static_cast<std::size_t>(items[k])] = static_cast<std::int32_t>(k);
  // What the proofs read of each triangle, in leaf order (a subtree's triangles are then one
  // run of memory, where reading them by triangle number missed the cache at each): its
  // neighbours' positions and its turns; filled in the triangles' own order, in which `across`
  // and `turns` are read in sequence and the neighbours' positions mostly in cache.
  across_at_.assign(items.size(), {-1, -1, -1});
  std::vector<std::uint8_t> turns(items.size(), 0);
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::int32_t at = position[t];
    if (at < 0) continue;
    const auto k = static_cast<std::size_t>(at);
    for (std::size_t e = 0; e < 3; ++e) {
      const std::int32_t u = stars.across[t][e];
      across_at_[k][e] = u < 0 ? -1 : position[static_cast<std::size_t>(u)];
    }
    turns[k] = stars.turns[t];
  }
  summarize(turns, stars.corners);
}

PatchProofs PatchProofs::from_leaf_order(const Soup& soup, ProvenStars& stars) {
  PatchProofs proofs(soup);
  proofs.across_at_ = std::move(stars.across);
  proofs.summarize(stars.turns, stars.corners);
  return proofs;
}

void PatchProofs::summarize(std::span<const std::uint8_t> turns_at,
                            std::span<const std::uint8_t> corners) {
  const std::span<const bvh::Node> nodes = soup_.tree.nodes();
  const std::span<const std::int32_t> items = soup_.tree.items();
  directions_.assign(nodes.size(), 0);
  ranges_.assign(nodes.size(), {0, 0});
  // The input of each node's triangles (-1: of several). Subtrees of two inputs are not tried:
  // they hold the places where the inputs come near each other, and their proofs failed there
  // (at a union of two 131k-triangle spheres, 3,282 tries over 1.1 M triangles, for nothing).
  std::vector<std::int32_t> input(nodes.size(), -1);
  // Children after their parent: bottom up in reverse.
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const bvh::Node& n = nodes[i];
    if (n.is_leaf()) {
      // Each position's turns (none with a corner not proven: such a triangle is never in a
      // settled subtree) and input read here, where arrays of them in leaf order were 5 bytes a
      // triangle of fresh pages and a pass more.
      unsigned bits = 0x3f;
      const auto first = static_cast<std::size_t>(n.first);
      const std::int32_t one = soup_.input[static_cast<std::size_t>(items[first])];
      for (std::size_t k = first; k < first + static_cast<std::size_t>(n.count); ++k) {
        const auto t = static_cast<std::size_t>(items[k]);
        bits &= soup_.input[t] == one && corners[t] == 7 ? turns_at[k] : 0U;
      }
      directions_[i] = static_cast<std::uint8_t>(bits);
      input[i] = one;
      ranges_[i] = {n.first, n.first + n.count};
    } else {
      const auto second = static_cast<std::size_t>(n.first);
      input[i] = input[i + 1] == input[second] ? input[second] : -1;
      directions_[i] =
          input[i] < 0 ? 0 : static_cast<std::uint8_t>(directions_[i + 1] & directions_[second]);
      ranges_[i] = {ranges_[i + 1][0], ranges_[second][1]};
    }
  }
}

bool PatchProofs::settled(std::int32_t node) const {
  const auto i = static_cast<std::size_t>(node);
  const unsigned directions = directions_[i];
  if (directions == 0 || soup_.tree.nodes()[i].is_leaf()) return false;
  // The subtree's items are contiguous in leaf order; an edge is on its boundary when the
  // triangle across it is not among them (every corner is proven: `across` knows them all).
  const auto [first, end] = ranges_[i];
  const std::span<const std::int32_t> items = soup_.tree.items();
  std::vector<BoundaryEdge>& boundary = scratch_.boundary;
  boundary.clear();
  for (std::int32_t k = first; k < end; ++k) {
    const std::array<std::int32_t, 3>& across = across_at_[static_cast<std::size_t>(k)];
    for (std::size_t e = 0; e < 3; ++e) {
      const std::int32_t at = across[e];
      if (at < 0) return false;  // (not reached: all its corners are proven)
      if (at < first || at >= end) {
        const TriangleIndices& v =
            soup_.triangles[static_cast<std::size_t>(items[static_cast<std::size_t>(k)])];
        boundary.push_back({v[e], v[(e + 1) % 3]});
      }
    }
  }
  return embedded_in(soup_, scratch_, directions);
}

}  // namespace contain::clip::solid
