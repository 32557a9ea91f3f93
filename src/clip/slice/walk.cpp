// Stage 2a of slicing: a plane through no vertex, chained by walking the surface.
//
// On a manifold stretch of the mesh (every crossing edge used by two triangles, once each way:
// SweepMesh::twin) the segment of a triangle ends on its edge going up, and the triangle across
// that edge starts its own segment there (the edge goes down in it). So the curve's closed
// paths are walked from triangle to triangle through the pairing of half-edges, each crossing
// computed once and no key looked up: the cycles chain_rings would find through a hash of the
// keys, in a flat array. Any vertex on the plane, or an edge without a twin, hands the plane
// back to the general stages (crossings.cpp, rings.cpp), which decide those exactly.

#include "clip/slice/stages.h"
#include "contain/predicates/rounded_crossing.h"

namespace contain::clip::slice {

namespace {

// Triangle t's edges going down (above to below, from corner `down` to the next) and up, when
// it crosses z = c with no vertex on it; false otherwise.
bool crossing_edges(const SweepMesh& mesh, std::int32_t t, double c, int& down, int& up) {
  const TriangleIndices& tri = mesh.triangles[static_cast<std::size_t>(t)];
  bool above[3];
  for (int i = 0; i < 3; ++i) {
    const double z = mesh.vertices[static_cast<std::size_t>(tri[i])].z;
    if (z == c) return false;
    above[i] = z > c;
  }
  down = -1;
  up = -1;
  for (int i = 0; i < 3; ++i) {
    const int j = i == 2 ? 0 : i + 1;
    if (above[i] && !above[j]) down = i;
    if (!above[i] && above[j]) up = i;
  }
  return down >= 0;
}

struct Point {
  std::uint64_t key;
  Vec2 at;
};

// The crossing of triangle t's edge from corner i to the next.
Point edge_crossing(const SweepMesh& mesh, std::int32_t t, int i, double c) {
  const TriangleIndices& tri = mesh.triangles[static_cast<std::size_t>(t)];
  const std::int32_t p = tri[i];
  const std::int32_t q = tri[i == 2 ? 0 : i + 1];
  const Vec3 x = predicates::rounded_axis_crossing(
      mesh.vertices[static_cast<std::size_t>(p)], mesh.vertices[static_cast<std::size_t>(q)], 2, c);
  return {edge_key(p, q), {x.x, x.y}};
}

// The closed path through triangle t0, appended to out as one cycle; false when it meets a
// vertex on the plane or an edge without a twin.
bool walk_cycle(const SweepMesh& mesh, std::int32_t t0, double c, WalkScratch& scratch,
                std::vector<CrossingSegment>& out, std::vector<ChainCycle>& cycles) {
  int down = 0, up = 0;
  if (!crossing_edges(mesh, t0, c, down, up)) return false;
  const Point start = edge_crossing(mesh, t0, down, c);
  ChainCycle cycle{start.key, out.size(), 0, 0};
  Point from = start;
  for (std::int32_t t = t0;;) {
    scratch.mark[static_cast<std::size_t>(t)] = scratch.stamp;
    const std::int32_t across =
        mesh.twin[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(up)];
    if (across < 0) return false;
    const std::int32_t next = across / 3;
    // The next triangle's corners, pairing and mark are read right after this crossing is
    // computed: fetched now, their cache misses (the walk jumps through large meshes) overlap
    // with that computation.
    const auto n = static_cast<std::size_t>(next);
    __builtin_prefetch(&mesh.triangles[n]);
    __builtin_prefetch(&mesh.twin[3 * n]);
    __builtin_prefetch(&scratch.mark[n]);
    const Point to = next == t0 ? start : edge_crossing(mesh, t, up, c);
    if (from.key < cycle.least) {
      cycle.least = from.key;
      cycle.first = cycle.size;
    }
    out.push_back({from.key, to.key, from.at, to.at, t});
    ++cycle.size;
    if (next == t0) break;
    // The edge goes down in the triangle across: that is where its segment starts.
    if (scratch.mark[static_cast<std::size_t>(next)] == scratch.stamp ||
        !crossing_edges(mesh, next, c, down, up) || 3 * next + down != across) {
      return false;
    }
    t = next;
    from = to;
  }
  cycles.push_back(cycle);
  return true;
}

}  // namespace

bool walk_curve(const SweepMesh& mesh, std::span<const std::int32_t> active, double c,
                WalkScratch& scratch, std::vector<CrossingSegment>& out,
                std::vector<ChainCycle>& cycles) {
  out.clear();
  cycles.clear();
  if (scratch.mark.size() != mesh.triangles.size()) {
    scratch.mark.assign(mesh.triangles.size(), 0);
    scratch.stamp = 0;
  }
  if (++scratch.stamp == 0) {  // wrapped: every old mark would look current
    std::fill(scratch.mark.begin(), scratch.mark.end(), 0);
    scratch.stamp = 1;
  }
  for (const std::int32_t t : active) {
    if (scratch.mark[static_cast<std::size_t>(t)] == scratch.stamp) continue;
    if (!walk_cycle(mesh, t, c, scratch, out, cycles)) return false;
  }
  return true;
}

}  // namespace contain::clip::slice
