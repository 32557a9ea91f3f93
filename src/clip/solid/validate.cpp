// The exact check of the written mesh. Pairs of triangles whose boxes meet are tested on the
// written doubles (welded by position, so sheets kept apart at one position share corners) by
// the corners they share, with orient2d and orient3d signs only (meet_beyond_shared): first in
// one projection, where an edge line leaving the other triangle outside settles most pairs (a
// merged face's fan, pieces of one plane, neighbours across an edge) with a few orient2d, then
// as collide::self_intersections decides (predicates::triangles_meet_beyond_shared). It asks only
// whether two triangles meet, never where: no crossing point is made (the pair stage's enclosed
// crossings were two thirds of the check).
//
// Why the pairs of triangles with three kept corners need no test. The engine's exact result
// is conforming: each input triangle is refined by a constrained triangulation holding every
// intersection with every other triangle (the pair stage computes a pair's points and segment
// once and gives them to both triangles; the refinement gives a point on an input edge to every
// triangle on that edge), so two refined faces meet in a common vertex, a common edge or not at
// all. The boundary faces are some of them; merge_coplanar re-triangulates a region of one
// plane inside its own outline, keeping every outline point and every point another face uses,
// which keeps that property; the sheets only renumber vertices. A written triangle whose three
// corners are kept (each written exactly at its exact point, and no other point of the faces
// written at that position) is such an exact face at its exact position, never dropped nor
// cancelled by the merging of points (that needs a corner shared with another point). So two
// such triangles meet at shared corners or a shared edge, and the pair test, which depends only
// on the two triangles' positions, passes on them. Every other pair that meets holds a triangle
// r with a corner not kept; the other's box meets r's box, so both are in the local soup (the
// triangles whose boxes meet a box of such a triangle), welded by position as the full soup is,
// and tested as the full check tests them. The same holds in each snap-rounding round: the
// written mesh's own arrangement is exact and conforming in turn. The tests compare the
// restricted check with the full one on random and degenerate meshes.

#include "clip/solid/validate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/exact_point.h"
#include "contain/bvh/bvh.h"
#include "contain/core/location.h"
#include "contain/core/union_find.h"
#include "contain/inside/point_in_mesh.h"
#include "contain/predicates/big_float.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/triangles_meet.h"
#include "contain/values/box.h"
#include "contain/values/triangle.h"

