#include "contain/shapes/mesh_validation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <sstream>
#include <tuple>

#include "contain/core/huge_pages.h"
#include "contain/core/union_find.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/rounded_volume.h"

// Outline: the triangle corners grouped by vertex (one counting sort) give, at each vertex v,
// its links: for each corner at v, the two neighbours along the triangle's edges. Links with the
// same neighbour w are the uses of the edge {v, w}: those with w > v count each edge once
// (border, non-manifold, inconsistent edges); all of them join v's corners into fans (a vertex
// of several fans is a pinch vertex). The triangles whose smallest vertex is v, sorted, give
// duplicates; vertices joined by edges give the components; exact orientations give degenerate
// faces. Work and memory stay local to a vertex: no sort or union-find over all edges.

namespace contain::shapes {

namespace {

// Zero area iff all three projected areas are zero. The projection along the largest component
// of the (rounded) normal goes first: for a triangle of some area it is the one whose filtered
// orient2d answers at once, whatever the triangle's direction (vertical ones included).
bool zero_area(Vec3 a, Vec3 b, Vec3 c) {
  using predicates::orient2d;
  const auto xy = [&] { return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::zero; };
  const auto yz = [&] { return orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::zero; };
  const auto zx = [&] { return orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::zero; };
  const Vec3 n = cross(b - a, c - a);
  const double nx = std::abs(n.x), ny = std::abs(n.y), nz = std::abs(n.z);
  if (nx >= ny && nx >= nz) return yz() && zx() && xy();
  if (ny >= nz) return zx() && xy() && yz();
  return xy() && yz() && zx();
}

// Corners 3 t + k grouped by their vertex, ascending within a vertex (so the corners of one
// triangle at one vertex are next to each other): corner[start[v] .. start[v + 1]).
// Huge pages (core/huge_pages.h): for 100k triangles these are 1.6 MB written once, 400 pages of
// 4 kB to fault in otherwise; `corner` default-initializes (every element is written below).
struct VertexCorners {
  HugePageVector<std::uint32_t> start;
  HugePageVector<std::uint32_t> corner;
};

VertexCorners corners_by_vertex(const Mesh& mesh) {
  VertexCorners out;
  out.start.assign(mesh.vertices.size() + 1, 0);
  for (const TriangleIndices& t : mesh.triangles)
    for (const std::int32_t v : t)
      ++out.start[static_cast<std::size_t>(v) + 1];
  std::partial_sum(out.start.begin(), out.start.end(), out.start.begin());
  out.corner.resize(3 * mesh.triangles.size());
  HugePageVector<std::uint32_t> next(out.start.begin(), out.start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k)
      out.corner[next[static_cast<std::size_t>(mesh.triangles[t][k])]++] =
          static_cast<std::uint32_t>(3 * t + k);
  return out;
}

// A use of the edge {v, other} by a triangle, seen from v, packed so that links sort as plain
// integers by the other end: other (bits 33..63), the corner's position in v's corner list
// (local, bits 1..32), whether the triangle runs min -> max along the edge (forward, bit 0).
using Link = std::uint64_t;

Link make_link(std::int32_t other, std::uint32_t local, bool forward) {
  return static_cast<std::uint64_t>(other) << 33 | static_cast<std::uint64_t>(local) << 1 |
         (forward ? 1U : 0U);
}
std::int32_t other_of(Link l) {
  return static_cast<std::int32_t>(l >> 33);
}
std::uint32_t local_of(Link l) {
  return static_cast<std::uint32_t>(l >> 1);
}
bool forward_of(Link l) {
  return (l & 1U) != 0;
}

// The links of vertex v, sorted by the other end; corners of one triangle at v are joined (a
// triangle with a repeated index).
void collect_links(const Mesh& mesh, const VertexCorners& vc, std::int32_t v,
                   std::vector<Link>& links, UnionFind<std::uint32_t>& fans) {
  const auto first = vc.start[static_cast<std::size_t>(v)];
  const auto count = vc.start[static_cast<std::size_t>(v) + 1] - first;
  links.clear();
  fans.reset(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t c = vc.corner[first + i];
    if (i > 0 && vc.corner[first + i - 1] / 3 == c / 3) fans.unite(i - 1, i);
    const TriangleIndices& tri = mesh.triangles[c / 3];
    const std::int32_t next = tri[(c % 3 + 1) % 3], prev = tri[(c % 3 + 2) % 3];
    if (next != v) links.push_back(make_link(next, i, v < next));  // the edge v -> next
    if (prev != v) links.push_back(make_link(prev, i, prev < v));  // the edge prev -> v
  }
  std::sort(links.begin(), links.end());
}

// Triangles with the same three vertices as another (any order) among those whose smallest
// vertex is v, counted past the first.
std::size_t duplicates_at(const Mesh& mesh, const VertexCorners& vc, std::int32_t v,
                          std::vector<std::array<std::int32_t, 3>>& group) {
  group.clear();
  for (auto i = vc.start[static_cast<std::size_t>(v)];
       i < vc.start[static_cast<std::size_t>(v) + 1]; ++i) {
    const std::uint32_t c = vc.corner[i];
    std::array<std::int32_t, 3> s = mesh.triangles[c / 3];
    // Once per triangle: at its first corner holding its smallest vertex.
    if (std::min({s[0], s[1], s[2]}) == v &&
        (i == vc.start[static_cast<std::size_t>(v)] || vc.corner[i - 1] / 3 != c / 3)) {
      std::sort(s.begin(), s.end());
      group.push_back(s);
    }
  }
  std::sort(group.begin(), group.end());
  std::size_t count = 0;
  for (std::size_t i = 1; i < group.size(); ++i)
    count += group[i] == group[i - 1] ? 1 : 0;
  return count;
}

// The corner at v of triangle `c / 3`, seen from v: the vertex before it and the one after it.
struct Around {
  std::int32_t prev;
  std::int32_t next;
};

// The components of the referenced vertices, once `vertices` joins the ends of every edge.
std::size_t count_components(const Mesh& mesh, const VertexCorners& vc,
                             UnionFind<std::uint32_t>& vertices) {
  std::size_t components = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (vc.start[v] != vc.start[v + 1] && vertices.find(static_cast<std::uint32_t>(v)) == v) {
      ++components;
    }
  }
  return components;
}

// The common case, proved cheaply: at every vertex v, its corners form one cycle in which each
// corner's next vertex is the following corner's previous one, the previous vertices all
// distinct. Then every directed edge v -> w is used once and w -> v once (closed, consistently
// oriented, no edge of three triangles), no vertex is a pinch (one fan), and no triangle repeats
// another (same orientation: a directed edge twice; opposite: a corner and its successor with
// swapped ends). Fills the topology fields as check_topology does; false, at the first sign of
// anything else (the full analysis then counts what and how much), with `r` unchanged.
bool check_topology_quick(const Mesh& mesh, const VertexCorners& vc, MeshReport& r) {
  std::vector<Around> around;
  UnionFind<std::uint32_t> vertices(mesh.vertices.size());
  std::size_t referenced = 0, edges = 0;
  for (std::size_t vi = 0; vi < mesh.vertices.size(); ++vi) {
    const std::uint32_t first = vc.start[vi], count = vc.start[vi + 1] - first;
    if (count == 0) continue;
    ++referenced;
    const auto v = static_cast<std::int32_t>(vi);
    around.clear();
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::uint32_t c = vc.corner[first + i];
      const TriangleIndices& tri = mesh.triangles[c / 3];
      const Around a{tri[(c % 3 + 2) % 3], tri[(c % 3 + 1) % 3]};
      if (a.prev == v || a.next == v) return false;  // a repeated index
      around.push_back(a);
    }
    std::sort(around.begin(), around.end(),
              [](const Around& a, const Around& b) { return a.prev < b.prev; });
    for (std::uint32_t i = 1; i < count; ++i)
      if (around[i].prev == around[i - 1].prev) return false;
    // The walk from corner 0 to the corner whose previous vertex is this one's next: back at
    // corner 0 first after exactly `count` steps, it has visited every corner once.
    std::size_t at = 0;
    for (std::uint32_t step = 1; step <= count; ++step) {
      const std::int32_t next = around[at].next;
      const auto found =
          std::lower_bound(around.begin(), around.end(), next,
                           [](const Around& a, std::int32_t value) { return a.prev < value; });
      if (found == around.end() || found->prev != next) return false;  // a border edge
      if (found->next == around[at].prev) return false;  // the same triangle, turned over
      at = static_cast<std::size_t>(found - around.begin());
      if ((at == 0) != (step == count)) return false;  // several fans, or edges of three
    }
    for (const Around& a : around) {
      if (a.next > v) {  // the edge {v, next}, counted at its smaller end
        ++edges;
        vertices.unite(static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(a.next));
      }
    }
  }
  r.referenced_vertices = referenced;
  r.edges = edges;
  r.components = count_components(mesh, vc, vertices);
  return true;
}

