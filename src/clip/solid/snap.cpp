// Stage 7 of the mesh boolean: the exact result written as doubles, checked exactly, and
// repaired by iterated snap rounding where rounding broke it (rule solid-output in
// docs/robustness.md).
//
// Rounding each exact point to its nearest doubles moves it by at most half an ulp, but a
// sliver thinner than that can fold over, and faces can cross. As CGAL 6.1 does for triangle
// soups (autorefine_triangle_soup with snap rounding: cgal.org/2025/06/13/autorefine-and-snap,
// inria hal-04907149; round, find the new intersections, refine, round again), the rounded mesh
// is then refined exactly again: its crossings and overlaps become exact points and edges of
// its own arrangement (the engine's stages on the written mesh, kept as a union, so folds of
// zero volume vanish), which are rounded in turn. Each round moves the surface by at most half
// an ulp per coordinate. Rounds that still fail also merge points whose doubles are close on a
// grid growing from 2^2 to 2^20 ulps of the largest coordinate (hot cells: what meets one cell
// becomes one vertex), which removes the slivers that keep folding. The number of rounds is
// bounded, so this ends; a mesh is returned only when the exact check of its doubles passes.
//
// Surfaces a few ulps apart (a solid against itself turned a quarter, whose vertices differ in
// their last bits) cross at hundreds of points whose slivers fold again at every round, however
// the result's points are merged: the crossings are new points each time. There the inputs
// themselves are snapped (snap_inputs): their vertices merged on growing grids, which turns
// nearly coincident surfaces into coincident ones, and the exact boolean of the snapped inputs,
// an exact arrangement with no such slivers, goes through the same rounds. Surfaces turned
// by ~1e-9 (vertices millions of ulps apart) need grids of up to 2^28 ulps, which can move a
// vertex far beyond the promised 1e-9: those are used only when stable, and their results only
// when every written vertex is proven near the exact result's boundary (result_boundary.h). The
// attempts are bounded too (11 grids), so the whole ends.

#include "clip/solid/snap.h"

#include <algorithm>
#include <array>
#include <cassert>
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
#include "clip/solid/result_boundary.h"
#include "clip/solid/validate.h"
#include "contain/bvh/bvh.h"
#include "contain/core/sort_few.h"
#include "contain/core/union_find.h"
#include "contain/values/box.h"

