// The proofs of star_proof.h: each vertex's star gathered by a counting sort of the triangles'
// corners, its ring walked, then the exact tests (filtered orient2d / orient3d, exact fallback).

#include "clip/solid/star_proof.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"

namespace contain::clip::solid {
namespace {

using predicates::orient2d;
using predicates::orient3d;

// Stars larger than this (a fan's apex) are left unproven: the ring's walk is quadratic in
// their size, and they are few.
constexpr std::size_t max_star = 16;

// One triangle v a b of a vertex v's star (as oriented, rotated to start at v): its edge a -> b
// of the ring around v.
struct LinkEdge {
  std::int32_t a, b;
  std::int32_t corner;  // 3 t + k: the star's triangle t, v its corner k
};

// The ring of v's star in order (triangle i is v w[i] w[i + 1], w[n] = w[0]) from its link
// edges; false when they are not one closed fan of distinct ring vertices.
bool walk_ring(std::span<const LinkEdge> star, std::array<std::int32_t, max_star>& w,
               std::array<std::uint8_t, max_star>& order) {
  const std::size_t n = star.size();
  // Follow a -> b from edge 0: the next edge is the first whose a is this one's b. One cycle
  // through all n edges, back to edge 0 only at the end, makes the a's distinct (a second edge
  // with the a of one on the cycle would never be found first, so never visited), and so the
  // ring's vertices.
  std::array<bool, max_star> seen{};
  seen[0] = true;
  std::size_t current = 0;
  for (std::size_t i = 0; i < n; ++i) {
    w[i] = star[current].a;
    order[i] = static_cast<std::uint8_t>(current);
    std::size_t next = n;
    for (std::size_t j = 0; j < n; ++j) {
      if (star[j].a == star[current].b) {
        next = j;
        break;
      }
    }
    if (next == n) return false;
    if (i + 1 == n) return next == 0;
    if (seen[next]) return false;
    seen[next] = true;
    current = next;
  }
  return false;
}

// The sign of component `axis` of ck (dropping that axis: orient2d(v, wk, w(k+1)) there), by
// `filtered_turn` or orient2d itself (the projected points made only then).
Sign turn(const RingProducts& c, int axis, const Vec3& v, const Vec3& wk, const Vec3& wk1) {
  const std::optional<Sign> s = filtered_turn(c, axis);
  return s ? *s : orient2d(drop_axis(v, axis), drop_axis(wk, axis), drop_axis(wk1, axis));
}

// orient3d(v, wk, w(k+1), w(k+2)) by `filtered_bend` or orient3d itself.
Sign bend(const RingProducts& c, const std::array<double, 3>& t, Vec3 v, Vec3 wk, Vec3 wk1,
          Vec3 wk2) {
  const std::optional<Sign> s = filtered_bend(c, t);
  return s ? *s : orient3d(v, wk, wk1, wk2);
}

// Where a proof writes its triangles' neighbours and turns: `slot` the position of each
// triangle in those arrays (empty: its number).
struct StarOutput {
  ProvenStars* stars = nullptr;
  std::span<const std::int32_t> slot;
  [[nodiscard]] std::size_t at(std::int32_t t) const {
    return static_cast<std::size_t>(slot.empty() ? t : slot[static_cast<std::size_t>(t)]);
  }
};

// Whether v's star is proven; if so and `out.stars` is given, its triangles' neighbours across
// the edges at v written to its `across`, and the turns of those whose corner 0 is v to its
// `turns` (both at out.at of the triangle).
bool proven_star(const Soup& soup, std::int32_t v, std::span<const std::int32_t> corners,
                 const StarOutput& out) {
  const std::size_t n = corners.size();
  if (n < 3 || n > max_star) return false;
  std::array<LinkEdge, max_star> star;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<std::size_t>(corners[i]);
    const TriangleIndices& t = soup.triangles[c / 3];
    star[i] = {t[(c + 1) % 3], t[(c + 2) % 3], corners[i]};
    // The ring's positions are read after the walk below, whose branches depend on these loads:
    // asked for now, the misses of all n overlap with it.
    __builtin_prefetch(&soup.vertices[static_cast<std::size_t>(star[i].a)]);
  }
  std::array<std::int32_t, max_star> ids;
  std::array<std::uint8_t, max_star> order;
  if (!walk_ring(std::span<const LinkEdge>(star.data(), n), ids, order)) return false;
  // The positions by pointer: an array of Vec3 would be zeroed first (member initializers).
  std::array<const Vec3*, max_star> ring;
  for (std::size_t i = 0; i < n; ++i)
    ring[i] = &soup.vertices[static_cast<std::size_t>(ids[i])];
  const Vec3 apex = soup.vertices[static_cast<std::size_t>(v)];
  // Each difference and product once, where orient2d and orient3d would compute each three times.
  std::array<std::array<double, 3>, max_star> d;
  for (std::size_t i = 0; i < n; ++i)
    d[i] = {ring[i]->x - apex.x, ring[i]->y - apex.y, ring[i]->z - apex.z};
  // The successor of each index around the ring (no division per use).
  std::array<std::uint8_t, max_star + 1> next;
  for (std::size_t i = 0; i < n; ++i)
    next[i] = static_cast<std::uint8_t>(i + 1 == n ? 0 : i + 1);
  std::array<RingProducts, max_star> c;
  // The projection: the dominant axis of the fan's area vector (the sum of the ck) in doubles,
  // the one most likely to pass; any axis keeps the proof exact.
  double nx = 0.0, ny = 0.0, nz = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    c[i] = ring_products(d[i], d[next[i]]);
    nx += c[i].yz - c[i].zy;
    ny += c[i].zx - c[i].xz;
    nz += c[i].xy - c[i].yx;
  }
  nx = std::fabs(nx);
  ny = std::fabs(ny);
  nz = std::fabs(nz);
  const int axis = nx >= ny && nx >= nz ? 0 : (ny >= nz ? 1 : 2);
  // 1: every sector turns the same strict way (a zero-area triangle fails here).
  const Sign first_turn = turn(c[0], axis, apex, *ring[0], *ring[1]);
  if (first_turn == Sign::zero) return false;
  for (std::size_t i = 1; i < n; ++i) {
    if (turn(c[i], axis, apex, *ring[i], *ring[next[i]]) != first_turn) return false;
  }
  // The projected ring's second coordinates (an array of Vec2 would be zeroed first: 256 bytes,
  // a `rep stos` per star).
  const double oy = drop_axis(apex, axis).y;
  std::array<double, max_star> py;
  for (std::size_t i = 0; i < n; ++i)
    py[i] = drop_axis(*ring[i], axis).y;
  // 2: the sectors all below pi and turning one way, the ring winds around v as often as it
  // crosses the ray from v along the first projected axis; a sector from wi to w(i+1) crosses it
  // exactly when it starts below v in the second coordinate and ends level or above (turning
  // counter-clockwise; clockwise ones cross it from above, but a closed ring crosses the line
  // upward as often as downward): comparisons of doubles, no predicate.
  int crossings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    crossings += py[i] < oy && py[next[i]] >= oy ? 1 : 0;
  }
  if (crossings != 1) return false;
  // 3: every turn of the ring in space the same strict way.
  const Sign first_bend = bend(c[0], d[next[1]], apex, *ring[0], *ring[1], *ring[next[1]]);
  if (first_bend == Sign::zero) return false;
  for (std::size_t i = 1; i < n; ++i) {
    if (bend(c[i], d[next[next[i]]], apex, *ring[i], *ring[next[i]], *ring[next[next[i]]]) !=
        first_bend) {
      return false;
    }
  }
  if (out.stars != nullptr) {
    ScratchVector<std::array<std::int32_t, 3>>& across = out.stars->across;
    // Triangle i is v w(i) w(i + 1), its corner k at v: its edge (k + 2) mod 3 runs w(i + 1)
    // -> v, which is edge k' (v -> w(i + 1)) of triangle i + 1.
    for (std::size_t i = 0; i < n; ++i) {
      const std::int32_t from = star[order[i]].corner, to = star[order[next[i]]].corner;
      const std::size_t from_at = out.at(from / 3), to_at = out.at(to / 3);
      across[from_at][static_cast<std::size_t>((from % 3 + 2) % 3)] =
          static_cast<std::int32_t>(to_at);
      across[to_at][static_cast<std::size_t>(to % 3)] = static_cast<std::int32_t>(from_at);
      // Its turns in the three projections (the triangle v w(i) w(i + 1) is a rotation of its
      // corners, so each is the sign of strict_turns' orient2d): taken once, at its corner 0.
      if (from % 3 == 0) {
        unsigned bits = 0;
        for (int k = 0; k < 3; ++k) {
          const Sign s = k == axis ? first_turn : turn(c[i], k, apex, *ring[i], *ring[next[i]]);
          if (s == Sign::positive) bits |= 1U << (2 * k);
          if (s == Sign::negative) bits |= 1U << (2 * k + 1);
        }
        out.stars->turns[from_at] = static_cast<std::uint8_t>(bits);
      }
    }
  }
  return true;
}