// Edges, fans, components and duplicates, vertex by vertex.
void check_topology(const Mesh& mesh, const VertexCorners& vc, MeshReport& r) {
  UnionFind<std::uint32_t> vertices(mesh.vertices.size());
  std::vector<Link> links;
  UnionFind<std::uint32_t> fans(0);  // v's corners, by their position in its list
  std::vector<std::array<std::int32_t, 3>> group;
  for (std::size_t vi = 0; vi < mesh.vertices.size(); ++vi) {
    if (vc.start[vi] == vc.start[vi + 1]) continue;
    ++r.referenced_vertices;
    const auto v = static_cast<std::int32_t>(vi);
    collect_links(mesh, vc, v, links, fans);
    for (std::size_t g = 0; g < links.size();) {
      std::size_t h = g + 1;
      const std::int32_t other = other_of(links[g]);
      while (h < links.size() && other_of(links[h]) == other)
        ++h;
      for (std::size_t q = g + 1; q < h; ++q)
        fans.unite(local_of(links[g]), local_of(links[q]));
      if (other > v) {  // the edge {v, other}, counted at its smaller end
        const std::size_t count = h - g;
        ++r.edges;
        if (count == 1) ++r.border_edges;
        if (count >= 3) ++r.nonmanifold_edges;
        if (count == 2 && forward_of(links[g]) == forward_of(links[g + 1])) {
          ++r.inconsistent_edges;
        }
        vertices.unite(static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(other));
      }
      g = h;
    }
    const std::uint32_t corners = vc.start[vi + 1] - vc.start[vi];
    for (std::uint32_t i = 1; i < corners; ++i) {
      if (fans.find(i) != 0) {  // a corner outside the fan of the first
        r.pinch_vertices.push_back(v);
        break;
      }
    }
    r.duplicated_triangles += duplicates_at(mesh, vc, v, group);
  }
  r.components = count_components(mesh, vc, vertices);
}

}  // namespace