namespace contain::clip::solid {
namespace {

// Points merged into one vertex (rule solid-output): faces that lose a corner so are dropped,
// and two faces that become the same triangle in opposite directions cancel. What this leaves
// is checked.
// Flat arrays indexed by point number, not a hash map: the written mesh of a large result has
// hundreds of thousands of points, and a node per point was a tenth of the whole boolean.
struct Representative {
  std::vector<std::int32_t> ids;  // the faces' points, ascending
  std::vector<std::int32_t> of;   // the written point of each of them (-1 for other points)
  [[nodiscard]] std::int32_t at(std::int32_t i) const { return of[static_cast<std::size_t>(i)]; }
};

// Faces that are the same triangle in opposite directions, grouped by their corners without a
// tree of keys: (a, min(b, c), max(b, c)) with a the smallest corner, then by face number.
struct CornerKey {
  std::array<std::int32_t, 3> key;
  std::uint32_t face;
  bool reversed;  // b > c in (a, b, c)
};

Faces merge_coincident(const Faces& faces, const Representative& rep) {
  Faces merged;
  merged.reserve(faces.size());
  for (const auto& f : faces) {
    std::array<std::int32_t, 3> t = {rep.at(f[0]), rep.at(f[1]), rep.at(f[2])};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    merged.push_back(t);
  }
  // Sorted by (key, face): a counting sort by the smallest corner, then each corner's few
  // faces sorted (one sort of every face was a twentieth of a large boolean).
  std::size_t points = 0;
  for (const auto& t : merged)
    points = std::max(points, static_cast<std::size_t>(t[0]) + 1);
  std::vector<std::size_t> start(points + 1, 0);
  for (const auto& t : merged)
    ++start[static_cast<std::size_t>(t[0]) + 1];
  for (std::size_t p = 0; p < points; ++p)
    start[p + 1] += start[p];
  std::vector<CornerKey> keys(merged.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const auto& t = merged[i];
    keys[next[static_cast<std::size_t>(t[0])]++] = {
        {t[0], std::min(t[1], t[2]), std::max(t[1], t[2])},
        static_cast<std::uint32_t>(i),
        t[1] > t[2]};
  }
  // By insertion (sort_few): a corner has a few faces, where std::sort's set-up cost more than
  // the sorting; (key, face) pairs are distinct, so any sort gives this order.
  for (std::size_t p = 0; p < points; ++p) {
    sort_few(keys.begin() + static_cast<std::ptrdiff_t>(start[p]),
             keys.begin() + static_cast<std::ptrdiff_t>(start[p + 1]), 16,
             [](const CornerKey& x, const CornerKey& y) {
               return x.key != y.key ? x.key < y.key : x.face < y.face;
             });
  }
  // Cancel opposite pairs in face order: a face cancels the latest still open face of the
  // other direction among the earlier ones (as a stack of each direction per key).
  std::vector<bool> gone(merged.size(), false);
  bool any_gone = false;
  std::array<std::vector<std::uint32_t>, 2> open;
  for (std::size_t i = 0, j = 0; i < keys.size(); i = j) {
    while (j < keys.size() && keys[j].key == keys[i].key)
      ++j;
    open[0].clear();
    open[1].clear();
    for (std::size_t k = i; k < j; ++k) {
      std::vector<std::uint32_t>& other = open[keys[k].reversed ? 0 : 1];
      if (!other.empty()) {
        gone[other.back()] = true;
        gone[keys[k].face] = true;
        any_gone = true;
        other.pop_back();
      } else {
        open[keys[k].reversed ? 1 : 0].push_back(keys[k].face);
      }
    }
  }
  if (!any_gone) return merged;  // most results: no copy
  Faces out;
  out.reserve(merged.size());
  for (std::size_t i = 0; i < merged.size(); ++i) {
    if (!gone[i]) out.push_back(merged[i]);
  }
  return out;
}

// The side of a hot cell at merge level `level`: ulp(scale) 2^level.
double cell_side(int level, double scale) {
  return std::ldexp(std::nextafter(scale, std::numeric_limits<double>::infinity()) - scale, level);
}

}  // namespace

std::optional<std::vector<std::size_t>> cluster_points(std::span<const Vec3> points, double h) {
  std::vector<std::size_t> by_x(points.size());
  for (std::size_t k = 0; k < by_x.size(); ++k)
    by_x[k] = k;
  std::sort(by_x.begin(), by_x.end(),
            [&](std::size_t a, std::size_t b) { return points[a].x < points[b].x; });
  UnionFind<std::size_t> near(points.size());  // the smallest index leads
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Vec3 p = points[by_x[k]];
    for (std::size_t m = k + 1; m < by_x.size(); ++m) {
      const Vec3 q = points[by_x[m]];
      if (q.x - p.x > h) break;
      if (std::fabs(q.y - p.y) <= h && std::fabs(q.z - p.z) <= h) near.unite(by_x[k], by_x[m]);
    }
  }
  // A chain of close points can join a wide cluster: a grid whose clusters move a point by more
  // than 2h in a coordinate is not used, so that a merge moves a point by at most 2h in each
  // coordinate.
  std::vector<std::size_t> leader(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    leader[k] = near.find(k);
    const Vec3 a = points[k], b = points[leader[k]];
    if (std::fabs(a.x - b.x) > 2 * h || std::fabs(a.y - b.y) > 2 * h ||
        std::fabs(a.z - b.z) > 2 * h) {
      return std::nullopt;
    }
  }
  return leader;
}