namespace contain::clip::solid {
namespace {

using predicates::orient2d;

// The axis along which the triangle's normal is largest in doubles: a choice of projection only
// (the test below is exact whatever the axis; this one keeps the projection's area large).
int largest_axis(const std::array<Vec3, 3>& t) {
  const Vec3 n = cross(t[1] - t[0], t[2] - t[0]);
  const double x = std::fabs(n.x), y = std::fabs(n.y), z = std::fabs(n.z);
  return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

// Whether an edge line of a's projection (of orientation `turn`, not zero) has b's projected
// corners strictly outside a, but those b shares with a that are ends of that edge (corner m of
// b is corner b_in_a[m] of a, or -1). Then the projections meet only in the hull of those
// shared ends: U' lies in the closed outer half-plane touching the line only there.
bool edge_line_separates(const std::array<Vec2, 3>& a, Sign turn, const std::array<Vec2, 3>& b,
                         const std::array<int, 3>& b_in_a) {
  unsigned shared = 0;  // a's corners that b shares, as bits
  for (const int k : b_in_a) {
    if (k >= 0) shared |= 1U << static_cast<unsigned>(k);
  }
  for (unsigned i = 0; i < 3; ++i) {
    const unsigned j = (i + 1) % 3;
    // A shared corner off the edge (a's third corner) is inside: no orient2d asked then.
    if ((shared & ~((1U << i) | (1U << j))) != 0) continue;
    bool outside = true;
    for (std::size_t m = 0; m < 3 && outside; ++m) {
      if (b_in_a[m] >= 0) continue;  // a shared end of the edge: on the line
      const Sign side = orient2d(a[i], a[j], b[m]);
      outside = side != Sign::zero && side != turn;
    }
    if (outside) return true;
  }
  return false;
}

// The projection of a pair's test: the axis dropped (the first triangle's largest_axis), the
// orientation of the first triangle's projection, and of the second's when known (the same
// axis is its own largest: the signs are each triangle's, computed once per triangle).
struct Facing {
  int axis = 0;
  Sign turn_t = Sign::zero;
  std::optional<Sign> turn_u;
};

// The axis and orientation of a triangle's own projection.
std::pair<int, Sign> own_projection(const std::array<Vec3, 3>& t) {
  const int axis = largest_axis(t);
  return {axis, orient2d(drop_axis(t[0], axis), drop_axis(t[1], axis), drop_axis(t[2], axis))};
}

// A cheap sufficient test, exact: in the projection along `axis`, an edge line of one
// triangle's projection leaves the other's corners outside but for shared ends of that edge.
// Then the projections meet at most in the hull H of those shared corners, and so do the
// triangles: a common point z projects into H, onto the projection of some w of H; z and w lie
// in the triangle whose projection is not flat (exactly, by orient2d), on which the projection
// is one to one, so z = w. Triangles in one plane (merged faces, pieces of one input triangle,
// on which every orient3d is an exact zero) and neighbours across an edge are most of the pairs
// of the check, and are settled here by a few orient2d.
bool apart_in_projection(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u,
                         const std::array<int, 3>& t_in_u, const std::array<int, 3>& u_in_t,
                         const Facing& facing) {
  const int axis = facing.axis;
  const std::array<Vec2, 3> a = {drop_axis(t[0], axis), drop_axis(t[1], axis),
                                 drop_axis(t[2], axis)};
  const std::array<Vec2, 3> b = {drop_axis(u[0], axis), drop_axis(u[1], axis),
                                 drop_axis(u[2], axis)};
  if (facing.turn_t != Sign::zero && edge_line_separates(a, facing.turn_t, b, u_in_t)) return true;
  const Sign turn_b = facing.turn_u ? *facing.turn_u : orient2d(b[0], b[1], b[2]);
  return turn_b != Sign::zero && edge_line_separates(b, turn_b, a, t_in_u);
}

// Triangles t and u (not of zero area) meet beyond the corners they share (corner m of u is
// corner u_in_t[m] of t, or -1) and the edge they share, exactly: the projection test first,
// then predicates::triangles_meet_beyond_shared, the decision collide::self_intersections
// makes too. Three shared (the same triangle twice, either way round): they meet.
bool meet_beyond_shared(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u,
                        const std::array<int, 3>& u_in_t, const Facing& facing) {
  std::array<int, 3> t_in_u = {-1, -1, -1};
  int shared = 0;
  for (std::size_t m = 0; m < 3; ++m) {
    if (u_in_t[m] >= 0) {
      t_in_u[static_cast<std::size_t>(u_in_t[m])] = static_cast<int>(m);
      ++shared;
    }
  }
  if (shared == 3) return true;
  if (apart_in_projection(t, u, t_in_u, u_in_t, facing)) return false;
  return predicates::triangles_meet_beyond_shared({t[0], t[1], t[2]}, {u[0], u[1], u[2]}, u_in_t);
}

// meet_beyond_shared on triangles t and u of the local soup (shared corners by number: the
// soup is welded by position).
bool pair_meets(const Soup& soup, const std::vector<std::pair<int, Sign>>& projections,
                std::size_t t, std::size_t u) {
  const TriangleIndices& vt = soup.triangles[t];
  const TriangleIndices& vu = soup.triangles[u];
  std::array<Vec3, 3> a{}, b{};
  std::array<int, 3> u_in_t = {-1, -1, -1};
  for (std::size_t m = 0; m < 3; ++m) {
    a[m] = soup.vertices[static_cast<std::size_t>(vt[m])];
    b[m] = soup.vertices[static_cast<std::size_t>(vu[m])];
    for (std::size_t k = 0; k < 3; ++k) {
      if (vu[m] == vt[k]) u_in_t[m] = static_cast<int>(k);
    }
  }
  const auto [axis, turn_t] = projections[t];
  const Facing facing{
      axis, turn_t,
      projections[u].first == axis ? std::optional(projections[u].second) : std::nullopt};
  return meet_beyond_shared(a, b, u_in_t, facing);
}

Status failure(const std::string& what) {
  return Error{.kind = ErrorKind::degenerate,
               .message = "the result rounded to doubles is not valid (" + what + ")"};
}

// Every directed edge once and its reverse once: the edges grouped by their first vertex (a
// counting sort, each vertex's few ends sorted), then each reverse looked up in its group.
bool edges_matched(const Mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  std::vector<std::size_t> start(n + 1, 0);
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::int32_t v : t) {
      if (v < 0 || static_cast<std::size_t>(v) >= n) return false;
      ++start[static_cast<std::size_t>(v) + 1];
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    start[v + 1] += start[v];
  std::vector<std::int32_t> to(start[n]);
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::size_t k = 0; k < 3; ++k)
      to[next[static_cast<std::size_t>(t[k])]++] = t[(k + 1) % 3];
  }
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = to.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto last = to.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last);
    if (std::adjacent_find(first, last) != last) return false;  // an edge twice
  }
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t e = start[v]; e < start[v + 1]; ++e) {
      const auto w = static_cast<std::size_t>(to[e]);
      const auto first = to.begin() + static_cast<std::ptrdiff_t>(start[w]);
      const auto last = to.begin() + static_cast<std::ptrdiff_t>(start[w + 1]);
      if (!std::binary_search(first, last, static_cast<std::int32_t>(v))) return false;
    }
  }
  return true;
}