namespace {

MeshReport validate(const Mesh& mesh, bool quick_first) {
  MeshReport r;
  r.vertices = mesh.vertices.size();
  r.triangles = mesh.triangles.size();
  const std::size_t nt = mesh.triangles.size();

  for (const TriangleIndices& tri : mesh.triangles) {
    const Vec3 a = mesh.vertex(tri[0]);
    const Vec3 b = mesh.vertex(tri[1]);
    const Vec3 c = mesh.vertex(tri[2]);
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] || zero_area(a, b, c)) {
      ++r.degenerate_triangles;
    }
  }
  if (const VertexCorners vc = corners_by_vertex(mesh);
      !quick_first || !check_topology_quick(mesh, vc, r)) {
    check_topology(mesh, vc, r);
  }

  r.euler_characteristic = static_cast<std::int64_t>(r.referenced_vertices) -
                           static_cast<std::int64_t>(r.edges) + static_cast<std::int64_t>(nt);
  if (r.closed() && r.manifold() && r.consistently_oriented()) {
    r.genus = (2 * static_cast<std::int64_t>(r.components) - r.euler_characteristic) / 2;
  }

  // Exact in sign (and correctly rounded): `outward` is decided on it.
  r.signed_volume = predicates::rounded_signed_volume(mesh.vertices, mesh.triangles);
  return r;
}

}  // namespace

MeshReport validate_mesh(const Mesh& mesh) {
  return validate(mesh, true);
}

MeshReport detail::validate_mesh_in_full(const Mesh& mesh) {
  return validate(mesh, false);
}

