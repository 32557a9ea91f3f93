#include "contain/shapes/mesh_validation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <tuple>

#include "contain/core/union_find.h"
#include "contain/predicates/orient2d.h"
#include "contain/values/box.h"

// Outline: one record per (edge, triangle) sorted by edge (counting sorts) gives border,
// non-manifold and inconsistent edges; the same groups join triangle corners at both end vertices
// (a vertex whose corners fall into several groups is a pinch vertex); vertices joined by edges
// give the components; sorted vertex triples give duplicates; exact orientations give degenerate
// faces.

namespace contain::shapes {

namespace {

struct EdgeUse {
  std::int32_t lo, hi;  // lo < hi
  std::int32_t triangle;
  bool forward;  // the triangle runs lo -> hi
};

bool zero_area(Vec3 a, Vec3 b, Vec3 c) {
  using predicates::orient2d;
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::zero &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::zero &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::zero;
}

std::size_t corner_of(const TriangleIndices& t, std::int32_t v) {
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

// The positions 0 .. n - 1 ordered by key(i) in [0, keys), equal keys in their given order: a
// counting sort, O(n + keys), where a comparison sort of the hundreds of thousands of records
// of a large mesh took most of the validation's time.
template <class Key>
std::vector<std::uint32_t> counting_order(std::size_t n, std::size_t keys, const Key& key,
                                          const std::vector<std::uint32_t>* within = nullptr) {
  std::vector<std::uint32_t> start(keys + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    ++start[key(i) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = within ? (*within)[i] : i;
    order[start[key(at)]++] = static_cast<std::uint32_t>(at);
  }
  return order;
}

// The edge uses in the order of (lo, hi, triangle): two stable counting sorts (by hi, then by
// lo) of uses made in triangle order.
std::vector<EdgeUse> sorted_by_edge(const std::vector<EdgeUse>& uses, std::size_t vertices) {
  const auto by_hi = counting_order(
      uses.size(), vertices, [&](std::size_t i) { return static_cast<std::size_t>(uses[i].hi); });
  const auto by_lo = counting_order(
      uses.size(), vertices, [&](std::size_t i) { return static_cast<std::size_t>(uses[i].lo); },
      &by_hi);
  std::vector<EdgeUse> out(uses.size());
  for (std::size_t i = 0; i < uses.size(); ++i)
    out[i] = uses[by_lo[i]];
  return out;
}

// Vertices (ascending) whose triangle corners fall into more than one group: pinch vertices.
std::vector<std::int32_t> pinch_vertices(const Mesh& mesh, UnionFind<std::size_t>& corners) {
  const std::size_t nc = 3 * mesh.triangles.size();
  const auto vertex_of = [&](std::size_t c) {
    return static_cast<std::size_t>(mesh.triangles[c / 3][c % 3]);
  };
  const auto order = counting_order(nc, mesh.vertices.size(), vertex_of);
  std::vector<std::int32_t> out;
  for (std::size_t g = 0; g < nc;) {
    const std::size_t v = vertex_of(order[g]);
    const std::size_t root = corners.find(order[g]);
    bool pinch = false;
    std::size_t h = g + 1;
    for (; h < nc && vertex_of(order[h]) == v; ++h)
      pinch = pinch || corners.find(order[h]) != root;
    if (pinch) out.push_back(static_cast<std::int32_t>(v));
    g = h;
  }
  return out;
}

// Triangles with the same three vertices as another (any order), counted past the first.
std::size_t duplicated_triangles(const Mesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  std::vector<std::array<std::int32_t, 3>> sorted(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    sorted[t] = mesh.triangles[t];
    std::sort(sorted[t].begin(), sorted[t].end());
  }
  // Grouped by the smallest vertex, then each (small) group sorted.
  const auto order = counting_order(nt, mesh.vertices.size(), [&](std::size_t t) {
    return static_cast<std::size_t>(sorted[t][0]);
  });
  std::size_t count = 0;
  std::vector<std::array<std::int32_t, 3>> group;
  for (std::size_t g = 0; g < nt;) {
    group.clear();
    std::size_t h = g;
    for (; h < nt && sorted[order[h]][0] == sorted[order[g]][0]; ++h)
      group.push_back(sorted[order[h]]);
    std::sort(group.begin(), group.end());
    for (std::size_t i = 1; i < group.size(); ++i)
      count += group[i] == group[i - 1] ? 1 : 0;
    g = h;
  }
  return count;
}

}  // namespace

MeshReport validate_mesh(const Mesh& mesh) {
  MeshReport r;
  r.vertices = mesh.vertices.size();
  r.triangles = mesh.triangles.size();
  const std::size_t nt = mesh.triangles.size();

  std::vector<char> used(mesh.vertices.size(), 0);
  std::vector<EdgeUse> uses;
  uses.reserve(3 * nt);
  Box3 box;
  for (std::size_t t = 0; t < nt; ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = tri[static_cast<std::size_t>(k)];
      const std::int32_t b = tri[static_cast<std::size_t>((k + 1) % 3)];
      used[static_cast<std::size_t>(a)] = 1;
      box.expand(mesh.vertex(a));
      if (a == b) continue;
      uses.push_back({std::min(a, b), std::max(a, b), static_cast<std::int32_t>(t), a < b});
    }
    const Vec3 a = mesh.vertex(tri[0]);
    const Vec3 b = mesh.vertex(tri[1]);
    const Vec3 c = mesh.vertex(tri[2]);
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] || zero_area(a, b, c)) {
      ++r.degenerate_triangles;
    }
  }
  r.referenced_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  uses = sorted_by_edge(uses, mesh.vertices.size());

