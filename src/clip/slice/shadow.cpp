// The shadow of a solid: the union of its triangles projected along the axis.
//
// For a closed mesh the triangles facing +axis cover the shadow: a generic line along the axis
// crosses the surface as often upward as downward, so a line through a triangle facing away
// also passes through one facing +axis. Those, projected, are counter-clockwise (exact
// orient2d; (u, v, axis) is right-handed), and the shadow is where the sum of their winding
// numbers is positive. Inner edges, shared by two such triangles in opposite directions, cancel
// before the 2D engine sees them; what is left is balanced at every point and chains into
// closed paths (rings.cpp), about the silhouette's size rather than the mesh's.
//
// An open mesh (a surface: terrain, a sheet, a box without its lid) bounds no solid, but the
// union of its projected triangles is as well defined: every triangle counts, each turned
// counter-clockwise, so the sum of winding numbers counts the triangles over a point and is
// positive exactly on the union. Neighbours on the same side of a fold still cancel their
// shared edge; a triangle seen edge-on has no area and adds nothing.

#include <algorithm>
#include <utility>

#include "clip/slice/stages.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/predicates/orient2d.h"
#include "contain/shapes/mesh_closure.h"

namespace contain::clip {

namespace {

bool less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// A projected edge, stored from its lesser end with the net count of its two directions.
struct Edge {
  Vec2 lo;
  Vec2 hi;
  int forward = 0;  // +1 for lo -> hi, -1 for hi -> lo
};

// The projected edges of the triangles facing +axis (closed), or of all, counter-clockwise.
std::vector<Edge> facing_edges(const Mesh& mesh, const slice::Frame& frame, bool closed) {
  std::vector<Edge> edges;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    Vec2 p[3] = {slice::project(tri.a, frame), slice::project(tri.b, frame),
                 slice::project(tri.c, frame)};
    const Sign turn = predicates::orient2d(p[0], p[1], p[2]);
    if (turn == Sign::zero || (closed && turn == Sign::negative)) continue;
    if (turn == Sign::negative) std::swap(p[1], p[2]);
    for (int i = 0; i < 3; ++i) {
      const Vec2 a = p[i];
      const Vec2 b = p[(i + 1) % 3];
      edges.push_back(less(a, b) ? Edge{a, b, 1} : Edge{b, a, -1});
    }
  }
  return edges;
}

// The net edges as keyed segments (a key per distinct point) for chain_rings.
std::vector<slice::CrossingSegment> net_segments(std::vector<Edge> edges) {
  const auto by_ends = [](const Edge& a, const Edge& b) {
    if (a.lo != b.lo) return less(a.lo, b.lo);
    return less(a.hi, b.hi);
  };
  std::sort(edges.begin(), edges.end(), by_ends);
  std::vector<Vec2> points;
  points.reserve(2 * edges.size());
  for (const Edge& e : edges) {
    points.push_back(e.lo);
    points.push_back(e.hi);
  }
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  const auto key = [&](Vec2 p) {
    return static_cast<std::uint64_t>(std::lower_bound(points.begin(), points.end(), p, less) -
                                      points.begin());
  };
  std::vector<slice::CrossingSegment> out;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    int net = 0;
    for (; j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi; ++j)
      net += edges[j].forward;
    Vec2 from = edges[i].lo;
    Vec2 to = edges[i].hi;
    if (net < 0) std::swap(from, to);
    for (int k = 0; k < std::abs(net); ++k)
      out.push_back({key(from), key(to), from, to, -1});
    i = j;
  }
  return out;
}

}  // namespace

Result<MultiPolygon> shadow(const Mesh& mesh, const SliceOptions& options) {
  const bool closed = !unmatched_edge(mesh).has_value();
  const slice::Frame frame = slice::frame_of(options.axis);
  const std::vector<Ring> rings =
      slice::chain_rings(net_segments(facing_edges(mesh, frame, closed)));
  return polygon_boolean(rings, {}, {.op = Op::union_, .fill = Fill::positive});
}

}  // namespace contain::clip