namespace {

// The written point of each point of `faces`: at level < 0, the first point with the same
// nearest doubles (the written mesh could not tell them apart); at level >= 0, the first point
// (by number) of its cluster: points whose nearest doubles are within ulp(scale) 2^level of each
// other in every coordinate are joined, transitively (the hot cells of a snap-rounding round).
// A level whose clusters are too wide (cluster_points) is not used: the rounds together then
// move a vertex by less than sqrt(3) (2^3 + 2^6 + ... + 2^21) ulps of the largest coordinate
// (< 9.3e-10 of it, within the spec's 1e-9; the half-ulp roundings add a negligible 5 ulps).
Representative representatives(const Faces& faces, const PointStore& store, int level,
                               double scale) {
  // The faces' points ascending, by marks in point order (a sort of every corner was a
  // twentieth of a large boolean).
  Representative rep;
  rep.of.assign(store.size(), -1);
  for (const auto& f : faces) {
    for (const std::int32_t i : f)
      rep.of[static_cast<std::size_t>(i)] = 0;
  }
  std::vector<std::int32_t> ids;
  for (std::size_t i = 0; i < rep.of.size(); ++i) {
    if (rep.of[i] == 0) ids.push_back(static_cast<std::int32_t>(i));
  }
  if (level >= 0) {
    std::vector<Vec3> points;
    points.reserve(ids.size());
    for (const std::int32_t i : ids)
      points.push_back(store.rounded(i));
    const std::optional<std::vector<std::size_t>> leader =
        cluster_points(points, cell_side(level, scale));
    if (leader) {
      for (std::size_t k = 0; k < ids.size(); ++k)
        rep.of[static_cast<std::size_t>(ids[k])] = ids[(*leader)[k]];
      rep.ids = std::move(ids);
      return rep;
    }
  }
  for (const std::int32_t i : ids)
    rep.of[static_cast<std::size_t>(i)] = store.representative(i);
  rep.ids = std::move(ids);
  return rep;
}

// The mesh and which of its vertices are kept for check_written: the one point of the faces
// merged into it, written exactly.
struct Written {
  Mesh mesh;
  std::vector<bool> kept;
  Edges edges = Edges::checked;  // known_matched when the sheets found every edge paired
};

// The faces' mesh with points merged by `rep`, sheets kept apart.
Written written_mesh(const Faces& kept, const Representative& rep, const PointStore& store) {
  const Sheets sheets = separate_sheets(merge_coincident(kept, rep), store);
  std::vector<int> merged(store.size(), 0);  // points merged into each representative
  for (const std::int32_t point : rep.ids)
    merged[static_cast<std::size_t>(rep.at(point))] += store.written_exactly(point) ? 1 : 2;
  Written out;
  out.edges = sheets.paired ? Edges::known_matched : Edges::checked;
  out.mesh.vertices.reserve(sheets.points.size());
  out.kept.reserve(sheets.points.size());
  for (const std::int32_t p : sheets.points) {
    out.mesh.vertices.push_back(store.rounded(p));
    out.kept.push_back(merged[static_cast<std::size_t>(p)] == 1);
  }
  out.mesh.triangles.reserve(sheets.faces.size());
  for (const auto& t : sheets.faces)
    out.mesh.triangles.push_back({t[0], t[1], t[2]});
  return out;
}

// The merge level of each repair round: rounding alone first, then grids of 2^2 ... 2^20 ulps.
constexpr std::array<int, 10> round_levels = {-1, -1, -1, 2, 5, 8, 11, 14, 17, 20};

// The soup with a hierarchy over the triangles of `region` only (the others get empty boxes):
// the pair stage on it tests just their pairs, with the soup's own vertex and triangle numbers.
Soup region_soup(const Soup& soup, const std::vector<std::int32_t>& region) {
  assert(soup.boxes.empty() || soup.boxes.size() == soup.triangles.size());
  Soup out;
  out.vertices = soup.vertices;
  out.triangles = soup.triangles;
  out.input = soup.input;
  out.degenerate = soup.degenerate;
  out.inputs = soup.inputs;
  out.boxes.assign(soup.triangles.size(), Box3{});
  for (const std::int32_t t : region)
    out.boxes[static_cast<std::size_t>(t)] = soup.boxes.empty()
                                                 ? triangle_box(soup, static_cast<std::size_t>(t))
                                                 : soup.boxes[static_cast<std::size_t>(t)];
  out.tree = bvh::Bvh(out.boxes);
  return out;
}

// The faces of `op` on the soup's arrangement, given its pair stage's work: the refined faces on
// the boundary, merged where coplanar.
Faces arranged_faces(const Soup& soup, const PairWork& work, PointStore& store, Op op) {
  const Refinement refinement = refine(soup, work, store);
  const FaceLabels labels = label_faces(soup, refinement, store);
  const BoundaryFaces boundary = boundary_faces(soup, refinement, work, labels, store, op);
  return merge_coplanar(soup, boundary, store);
}

// A snap round that grows the work instead of mending (rule solid-output): the faces of nearly
// coincident surfaces (a torus minus itself turned a quarter) folded by rounding and merging
// cross by the thousand, and refining such a round (hundreds of crossings in one triangle) or
// the next ones runs for minutes. The bounds, with F the first written mesh's triangles: a
// round writes at most 2 F + 64 triangles, and its pair stage (before refining) finds at most
// 8 (2 F + 64) new crossings in all and at most 32 in one triangle. The rounds that mend have
// found a few crossings per triangle; those that do not grow them round after round (a sphere
// against its copy turned by 1e-9: 50, 80, 223), and with the inputs snapped on coarser grids
// behind them, ending sooner costs no result and halves the time of such a failure.
constexpr std::size_t max_crossings_in_one = 32;

Error not_converging(std::size_t found, const char* what, std::size_t bound) {
  return Error{.kind = ErrorKind::degenerate,
               .message =
                   "the result rounded to doubles is not valid, and snap rounding does "
                   "not converge: a round " +
                   std::string(what) + " " + std::to_string(found) + " (more than " +
                   std::to_string(bound) + ")"};
}

// The written mesh's own arrangement, exactly, kept as a union (the solid where its winding
// number is positive) and written at merge `level`. Only the pairs of triangles of `crossing`
// (those of the pairs the check found meeting wrongly; every triangle after an edge failure)
// are intersected: every other pair meets at shared corners or a shared edge, where the pair
// stage finds nothing to add (coplanar neighbours that do not overlap give each other edges
// that have no piece inside them), and zero-area triangles are never intersected, so the
// arrangement is the one of all pairs, at the cost of the few (none when the check failed only
// on zero-area triangles: the round then drops them, they bound nothing). The labels still cast
// their rays through the whole mesh.
Result<Written> resolved(const Mesh& mesh, const std::vector<std::int32_t>& crossing, int level,
                         double scale, std::size_t limit) {
  Result<Soup> soup = make_soup(std::span<const Mesh>(&mesh, 1));
  if (!soup) return soup.error();
  PointStore store;
  store.add_vertices(*soup, std::move(soup->index));
  const PairWork work = crossing.size() == soup->triangles.size()
                            ? intersect_pairs(*soup, store)
                            : intersect_pairs(region_soup(*soup, crossing), store);
  std::size_t constraints = 0, most = 0;
  for (std::size_t t = 0; t < work.size(); ++t) {
    constraints += work[t].constraints.size();
    most = std::max(most, work[t].constraints.size());
  }
  if (most > max_crossings_in_one) {
    return not_converging(most, "found new crossings in one triangle:", max_crossings_in_one);
  }
  if (constraints > 8 * limit)
    return not_converging(constraints, "found new crossings:", 8 * limit);
  // And at most 8 per triangle of the region (+ 64): crossings of a round's constraints with
  // each other grow as their square, and a round past this (a torus against a copy turned by
  // 1e-8: 928 crossings in 84 triangles, 30 in some) refined for seconds, then failed anyway.
  const std::size_t per_region = 8 * crossing.size() + 64;
  if (constraints > per_region)
    return not_converging(constraints, "found new crossings in its region:", per_region);
  const Faces faces = arranged_faces(*soup, work, store, Op::union_);
  return written_mesh(faces, representatives(faces, store, level, scale), store);
}

}  // namespace