// Whether each vertex is proven; with `out.stars`, the neighbours and turns of `proven_stars`; with
// `corners`, bit k of each triangle whose corner k is proven (made here, after the sort's
// buffers: below them, it would leave their memory a hole the next allocations may not fit).
std::vector<bool> proven_vertices_of(const Soup& soup, const StarOutput& out,
                                     ScratchVector<std::uint8_t>* corners) {
  const std::size_t vertices = soup.vertices.size();
  // The corners at each vertex (3 t + k: triangle t's corner k), by a counting sort, in
  // ascending order (a triangle naming a vertex twice is listed twice, and fails the turns).
  // Four bytes a corner, the link edges read from the triangles by proven_star for every star of
  // 3 to max_star corners, before its proof: a buffer of link edges (12 bytes a corner) was
  // 9.4 MB of fresh pages at a union of two 131k-triangle spheres, more than the proofs' own
  // work in page faults.
  ScratchVector<std::int32_t> start(vertices + 1, 0);
  for (const TriangleIndices& t : soup.triangles) {
    for (const std::int32_t i : t)
      ++start[static_cast<std::size_t>(i) + 1];
  }
  for (std::size_t i = 1; i <= vertices; ++i)
    start[i] += start[i - 1];
  ScratchVector<std::int32_t> star(static_cast<std::size_t>(start[vertices]));
  // Filled from the back, each bucket's end moving down to its start (no second array of
  // positions).
  for (std::size_t i = soup.triangles.size(); i-- > 0;) {
    const TriangleIndices& t = soup.triangles[i];
    for (std::size_t k = 3; k-- > 0;) {
      star[static_cast<std::size_t>(--start[static_cast<std::size_t>(t[k]) + 1])] =
          static_cast<std::int32_t>(3 * i + k);
    }
  }
  // start[v + 1] is now the start of v's bucket; v's bucket ends where v + 1's starts.
  std::vector<bool> proven(vertices, false);
  if (corners != nullptr) corners->assign(soup.triangles.size(), 0);
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto first = static_cast<std::size_t>(start[v + 1]);
    const auto end = v + 2 <= vertices ? static_cast<std::size_t>(start[v + 2]) : star.size();
    const std::span<const std::int32_t> at_v =
        std::span<const std::int32_t>(star).subspan(first, end - first);
    proven[v] = proven_star(soup, static_cast<std::int32_t>(v), at_v, out);
    // The triangles of a proven star marked at their corner v here, where the bits of every
    // triangle's three corners looked up afterwards was a second pass over the triangles.
    if (proven[v] && corners != nullptr) {
      for (const std::int32_t c : at_v) {
        std::uint8_t& bits = (*corners)[static_cast<std::size_t>(c / 3)];
        bits = static_cast<std::uint8_t>(bits | (1U << (c % 3)));
      }
    }
  }
  return proven;
}

}  // namespace

std::vector<bool> proven_vertices(const Soup& soup) {
  return proven_vertices_of(soup, {}, nullptr);
}

ScratchVector<std::uint8_t> proven_corners(const Soup& soup) {
  ScratchVector<std::uint8_t> corners;
  (void)proven_vertices_of(soup, {}, &corners);
  return corners;
}

ProvenStars proven_stars(const Soup& soup, StarOrder order) {
  ProvenStars stars;
  stars.across.assign(soup.triangles.size(), {-1, -1, -1});
  stars.turns.assign(soup.triangles.size(), 0);
  ScratchVector<std::int32_t> position;
  if (order == StarOrder::leaf) {
    const std::span<const std::int32_t> items = soup.tree.items();
    position.assign(soup.triangles.size(), -1);
    for (std::size_t k = 0; k < items.size(); ++k)
      position[static_cast<std::size_t>(items[k])] = static_cast<std::int32_t>(k);
  }
  (void)proven_vertices_of(soup, {&stars, position}, &stars.corners);
  return stars;
}

}  // namespace contain::clip::solid