  // Corners: 3 t + k. A triangle with a repeated index joins its own corners at that vertex.
  UnionFind<std::size_t> corners(3 * nt);
  UnionFind<std::size_t> vertices(mesh.vertices.size());
  for (std::size_t t = 0; t < nt; ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t l = k + 1; l < 3; ++l) {
        if (tri[k] == tri[l]) corners.unite(3 * t + k, 3 * t + l);
      }
    }
  }
  for (std::size_t g = 0; g < uses.size();) {
    std::size_t h = g;
    while (h < uses.size() && uses[h].lo == uses[g].lo && uses[h].hi == uses[g].hi)
      ++h;
    const std::size_t count = h - g;
    ++r.edges;
    if (count == 1) ++r.border_edges;
    if (count >= 3) ++r.nonmanifold_edges;
    if (count == 2 && uses[g].forward == uses[g + 1].forward) ++r.inconsistent_edges;
    const EdgeUse& first = uses[g];
    vertices.unite(static_cast<std::size_t>(first.lo), static_cast<std::size_t>(first.hi));
    const auto tf = static_cast<std::size_t>(first.triangle);
    for (std::size_t q = g + 1; q < h; ++q) {
      const auto tq = static_cast<std::size_t>(uses[q].triangle);
      for (std::int32_t v : {first.lo, first.hi}) {
        corners.unite(3 * tf + corner_of(mesh.triangles[tf], v),
                      3 * tq + corner_of(mesh.triangles[tq], v));
      }
    }
    g = h;
  }

  r.pinch_vertices = pinch_vertices(mesh, corners);

  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (used[v] && vertices.find(v) == v) ++r.components;
  }

  r.duplicated_triangles = duplicated_triangles(mesh);

  r.euler_characteristic = static_cast<std::int64_t>(r.referenced_vertices) -
                           static_cast<std::int64_t>(r.edges) + static_cast<std::int64_t>(nt);
  if (r.closed() && r.manifold() && r.consistently_oriented()) {
    r.genus = (2 * static_cast<std::int64_t>(r.components) - r.euler_characteristic) / 2;
  }

  // Signed volume: sum of a . (b x c) / 6, relative to the box centre, Neumaier summation.
  if (!box.empty()) {
    const Vec3 o = 0.5 * box.min + 0.5 * box.max;
    double sum = 0.0, compensation = 0.0;
    for (const TriangleIndices& tri : mesh.triangles) {
      const Vec3 a = mesh.vertex(tri[0]) - o, b = mesh.vertex(tri[1]) - o,
                 c = mesh.vertex(tri[2]) - o;
      const double term = dot(a, cross(b, c));
      const double s = sum + term;
      compensation += std::abs(sum) >= std::abs(term) ? (sum - s) + term : (term - s) + sum;
      sum = s;
    }
    r.signed_volume = (sum + compensation) / 6.0;
  }
  return r;
}

