// Stage 2 of slicing: a plane's crossing segments, for the plane just above and just below.
//
// Rule slice-two-sides (docs/robustness.md): at the plane z = c + e (e -> 0+) a vertex with
// z == c is below; at z = c - e it is above. For either side every triangle with vertices on
// both sides is cut by the perturbed plane in a segment between its two crossing edges, and the
// segment's limit as e -> 0 joins the exact crossings of those edges with z = c (a vertex on the
// plane is its edges' crossing). The triangle's orientation directs it: from the edge going down
// (above to below along the triangle's boundary) to the edge going up, which runs
// counter-clockwise around the solid's section seen from +z (outward normal n: the tangent is
// z x n). A triangle in the plane has all vertices on one side and gives nothing.

#include <utility>

#include "clip/slice/stages.h"
#include "contain/predicates/rounded_crossing.h"

namespace contain::clip::slice {

namespace {

constexpr std::uint64_t kVertexTag = 0xFFFFFFFFULL;

std::uint64_t vertex_key(std::int32_t v) {
  return (static_cast<std::uint64_t>(v) << 32) | kVertexTag;
}

struct Crossing {
  std::uint64_t key;
  Vec2 point;
};

// The crossing of the edge p-q (one endpoint above, one below on the chosen side) with z = c.
// Each edge's point is computed once per plane (`memo`, by edge key), though every triangle on
// the edge (two on a manifold) and both sides ask for it.
Crossing crossing(const SweepMesh& mesh, std::int32_t p, std::int32_t q, double c,
                  KeyTable<Vec2>& memo) {
  const Vec3& a = mesh.vertices[static_cast<std::size_t>(p)];
  const Vec3& b = mesh.vertices[static_cast<std::size_t>(q)];
  if (a.z == c) return {vertex_key(p), {a.x, a.y}};
  if (b.z == c) return {vertex_key(q), {b.x, b.y}};
  const std::uint64_t key = edge_key(p, q);
  const auto [point, fresh] = memo.insert(key);
  if (fresh) {
    const Vec3 x = predicates::rounded_axis_crossing(a, b, 2, c);
    *point = {x.x, x.y};
  }
  return {key, *point};
}

// The segment of triangle t on one side (`on_plane_above`: where a vertex with z == c counts),
// appended to out when the triangle has vertices on both sides.
void add_segment(const SweepMesh& mesh, std::int32_t t, const double (&z)[3], double c,
                 bool on_plane_above, KeyTable<Vec2>& memo, std::vector<CrossingSegment>& out) {
  const TriangleIndices& tri = mesh.triangles[static_cast<std::size_t>(t)];
  bool above[3];
  for (int i = 0; i < 3; ++i)
    above[i] = on_plane_above ? z[i] >= c : z[i] > c;
  if (above[0] == above[1] && above[1] == above[2]) return;
  int down = -1;  // the edge i -> i+1 going from above to below
  int up = -1;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (above[i] && !above[j]) down = i;
    if (!above[i] && above[j]) up = i;
  }
  const Crossing from = crossing(mesh, tri[down], tri[(down + 1) % 3], c, memo);
  const Crossing to = crossing(mesh, tri[up], tri[(up + 1) % 3], c, memo);
  out.push_back({from.key, to.key, from.point, to.point, t});
}

}  // namespace

void crossing_segments(const SweepMesh& mesh, std::span<const std::int32_t> active, double c,
                       KeyTable<Vec2>& memo, PlaneCurves& out) {
  out.above.clear();
  out.below.clear();
  out.touches = false;
  memo.reset(2 * active.size());
  const auto heights = [&](std::int32_t t, double(&z)[3]) {
    const TriangleIndices& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (int i = 0; i < 3; ++i)
      z[i] = mesh.vertices[static_cast<std::size_t>(tri[i])].z;
  };
  for (const std::int32_t t : active) {
    double z[3];
    heights(t, z);
    out.touches = out.touches || z[0] == c || z[1] == c || z[2] == c;
    add_segment(mesh, t, z, c, false, memo, out.above);
  }
  if (out.touches) {
    for (const std::int32_t t : active) {
      double z[3];
      heights(t, z);
      add_segment(mesh, t, z, c, true, memo, out.below);
    }
  }
}

PlaneCurves crossing_segments(const SweepMesh& mesh, std::span<const std::int32_t> active,
                              double c) {
  KeyTable<Vec2> memo;
  PlaneCurves out;
  crossing_segments(mesh, active, c, memo, out);
  return out;
}

}  // namespace contain::clip::slice