Result<Mesh> snap_round(const Faces& faces, const PointStore& store, double scale,
                        std::size_t* rounds, bool* one_shell) {
  Written written = written_mesh(faces, representatives(faces, store, -1, scale), store);
  std::vector<std::int32_t> crossing;
  Status valid = check_written(written.mesh, written.kept, &crossing, written.edges, one_shell);
  const std::size_t limit = 2 * written.mesh.triangles.size() + 64;
  for (std::size_t round = 0; !valid && round < round_levels.size(); ++round) {
    if (rounds != nullptr) *rounds = round + 1;
    Result<Written> next = resolved(written.mesh, crossing, round_levels[round], scale, limit);
    if (!next) return next.error();
    written = std::move(*next);
    if (written.mesh.triangles.size() > limit) {
      return not_converging(written.mesh.triangles.size(), "wrote triangles:", limit);
    }
    crossing.clear();
    valid = check_written(written.mesh, written.kept, &crossing, written.edges, one_shell);
  }
  if (!valid) {
    return Error{.kind = ErrorKind::degenerate,
                 .message = valid.error().message + ", and " + std::to_string(round_levels.size()) +
                            " rounds of snap rounding (points merged up to 2^20 ulps of the "
                            "largest coordinate) did not mend it"};
  }
  return std::move(written.mesh);
}