std::string MeshReport::summary() const {
  std::ostringstream out;
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  out << vertices << " vertices (" << referenced_vertices << " referenced), " << triangles
      << " triangles, " << edges << " edges, " << components
      << (components == 1 ? " component\n" : " components\n");
  out << "closed: " << yes(closed()) << "; 2-manifold: " << yes(manifold())
      << "; consistently oriented: " << yes(consistently_oriented())
      << "; outward: " << yes(outward()) << " (signed volume " << signed_volume << ")\n";
  out << "Euler characteristic " << euler_characteristic;
  if (genus) out << ", genus " << *genus;
  out << "\n";
  out << "border edges: " << border_edges << "; non-manifold edges: " << nonmanifold_edges
      << "; inconsistently oriented edges: " << inconsistent_edges
      << "; pinch vertices: " << pinch_vertices.size();
  if (!pinch_vertices.empty()) {
    out << " (0-based:";
    for (std::size_t i = 0; i < pinch_vertices.size() && i < 5; ++i)
      out << " " << pinch_vertices[i];
    if (pinch_vertices.size() > 5) out << " ...";
    out << ")";
  }
  out << "; degenerate triangles: " << degenerate_triangles
      << "; duplicated triangles: " << duplicated_triangles << "\n";
  return out.str();
}

namespace {

// The bits of a coordinate for hashing, +0 and -0 made one (they are equal doubles).
std::uint64_t coordinate_bits(double x) {
  return std::bit_cast<std::uint64_t>(x + 0.0);
}

// Open addressing from positions to new vertex numbers, in a power-of-two table at most half
// full: equal positions meet in one slot; a NaN coordinate equals nothing, so it is never welded.
class PositionTable {
 public:
  explicit PositionTable(std::size_t n) {
    slots_.assign(std::bit_ceil(std::max<std::size_t>(16, 2 * n)), -1);
  }
  // The number of the first vertex at p (in `kept`), or -1 after reserving a slot for `fresh`.
  std::int32_t find_or_add(Vec3 p, const std::vector<Vec3>& kept, std::int32_t fresh) {
    const std::size_t mask = slots_.size() - 1;
    std::uint64_t h = coordinate_bits(p.x) * 0x9E3779B97F4A7C15ULL ^
                      coordinate_bits(p.y) * 0xC2B2AE3D27D4EB4FULL ^
                      coordinate_bits(p.z) * 0x165667B19E3779F9ULL;
    // Round coordinates (integers, halves) have zero low bits: the finalizer of MurmurHash3
    // brings the high bits down before the mask.
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDULL;
    h ^= h >> 33;
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      const std::int32_t v = slots_[i];
      if (v < 0) {
        slots_[i] = fresh;
        return -1;
      }
      const Vec3 q = kept[static_cast<std::size_t>(v)];
      if (q.x == p.x && q.y == p.y && q.z == p.z) return v;
    }
  }

 private:
  std::vector<std::int32_t> slots_;
};

}  // namespace

// One pass in file order: a position's first vertex is kept, later ones map to it. Linear
// where the sort by position it replaces was a third of slicing 100 planes through a sphere.
WeldResult weld_vertices(const Mesh& mesh) {
  WeldResult w;
  const std::size_t n = mesh.vertices.size();
  PositionTable table(n);
  w.remap.resize(n);
  w.mesh.vertices.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto fresh = static_cast<std::int32_t>(w.mesh.vertices.size());
    const std::int32_t found = table.find_or_add(mesh.vertices[i], w.mesh.vertices, fresh);
    if (found < 0) w.mesh.vertices.push_back(mesh.vertices[i]);
    w.remap[i] = found < 0 ? fresh : found;
  }
  w.mesh.triangles.reserve(mesh.triangles.size());
  for (const TriangleIndices& t : mesh.triangles) {
    w.mesh.triangles.push_back({w.remap[static_cast<std::size_t>(t[0])],
                                w.remap[static_cast<std::size_t>(t[1])],
                                w.remap[static_cast<std::size_t>(t[2])]});
  }
  w.merged = n - w.mesh.vertices.size();
  return w;
}

}  // namespace contain::shapes