// The box of each written triangle, computed when asked (a stored box per triangle was 48
// bytes each, megabytes of fresh pages for a large result): empty for a zero-area triangle.
struct TriangleBoxes {
  const Mesh& mesh;
  const std::vector<char>& flat;  // zero area
  [[nodiscard]] std::size_t size() const { return flat.size(); }
  [[nodiscard]] Box3 operator[](std::size_t t) const {
    Box3 box;
    if (flat[t] != 0) return box;
    for (const std::int32_t v : mesh.triangles[t])
      box.expand(mesh.vertex(v));
    return box;
  }
};

// The triangles whose boxes meet the box of a triangle of `rounded` (those included): every
// triangle that can meet one of them. A hierarchy over the rounded triangles' boxes only, one
// query per triangle.
std::vector<std::int32_t> neighbourhood(const TriangleBoxes& boxes,
                                        const std::vector<std::int32_t>& rounded) {
  if (rounded.size() == boxes.size()) return rounded;
  std::vector<Box3> own;
  own.reserve(rounded.size());
  for (const std::int32_t t : rounded)
    own.push_back(boxes[static_cast<std::size_t>(t)]);
  // The linear build: the check's decisions do not depend on the tree, and the SAH's sweeps
  // were most of the hierarchy's cost here.
  const bvh::Bvh tree(own, {.method = bvh::BuildMethod::morton});
  std::vector<std::int32_t> near;
  for (std::size_t t = 0; t < boxes.size(); ++t) {
    const Box3 box = boxes[t];
    if (!tree.bounds().overlaps(box)) continue;
    const bvh::TraversalStats seen =
        tree.traverse([&](const bvh::Node& node, std::int32_t) { return node.box.overlaps(box); },
                      [&](std::int32_t i) {
                        return own[static_cast<std::size_t>(i)].overlaps(box) ? bvh::Visit::stop
                                                                              : bvh::Visit::proceed;
                      });
    if (seen.stopped) near.push_back(static_cast<std::int32_t>(t));
  }
  return near;
}

// The soup of the triangles `chosen` of the written mesh (none of zero area), welded by
// position as the pair stage needs: sheets kept apart at one position share corners there.
Soup local_soup(const Mesh& mesh, const std::vector<std::int32_t>& chosen,
                const TriangleBoxes& boxes) {
  Soup soup;
  soup.inputs = 1;
  // Welded by the flat table of the engine's soups (PointTable: +0 and -0 one key), not a
  // node-based map.
  soup.index.reserve(3 * chosen.size(), soup.vertices);
  soup.triangles.reserve(chosen.size());
  soup.input.assign(chosen.size(), 0);
  soup.degenerate.assign(chosen.size(), false);  // zero-area triangles are never chosen
  soup.boxes.reserve(chosen.size());
  for (const std::int32_t t : chosen) {
    TriangleIndices local{};
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3 v = mesh.vertex(mesh.triangles[static_cast<std::size_t>(t)][k]);
      const Vec3 key{v.x + 0.0, v.y + 0.0, v.z + 0.0};
      const auto [id, fresh] = soup.index.try_emplace(
          key, static_cast<std::int32_t>(soup.vertices.size()), soup.vertices);
      if (fresh) soup.vertices.push_back(key);
      local[k] = id;
    }
    soup.triangles.push_back(local);
    soup.boxes.push_back(boxes[static_cast<std::size_t>(t)]);
  }
  // The pairs' decisions do not depend on the tree: the linear build, as for large soups.
  soup.tree = bvh::Bvh(soup.boxes, {.method = bvh::BuildMethod::morton});
  return soup;
}