bool detail::topology_proven_quickly(const Mesh& mesh) {
  MeshReport unused;
  return check_topology_quick(mesh, corners_by_vertex(mesh), unused);
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

// Equal positions hash equal (+0 and -0 too). Round coordinates (integers, halves) have zero low
// bits: the finalizer of MurmurHash3 brings the high bits down, for masks and high halves alike.
std::uint64_t position_hash(Vec3 p) {
  std::uint64_t h = coordinate_bits(p.x) * 0x9E3779B97F4A7C15ULL ^
                    coordinate_bits(p.y) * 0xC2B2AE3D27D4EB4FULL ^
                    coordinate_bits(p.z) * 0x165667B19E3779F9ULL;
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDULL;
  h ^= h >> 33;
  return h;
}

// Open addressing from positions to new vertex numbers, in a power-of-two table at most half
// full: equal positions meet in one slot; a NaN coordinate equals nothing, so it is never welded.
// A slot holds the number and the high half of the position's hash, so that a probe past another
// position rarely reads that vertex (a cache miss in a large mesh).
class PositionTable {
 public:
  explicit PositionTable(std::size_t n) {
    slots_.assign(std::bit_ceil(std::max<std::size_t>(16, 2 * n)), kEmpty);
  }
  // The number of the first vertex at p (in `kept`), or -1 after reserving a slot for `fresh`.
  std::int32_t find_or_add(Vec3 p, std::span<const Vec3> kept, std::int32_t fresh) {
    const std::size_t mask = slots_.size() - 1;
    const std::uint64_t h = position_hash(p);
    const std::uint64_t tag = h & 0xFFFFFFFF00000000ULL;
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      const std::uint64_t slot = slots_[i];
      if (slot == kEmpty) {
        slots_[i] = tag | static_cast<std::uint32_t>(fresh);
        return -1;
      }
      if ((slot & 0xFFFFFFFF00000000ULL) != tag) continue;
      const auto v = static_cast<std::int32_t>(slot & 0xFFFFFFFFU);
      const Vec3 q = kept[static_cast<std::size_t>(v)];
      if (q.x == p.x && q.y == p.y && q.z == p.z) return v;
    }
  }

 private:
  // No slot of a vertex number (below 2^31) is all ones.
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::vector<std::uint64_t> slots_;
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

// Equal positions found by sorting (hash high half, vertex number) words by their high half, in
// three passes of a radix sort over sequential arrays, then comparing the positions within each
// run of equal halves: several times cheaper than the hash table of weld_vertices, whose probes
// miss the cache once a table per vertex in a large mesh (a sixth of slicing 524k triangles).
bool vertices_distinct(std::span<const Vec3> vertices) {
  const std::size_t n = vertices.size();
  if (n < 2) return true;
  if (n > 0xFFFFFFFFU) {  // no room for the vertex number in the word: the weld's table
    PositionTable table(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (table.find_or_add(vertices[i], vertices, static_cast<std::int32_t>(i)) >= 0) return false;
    }
    return true;
  }
  std::vector<std::uint64_t> words(n);
  std::vector<std::uint64_t> other(n);
  for (std::size_t i = 0; i < n; ++i)
    words[i] = (position_hash(vertices[i]) & 0xFFFFFFFF00000000ULL) | i;
  constexpr int kBits = 11;
  for (int shift = 32; shift < 64; shift += kBits) {
    std::array<std::uint32_t, (1U << kBits) + 1> start{};
    const auto digit = [&](std::uint64_t w) { return (w >> shift) & ((1U << kBits) - 1); };
    for (const std::uint64_t w : words)
      ++start[digit(w) + 1];
    for (std::size_t d = 1; d < start.size(); ++d)
      start[d] += start[d - 1];
    for (const std::uint64_t w : words)
      other[start[digit(w)]++] = w;
    words.swap(other);
  }
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && (words[j] >> 32) == (words[i] >> 32))
      ++j;
    for (std::size_t a = i; a < j; ++a) {
      const Vec3 p = vertices[words[a] & 0xFFFFFFFFU];
      for (std::size_t b = a + 1; b < j; ++b) {
        const Vec3 q = vertices[words[b] & 0xFFFFFFFFU];
        if (p.x == q.x && p.y == q.y && p.z == q.z) return false;
      }
    }
    i = j;
  }
  return true;
}
}  // namespace contain::shapes
