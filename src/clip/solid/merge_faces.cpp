// Stage 6b of the mesh boolean: coplanar output faces merged (rule solid-output in
// docs/robustness.md). Each face of the result is a piece of an input triangle; the pieces of one
// plane that meet across an edge (held by just those two faces, in opposite directions, their
// third corners on opposite sides of it) form a region, and a region with points inside it that
// no other face uses is triangulated again without them: the constrained triangulation of its
// boundary edges and its remaining points inside an enclosing triangle (triangulate.cpp, exact
// orientations of the implicit points), the region's triangles found by a walk from its boundary
// edges that never crosses one. Every point on a region's boundary stays (neighbouring faces
// hold it: dropping it would open the mesh), so the surface is the same point set, closed by
// point number as before.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/edge_uses.h"
#include "clip/solid/engine.h"
#include "clip/solid/snap.h"
#include "contain/core/union_find.h"
#include "contain/predicates/orient3d.h"

namespace contain::clip::solid {
namespace {

using Face = std::array<std::int32_t, 3>;
using ScratchUnionFind = UnionFind<std::size_t, ScratchAllocator<std::size_t>>;

std::uint64_t directed_key(std::int32_t a, std::int32_t b) {
  return (std::uint64_t{static_cast<std::uint32_t>(a)} << 32U) | static_cast<std::uint32_t>(b);
}

// Input triangles t and u lie in one plane.
bool same_plane(const Soup& soup, std::int32_t t, std::int32_t u) {
  if (t == u) return true;
  const TriangleIndices& a = soup.triangles[static_cast<std::size_t>(t)];
  const TriangleIndices& b = soup.triangles[static_cast<std::size_t>(u)];
  const auto at = [&](std::int32_t i) { return soup.vertices[static_cast<std::size_t>(i)]; };
  for (std::size_t k = 0; k < 3; ++k) {
    // A shared corner is on the plane: no test (an exact zero is the filter's slowest case).
    if (b[k] == a[0] || b[k] == a[1] || b[k] == a[2]) continue;
    if (predicates::orient3d(at(a[0]), at(a[1]), at(a[2]), at(b[k])) != Sign::zero) return false;
  }
  return true;
}

// The faces joined into regions: across edges held by exactly two faces in opposite
// directions, of one plane, lying on the two sides of the edge.
ScratchUnionFind regions(const Soup& soup, const BoundaryFaces& boundary, const PointStore& store) {
  // Every edge use, grouped by edge: flat arrays, not a map of vectors (one allocation per edge
  // was a tenth of the boolean).
  const EdgeUses uses = edge_uses(boundary.faces.size(),
                                  [&](std::size_t f) -> const Face& { return boundary.faces[f]; });
  ScratchUnionFind sets(boundary.faces.size());
  for_each_edge(uses, [&](std::int32_t lo, std::int32_t hi, std::span<const std::uint64_t> group) {
    if (group.size() != 2) return;
    const std::size_t f = EdgeUses::face(group[0]), g = EdgeUses::face(group[1]);
    const Face& a = boundary.faces[f];
    const Face& b = boundary.faces[g];
    const int i = corner_of_edge(a, lo, hi, 0), j = corner_of_edge(b, lo, hi, f == g ? 1 : 0);
    const std::int32_t p = a[static_cast<std::size_t>(i)],
                       q = a[static_cast<std::size_t>((i + 1) % 3)];
    if (b[static_cast<std::size_t>(j)] != q) return;  // same direction: not one oriented plane
    if (!same_plane(soup, boundary.triangle[f], boundary.triangle[g])) return;
    const int axis = soup.projection(static_cast<std::size_t>(boundary.triangle[f])).axis;
    const std::int32_t r = a[static_cast<std::size_t>((i + 2) % 3)];
    const std::int32_t s = b[static_cast<std::size_t>((j + 2) % 3)];
    const int sr = to_int(orient2d_dropped(store.point(p), store.point(q), store.point(r), axis));
    const int ss = to_int(orient2d_dropped(store.point(p), store.point(q), store.point(s), axis));
    if (sr * ss < 0) sets.unite(f, g);
  });
  return sets;
}

// Corners, counter-clockwise in the projection dropping `axis`, of a triangle of doubles whose
// projection holds every point of `ids` well inside (the exact points are within half an ulp of
// their nearest doubles).
Face enclosing(const std::vector<std::int32_t>& ids, PointStore& store, int axis) {
  const auto uv = [axis](Vec3 v) {
    const double c[3] = {v.x, v.y, v.z};
    return std::array<double, 2>{c[(axis + 1) % 3], c[(axis + 2) % 3]};
  };
  std::array<double, 2> lo = uv(store.rounded(ids[0])), hi = lo;
  for (const std::int32_t i : ids) {
    const auto p = uv(store.rounded(i));
    for (std::size_t k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double cu = 0.5 * (lo[0] + hi[0]), cv = 0.5 * (lo[1] + hi[1]);
  const double r = 2.0 * std::max(hi[0] - lo[0], hi[1] - lo[1]) +
                   1e-10 * (std::fabs(cu) + std::fabs(cv)) + 1e-290;
  const auto point = [&](double u, double v) {
    double c[3] = {0.0, 0.0, 0.0};
    c[(axis + 1) % 3] = u;
    c[(axis + 2) % 3] = v;
    return store.add(Vec3{c[0], c[1], c[2]});
  };
  return {point(cu - 4 * r, cv - 2 * r), point(cu + 4 * r, cv - 2 * r), point(cu, cv + 4 * r)};
}

// The region's triangles of the constrained triangulation `tris` (counter-clockwise in the
// projection): those reached from the boundary edges' inner sides without crossing a boundary
// edge, turned to the region's orientation. Nothing when a walk reaches the enclosing corners.
std::optional<std::vector<Face>> inside(const std::vector<Face>& tris,
                                        const std::vector<std::uint64_t>& outline, bool positive,
                                        const Face& corners) {
  // Sorted arrays, not hash tables: a region has a few dozen edges, and the tables' nodes were
  // most of the merging's time. Each directed edge of a triangulation is in one triangle.
  std::vector<std::pair<std::uint64_t, std::size_t>> by_edge;
  by_edge.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k)
      by_edge.emplace_back(directed_key(tris[t][k], tris[t][(k + 1) % 3]), t);
  }
  std::sort(by_edge.begin(), by_edge.end());
  const auto triangle_of = [&](std::uint64_t key) -> std::optional<std::size_t> {
    const auto it = std::lower_bound(by_edge.begin(), by_edge.end(),
                                     std::pair<std::uint64_t, std::size_t>{key, 0});
    if (it == by_edge.end() || it->first != key) return std::nullopt;
    return it->second;
  };
  std::vector<std::uint64_t> walls;
  walls.reserve(outline.size());
  std::vector<std::size_t> stack;
  for (const std::uint64_t e : outline) {
    const auto a = static_cast<std::int32_t>(e >> 32U), b = static_cast<std::int32_t>(e);
    walls.push_back(edge_key(a, b));
    const std::optional<std::size_t> t =
        triangle_of(positive ? directed_key(a, b) : directed_key(b, a));
    if (!t) return std::nullopt;  // not an edge: the pieces were not recovered
    stack.push_back(*t);
  }
  std::sort(walls.begin(), walls.end());
  std::vector<bool> seen(tris.size(), false);
  std::vector<Face> out;
  while (!stack.empty()) {
    const std::size_t t = stack.back();
    stack.pop_back();
    if (seen[t]) continue;
    seen[t] = true;
    const Face& v = tris[t];
    for (const std::int32_t c : corners) {
      if (std::find(v.begin(), v.end(), c) != v.end()) return std::nullopt;
    }
    out.push_back(positive ? v : Face{v[0], v[2], v[1]});
    for (std::size_t k = 0; k < 3; ++k) {
      if (std::binary_search(walls.begin(), walls.end(), edge_key(v[k], v[(k + 1) % 3]))) continue;
      if (const std::optional<std::size_t> across = triangle_of(directed_key(v[(k + 1) % 3], v[k])))
        stack.push_back(*across);
    }
  }
  return out;
}

// Region `faces` (indices into `all`) triangulated again without `dropped` points, or nothing
// when there is nothing to drop or the walk failed (the faces are then kept as they are).
std::optional<std::vector<Face>> retriangulated(const Soup& soup, const BoundaryFaces& all,
                                                const std::vector<std::size_t>& faces,
                                                const std::vector<std::int32_t>& keep,
                                                const std::vector<std::uint64_t>& outline,
                                                PointStore& store) {
  const Face& first = all.faces[faces[0]];
  const int axis = soup.projection(static_cast<std::size_t>(all.triangle[faces[0]])).axis;
  const bool positive = orient2d_dropped(store.point(first[0]), store.point(first[1]),
                                         store.point(first[2]), axis) == Sign::positive;
  std::vector<std::array<std::int32_t, 2>> pieces;
  for (const std::uint64_t e : outline)
    pieces.push_back({static_cast<std::int32_t>(e >> 32U), static_cast<std::int32_t>(e)});
  const Face corners = enclosing(keep, store, axis);
  const std::vector<Face> tris = triangulate(corners, keep, pieces, store, axis, Sign::positive);
  return inside(tris, outline, positive, corners);
}

// The faces of one region (of `leader`, more than one face or a face with a repeated corner)
// appended to `out`: merged when it holds points no other region uses, as they are otherwise.
void merge_region(const Soup& soup, const BoundaryFaces& boundary,
                  std::span<const std::size_t> region, std::size_t leader,
                  const ScratchVector<std::size_t>& owner, PointStore& store, Faces& out) {
  const std::vector<std::size_t> faces(region.begin(), region.end());
  // Sorted arrays, not hash sets (a region holds a few dozen edges).
  std::vector<std::uint64_t> directed;
  directed.reserve(3 * faces.size());
  for (const std::size_t f : faces) {
    const Face& v = boundary.faces[f];
    for (std::size_t k = 0; k < 3; ++k)
      directed.push_back(directed_key(v[k], v[(k + 1) % 3]));
  }
  std::sort(directed.begin(), directed.end());
  directed.erase(std::unique(directed.begin(), directed.end()), directed.end());
  std::vector<std::uint64_t> outline;  // directed edges whose reverse is in no region face
  std::vector<std::int32_t> on_outline;
  for (const std::uint64_t e : directed) {
    const auto a = static_cast<std::int32_t>(e >> 32U), b = static_cast<std::int32_t>(e);
    if (std::binary_search(directed.begin(), directed.end(), directed_key(b, a))) continue;
    outline.push_back(e);  // ascending, as `directed`
    on_outline.push_back(a);
    on_outline.push_back(b);
  }
  std::sort(on_outline.begin(), on_outline.end());
  std::vector<std::int32_t> keep;
  bool drops = false;
  for (const std::size_t f : faces) {
    for (const std::int32_t p : boundary.faces[f]) {
      if (std::binary_search(on_outline.begin(), on_outline.end(), p) ||
          owner[static_cast<std::size_t>(p)] != leader) {
        keep.push_back(p);
      } else {
        drops = true;
      }
    }
  }
  std::sort(keep.begin(), keep.end());
  keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
  std::optional<std::vector<Face>> merged;
  if (drops) merged = retriangulated(soup, boundary, faces, keep, outline, store);
  if (merged) {
    out.insert(out.end(), merged->begin(), merged->end());
  } else {
    for (const std::size_t f : faces)
      out.push_back(boundary.faces[f]);
  }
}

// The region of each point (by point number), or `shared` when faces of several regions hold
// it; `shared` too for points no face holds.
ScratchVector<std::size_t> point_owners(const BoundaryFaces& boundary,
                                        const ScratchVector<std::size_t>& leader,
                                        std::size_t points, std::size_t shared) {
  const std::size_t none = shared - 1;
  ScratchVector<std::size_t> owner(points, none);
  for (std::size_t f = 0; f < boundary.faces.size(); ++f) {
    for (const std::int32_t p : boundary.faces[f]) {
      std::size_t& o = owner[static_cast<std::size_t>(p)];
      o = (o == none || o == leader[f]) ? leader[f] : shared;
    }
  }
  return owner;
}

bool distinct_corners(const Face& v) {
  return v[0] != v[1] && v[1] != v[2] && v[2] != v[0];
}

}  // namespace

Faces merge_coplanar(const Soup& soup, const BoundaryFaces& boundary, PointStore& store) {
  ScratchUnionFind sets = regions(soup, boundary, store);
  const std::size_t n = boundary.faces.size();
  // Each region's faces in ascending order, the regions by their leaders (their smallest face):
  // flat arrays by counting, as deterministic as the order of the leaders.
  ScratchVector<std::size_t> leader(n), start(n + 1, 0);
  bool merges = false;
  for (std::size_t f = 0; f < n; ++f) {
    leader[f] = sets.find(f);
    ++start[leader[f] + 1];
    merges = merges || leader[f] != f || !distinct_corners(boundary.faces[f]);
  }
  for (std::size_t f = 0; f < n; ++f)
    start[f + 1] += start[f];
  ScratchVector<std::size_t> members(n), fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < n; ++f)
    members[fill[leader[f]]++] = f;
  constexpr std::size_t shared = std::numeric_limits<std::size_t>::max();
  // Only regions of several faces read the owners: most outputs (no coplanar faces) skip them.
  const ScratchVector<std::size_t> owner =
      merges ? point_owners(boundary, leader, store.size(), shared) : ScratchVector<std::size_t>{};
  Faces out;
  out.reserve(n);
  for (std::size_t l = 0; l < n; ++l) {
    const std::size_t count = start[l + 1] - start[l];
    if (count == 0) continue;
    if (count == 1 && distinct_corners(boundary.faces[l])) {
      out.push_back(boundary.faces[l]);  // its own region: every corner on its outline
      continue;
    }
    merge_region(soup, boundary, std::span(members).subspan(start[l], count), l, owner, store, out);
  }
  return out;
}

}  // namespace contain::clip::solid