// The double sum of 6 V = a . (b - a) x (c - a) over some triangles, and the sum of the
// magnitudes of its products: the filter of volume_sign. Each term within 8 ulps of its
// magnitude, the sum within F ulps more.
struct VolumeSum {
  double sum = 0.0;
  double magnitude = 0.0;

  void add(Vec3 a, Vec3 b, Vec3 c) {
    const Vec3 u = b - a, w = c - a;
    const Vec3 n{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
    const Vec3 m{std::fabs(u.y * w.z) + std::fabs(u.z * w.y),
                 std::fabs(u.z * w.x) + std::fabs(u.x * w.z),
                 std::fabs(u.x * w.y) + std::fabs(u.y * w.x)};
    sum += a.x * n.x + a.y * n.y + a.z * n.z;
    magnitude += std::fabs(a.x) * m.x + std::fabs(a.y) * m.y + std::fabs(a.z) * m.z;
  }
};

// The sign of a shell's volume, exactly: 6 V = sum of a . (b - a) x (c - a) over its triangles,
// first in doubles with a bound on their error (`doubles`: that sum over the same triangles,
// made here or by the caller's own pass over them), then as exact numbers.
// The triangles are `triangle(0) ... triangle(count - 1)`.
template <class Triangle>
Sign volume_sign(const Mesh& mesh, std::size_t count, Triangle&& triangle,
                 std::optional<VolumeSum> doubles = std::nullopt) {
  if (!doubles) {
    doubles.emplace();
    for (std::size_t i = 0; i < count; ++i) {
      const TriangleIndices& v = mesh.triangles[triangle(i)];
      doubles->add(mesh.vertex(v[0]), mesh.vertex(v[1]), mesh.vertex(v[2]));
    }
  }
  const double sum = doubles->sum;
  const double bound = static_cast<double>(count + 16) * 0x1p-50 * doubles->magnitude;
  if (std::isfinite(bound) && bound >= std::numeric_limits<double>::min() &&
      std::fabs(sum) > bound) {
    return sum > 0 ? Sign::positive : Sign::negative;
  }
  predicates::BigFloat six;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t t = triangle(i);
    const TriangleIndices& v = mesh.triangles[t];
    const Vec3 a = mesh.vertex(v[0]);
    six = six + predicates::dot(predicates::to_big(a),
                                exact_normal(a, mesh.vertex(v[1]), mesh.vertex(v[2])));
  }
  return six.sign();
}

// The written mesh's shells (its triangles connected through shared vertex numbers: sheets kept
// apart are apart), with their boxes.
struct Shells {
  std::vector<std::vector<std::size_t>> triangles;
  std::vector<Box3> boxes;
  std::vector<std::size_t> of_vertex;  // the shell of each vertex used
};

Shells shells_of(const Mesh& mesh) {
  UnionFind<std::size_t> sets(mesh.vertices.size());
  for (const TriangleIndices& t : mesh.triangles) {
    sets.unite(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]));
    sets.unite(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[2]));
  }
  Shells out;
  constexpr std::size_t none = ~std::size_t{0};
  std::vector<std::size_t> number(mesh.vertices.size(), none);  // of each set's root
  out.of_vertex.assign(mesh.vertices.size(), none);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::size_t& shell = number[sets.find(static_cast<std::size_t>(mesh.triangles[t][0]))];
    if (shell == none) {
      shell = out.triangles.size();
      out.triangles.emplace_back();
      out.boxes.emplace_back();
    }
    out.triangles[shell].push_back(t);
    for (const std::int32_t v : mesh.triangles[t]) {
      out.boxes[shell].expand(mesh.vertex(v));
      out.of_vertex[static_cast<std::size_t>(v)] = shell;
    }
  }
  return out;
}

// Whether the triangles are connected through shared vertex numbers (one shell): a union-find
// of 32-bit vertex numbers, no lists of each shell's triangles nor boxes.
bool one_shell(const Mesh& mesh) {
  if (mesh.triangles.empty()) return false;
  UnionFind<std::uint32_t> sets(mesh.vertices.size());
  const auto at = [](std::int32_t v) { return static_cast<std::uint32_t>(v); };
  for (const TriangleIndices& t : mesh.triangles) {
    sets.unite(at(t[0]), at(t[1]));
    sets.unite(at(t[0]), at(t[2]));
  }
  const std::uint32_t first = sets.find(at(mesh.triangles[0][0]));
  return std::all_of(mesh.triangles.begin(), mesh.triangles.end(),
                     [&](const TriangleIndices& t) { return sets.find(at(t[0])) == first; });
}