namespace {

// The merge levels of the inputs' vertices when snap rounding of the result does not converge.
// A vertex moves by at most 2^(level + 1) ulps of the largest coordinate per coordinate; with the
// result's own rounds after it (< 9.3e-10 of the largest coordinate), 2^16 keeps every written
// vertex within 1e-9 of it. The coarser grids (up to 2^28 ulps: a vertex moves by up to 2^29
// ulps, < 1.2e-7 of the largest coordinate) join surfaces turned or shifted by up to ~1e-8 (a
// sphere against a copy turned by 1e-9 radians, whose crossings at angles of 1e-9 fold at every
// round); they have no such bound, so a grid there is used only when it is stable and its
// result only when proven near the exact one (result_boundary.h).
constexpr std::array<int, 11> input_levels = {2, 6, 10, 14, 16, 18, 20, 22, 24, 26, 28};
constexpr int finest_unproven_level = 16;

// The bound on the distance from each written vertex to the exact result's boundary, relative
// to the largest coordinate: the spec's 1e-9, less a margin.
constexpr double proven_distance = 0.999e-9;

}  // namespace

std::optional<Soup> snapped_soup(const Soup& soup, int level, double scale) {
  const std::optional<std::vector<std::size_t>> leader =
      cluster_points(soup.vertices, cell_side(level, scale));
  if (!leader) return std::nullopt;
  if (level > finest_unproven_level) {
    // Stable: the clusters are those of a grid 8 times coarser, so no cluster is split where
    // its points happen to straddle a side (the twin vertices of two nearly equal surfaces
    // joined, not some of them), and far vertices stay apart by more than 8 sides.
    const std::optional<std::vector<std::size_t>> coarse =
        cluster_points(soup.vertices, cell_side(level + 3, scale));
    if (!coarse || *coarse != *leader) return std::nullopt;
  }
  Soup out;
  out.inputs = soup.inputs;
  out.input = soup.input;
  std::vector<std::int32_t> number(soup.vertices.size(), -1);
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    const std::size_t lead = (*leader)[v];
    if (number[lead] < 0) {
      number[lead] = static_cast<std::int32_t>(out.vertices.size());
      out.vertices.push_back(soup.vertices[lead]);
    }
    number[v] = number[lead];
  }
  if (out.vertices.size() == soup.vertices.size()) return std::nullopt;  // nothing merged
  out.triangles.reserve(soup.triangles.size());
  for (const TriangleIndices& t : soup.triangles) {
    const TriangleIndices m = {number[static_cast<std::size_t>(t[0])],
                               number[static_cast<std::size_t>(t[1])],
                               number[static_cast<std::size_t>(t[2])]};
    const Vec3 a = out.vertices[static_cast<std::size_t>(m[0])];
    const Vec3 b = out.vertices[static_cast<std::size_t>(m[1])];
    const Vec3 c = out.vertices[static_cast<std::size_t>(m[2])];
    out.triangles.push_back(m);
    out.degenerate.push_back(zero_area(a, b, c));
    Box3 box;  // empty for a degenerate triangle: it meets nothing
    if (!out.degenerate.back()) {
      box.expand(a);
      box.expand(b);
      box.expand(c);
    }
    out.boxes.push_back(box);
  }
  out.tree = bvh::Bvh(out.boxes);
  return out;
}

Result<Mesh> snap_inputs(const Soup& soup, Op op, double scale, const Faces& exact_faces,
                         const PointStore& exact_store, Error failure) {
  for (const int level : input_levels) {
    const std::optional<Soup> snapped = snapped_soup(soup, level, scale);
    if (!snapped) continue;
    PointStore store;
    for (const Vec3 v : snapped->vertices)
      (void)store.add(v);
    const PairWork work = intersect_pairs(*snapped, store);
    Result<Mesh> mesh = snap_round(arranged_faces(*snapped, work, store, op), store, scale);
    if (mesh && level > finest_unproven_level &&
        !within_boundary(*mesh, exact_faces, exact_store, proven_distance * scale, scale)) {
      mesh = Error{.kind = ErrorKind::degenerate,
                   .message = "the result of the inputs merged on a grid of 2^" +
                              std::to_string(level) +
                              " ulps is not proven within 1e-9 of the exact result"};
    }
    if (mesh || mesh.error().kind != ErrorKind::degenerate) return mesh;
    failure = mesh.error();
  }
  failure.message += ", also with the inputs' vertices merged on grids up to 2^28 ulps";
  return failure;
}

}  // namespace contain::clip::solid