// Shells that do not cross nor touch other than at shared positions bound nested regions; the
// winding number is 1 inside the result and 0 outside exactly when every shell s is outward
// (positive volume) with the other shells' solid outside it, or inward with the other shells'
// solid around it (by induction on the depth of nesting: the shells around a shell at even depth
// sum to 0, at odd depth to 1). The other shells' side is asked at a vertex of s whose position
// no other shell uses: such a vertex is on no other shell (its triangles would meet that shell
// beyond shared corners), and only shells whose boxes hold it can hold it.
bool oriented(const Mesh& mesh, const std::optional<VolumeSum>& whole, bool* one) {
  // One shell (most results): no other shell to ask about (every position is its own, so the
  // loop below would ask no shell at its free vertex and find it outside), so it is oriented
  // exactly when its volume is positive; the shells' lists and the table of positions are built
  // only for several.
  if (one_shell(mesh)) {
    if (one != nullptr) *one = true;
    return volume_sign(
               mesh, mesh.triangles.size(), [](std::size_t i) { return i; }, whole) ==
           Sign::positive;
  }
  const Shells shells = shells_of(mesh);
  // Each used vertex's position numbered by value (PointTable), and per position the first
  // shell met there and how many shell changes were seen at it (1: only one shell uses it).
  PointTable table;
  std::vector<Vec3> positions;
  std::vector<std::int32_t> position(mesh.vertices.size(), -1);
  std::vector<std::size_t> first, users;
  table.reserve(mesh.vertices.size(), positions);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (shells.of_vertex[v] == ~std::size_t{0}) continue;
    const Vec3 p = mesh.vertices[v] + Vec3{0, 0, 0};
    const auto [id, fresh] =
        table.try_emplace(p, static_cast<std::int32_t>(positions.size()), positions);
    if (fresh) {
      positions.push_back(p);
      first.push_back(shells.of_vertex[v]);
      users.push_back(0);
    }
    position[v] = id;
    const auto i = static_cast<std::size_t>(id);
    if (fresh || first[i] != shells.of_vertex[v]) ++users[i];
  }
  for (std::size_t s = 0; s < shells.triangles.size(); ++s) {
    const std::vector<std::size_t>& own = shells.triangles[s];
    const Sign volume = volume_sign(mesh, own.size(), [&](std::size_t i) { return own[i]; });
    if (volume == Sign::zero) return false;
    std::optional<Vec3> free;
    for (const std::size_t t : shells.triangles[s]) {
      for (const std::int32_t v : mesh.triangles[t]) {
        const auto i = static_cast<std::size_t>(position[static_cast<std::size_t>(v)]);
        if (!free && users[i] == 1) free = positions[i];
      }
    }
    if (!free) continue;  // every corner shared with another shell: not decided here
    Mesh around;
    for (std::size_t o = 0; o < shells.triangles.size(); ++o) {
      if (o == s || !shells.boxes[o].contains(*free)) continue;
      for (const std::size_t t : shells.triangles[o]) {
        const TriangleIndices& v = mesh.triangles[t];
        const auto base = static_cast<std::int32_t>(around.vertices.size());
        for (const std::int32_t i : v)
          around.vertices.push_back(mesh.vertex(i));
        around.triangles.push_back({base, base + 1, base + 2});
      }
    }
    const bool inside =
        !around.triangles.empty() && inside::point_in_mesh(around, *free) == Location::inside;
    if (inside != (volume == Sign::negative)) return false;
  }
  return true;
}
}  // namespace

bool written_pair_meets(const Triangle3& a, const Triangle3& b) {
  const std::array<Vec3, 3> t = {a.a, a.b, a.c}, u = {b.a, b.b, b.c};
  std::array<int, 3> u_in_t = {-1, -1, -1};
  for (std::size_t m = 0; m < 3; ++m) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (u[m] == t[k]) u_in_t[m] = static_cast<int>(k);
    }
  }
  const auto [axis, turn_t] = own_projection(t);
  return meet_beyond_shared(t, u, u_in_t, Facing{axis, turn_t, std::nullopt});
}

bool zero_area(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::zero &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::zero &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::zero;
}

namespace {

// The failure of a mesh whose shells do not bound a solid of winding numbers 0 and 1 (a shell
// turned inside out, shells nested in the same direction); every triangle is the region.
Status orientation(const Mesh& mesh, std::vector<std::int32_t>* crossing,
                   const std::optional<VolumeSum>& whole, bool* one_shell) {
  if (oriented(mesh, whole, one_shell)) return Ok{};
  for (std::size_t t = 0; crossing != nullptr && t < mesh.triangles.size(); ++t)
    crossing->push_back(static_cast<std::int32_t>(t));
  return failure("a shell is inside out, or nested in a shell of its own direction");
}

}  // namespace

Status check_written(const Mesh& mesh) {
  return check_written(mesh, std::vector<bool>(mesh.vertices.size(), false));
}

Status check_written(const Mesh& mesh, const std::vector<bool>& kept,
                     std::vector<std::int32_t>* crossing, Edges edges, bool* one_shell) {
  if (one_shell != nullptr) *one_shell = false;
  if (edges == Edges::checked && !edges_matched(mesh)) {
    // No pair is known to be the cause: every triangle is the region to repair.
    for (std::size_t t = 0; crossing != nullptr && t < mesh.triangles.size(); ++t)
      crossing->push_back(static_cast<std::int32_t>(t));
    return failure("an edge is not matched by exactly one opposite edge");
  }
  Status status = Ok{};
  std::vector<char> flat(mesh.triangles.size(), 0);  // zero area
  std::vector<std::int32_t> rounded;                 // triangles with a corner that is not kept
  // The orientation's volume filter summed in this pass over every triangle, in order (the
  // same sum as its own pass: the corners are read once, not twice).
  std::optional<VolumeSum> whole(std::in_place);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const TriangleIndices& v = mesh.triangles[t];
    const Vec3 a = mesh.vertex(v[0]), b = mesh.vertex(v[1]), c = mesh.vertex(v[2]);
    whole->add(a, b, c);
    if (zero_area(a, b, c)) {
      if (crossing == nullptr) return failure("a triangle has zero area");
      status = failure("a triangle has zero area");
      flat[t] = 1;
      continue;
    }
    if (!kept[static_cast<std::size_t>(v[0])] || !kept[static_cast<std::size_t>(v[1])] ||
        !kept[static_cast<std::size_t>(v[2])]) {
      rounded.push_back(static_cast<std::int32_t>(t));
    }
  }
  if (rounded.empty()) return status ? orientation(mesh, crossing, whole, one_shell) : status;
  const TriangleBoxes boxes{mesh, flat};
  const std::vector<std::int32_t> chosen = neighbourhood(boxes, rounded);
  const Soup soup = local_soup(mesh, chosen, boxes);
  // Pairs of two triangles with every corner kept need no test (above); each other pair whose
  // boxes meet is tested once.
  std::vector<bool> tested(chosen.size(), false);
  for (std::size_t i = 0, r = 0; i < chosen.size(); ++i) {
    while (r < rounded.size() && rounded[r] < chosen[i])
      ++r;
    tested[i] = r < rounded.size() && rounded[r] == chosen[i];
  }
  // Each tested triangle's own projection, once (not per pair).
  std::vector<std::pair<int, Sign>> projections(chosen.size());
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const TriangleIndices& v = soup.triangles[i];
    projections[i] = own_projection({soup.vertices[static_cast<std::size_t>(v[0])],
                                     soup.vertices[static_cast<std::size_t>(v[1])],
                                     soup.vertices[static_cast<std::size_t>(v[2])]});
  }
  std::vector<bool> bad(chosen.size(), false);
  const char* what = nullptr;
  (void)bvh::traverse_self(
      soup.tree, [](const bvh::Node& x, const bvh::Node& y) { return x.box.overlaps(y.box); },
      [&](std::int32_t i, std::int32_t j) {
        const auto t = static_cast<std::size_t>(std::min(i, j));
        const auto u = static_cast<std::size_t>(std::max(i, j));
        if ((!tested[t] && !tested[u]) || !soup.boxes[t].overlaps(soup.boxes[u])) {
          return bvh::Visit::proceed;
        }
        if (!pair_meets(soup, projections, t, u)) return bvh::Visit::proceed;
        what = "two triangles cross or overlap";
        bad[t] = true;
        bad[u] = true;
        return crossing == nullptr ? bvh::Visit::stop : bvh::Visit::proceed;
      });
  if (what != nullptr) {
    if (crossing == nullptr) return failure(what);
    status = failure(what);
  }
  for (std::size_t t = 0; t < bad.size(); ++t) {
    if (bad[t]) crossing->push_back(chosen[t]);
  }
  return status ? orientation(mesh, crossing, whole, one_shell) : status;
}

}  // namespace contain::clip::solid
