// Meshes by half-spaces: one half-space at a time, triangle by triangle, with crossing vertices
// shared per mesh edge; the cap (optional) closes the border loops lying on the plane.

#include "contain/clip/mesh_clip.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "clip/cap_triangulation.h"
#include "clip/convex_functions.h"
#include "clip/ring_clip.h"
#include "contain/clip/box_halfspaces.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/ring_orientation.h"

namespace contain::clip {
namespace {

using predicates::BigFloat;

struct Gradient {
  BigFloat x, y, z;  // exact
  Vec3 approx;
};

Gradient gradient(const predicates::PlaneFunction& f) {
  return {BigFloat(f.plane.a), BigFloat(f.plane.b), BigFloat(f.plane.c), f.plane.normal()};
}
Gradient gradient(const predicates::FaceFunction& f) {
  // s(p) = ((c - a) x (b - a)) . (p - a)
  const Triangle3& t = f.face;
  const BigFloat ux = BigFloat(t.c.x) - BigFloat(t.a.x), uy = BigFloat(t.c.y) - BigFloat(t.a.y),
                 uz = BigFloat(t.c.z) - BigFloat(t.a.z);
  const BigFloat wx = BigFloat(t.b.x) - BigFloat(t.a.x), wy = BigFloat(t.b.y) - BigFloat(t.a.y),
                 wz = BigFloat(t.b.z) - BigFloat(t.a.z);
  return {uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx, cross(t.c - t.a, t.b - t.a)};
}

// Sign of the triangle's normal (b - a) x (c - a) dotted with the gradient, exactly.
Sign facing(const Vec3& a, const Vec3& b, const Vec3& c, const Gradient& g) {
  const BigFloat ux = BigFloat(b.x) - BigFloat(a.x), uy = BigFloat(b.y) - BigFloat(a.y),
                 uz = BigFloat(b.z) - BigFloat(a.z);
  const BigFloat wx = BigFloat(c.x) - BigFloat(a.x), wy = BigFloat(c.y) - BigFloat(a.y),
                 wz = BigFloat(c.z) - BigFloat(a.z);
  return ((uy * wz - uz * wy) * g.x + (uz * wx - ux * wz) * g.y + (ux * wy - uy * wx) * g.z).sign();
}

using Key = std::uint64_t;
Key edge_key(std::int32_t i, std::int32_t j) {
  return (static_cast<Key>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
}

std::unordered_set<Key> directed_edges(const Mesh& mesh) {
  std::unordered_set<Key> directed;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e)
      directed.insert(
          edge_key(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]));
  }
  return directed;
}

// Points on the plane with equal coordinates become one vertex. Crossing points of edges that
// leave a vertex lying within rounding distance of the plane round to the same point (spot.obj
// has vertices at x = 4e-19 next to the cut x = 0): as two vertices they leave a zero-length
// edge in the cap's loop, which no triangulation can close. Triangles that repeat a vertex
// after the welding (slivers between such points) are dropped: their other edges pair up.
void weld_on_plane(Mesh& mesh, const std::vector<bool>& on_plane) {
  struct Hash {
    std::size_t operator()(const Vec3& v) const {
      std::uint64_t h = 0;
      for (const double c : {v.x, v.y, v.z}) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &c, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ull;
      }
      return static_cast<std::size_t>(h);
    }
  };
  std::unordered_map<Vec3, std::int32_t, Hash> first;
  std::vector<std::int32_t> to(mesh.vertices.size());
  bool any = false;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    to[v] = static_cast<std::int32_t>(v);
    if (!on_plane[v]) continue;
    const Vec3 p = mesh.vertices[v] + Vec3{0.0, 0.0, 0.0};  // -0 and +0 alike
    const auto [it, fresh] = first.try_emplace(p, static_cast<std::int32_t>(v));
    if (!fresh) {
      to[v] = it->second;
      any = true;
    }
  }
  if (!any) return;
  std::size_t m = 0;
  for (TriangleIndices t : mesh.triangles) {
    for (auto& i : t)
      i = to[static_cast<std::size_t>(i)];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    mesh.triangles[m++] = t;
  }
  mesh.triangles.resize(m);
}

// A mesh cut by one half-space, before any cap: `on_plane` says which vertices lie on the plane
// (exactly, or as rounded crossing points).
struct Cut {
  Mesh mesh;
  std::vector<bool> on_plane;
};

// Keeps the part of each triangle on the inside: whole triangles with no vertex outside (those
// lying in the plane only when they face against the gradient, so that one of two coincident
// faces stays), nothing of those with no vertex inside, and the fan of the inside polygon for
// the rest, its crossing points shared per mesh edge.
template <class F>
Cut cut_by(const Mesh& mesh, const F& f, const Gradient& g) {
  Cut cut;
  Mesh& out = cut.mesh;
  out.vertices = mesh.vertices;
  std::vector<Sign> side(mesh.vertices.size());
  cut.on_plane.resize(mesh.vertices.size());
  for (std::size_t v = 0; v < side.size(); ++v) {
    side[v] = f.side(mesh.vertices[v]);
    cut.on_plane[v] = side[v] == Sign::zero;
  }
  std::unordered_map<Key, std::int32_t> crossings;
  auto crossing = [&](std::int32_t i, std::int32_t j) {
    if (j < i) std::swap(i, j);
    const auto [it, fresh] = crossings.try_emplace(edge_key(i, j), 0);
    if (fresh) {
      it->second = static_cast<std::int32_t>(out.vertices.size());
      out.vertices.push_back(detail::crossing_point(mesh.vertex(i), mesh.vertex(j), f));
      cut.on_plane.push_back(true);
    }
    return it->second;
  };
  for (const TriangleIndices& t : mesh.triangles) {
    Sign s[3];
    bool any_in = false, any_out = false;
    for (int e = 0; e < 3; ++e) {
      s[e] = side[static_cast<std::size_t>(t[static_cast<std::size_t>(e)])];
      any_in |= s[e] == Sign::positive;
      any_out |= s[e] == Sign::negative;
    }
    if (!any_out) {
      if (any_in ||
          facing(mesh.vertex(t[0]), mesh.vertex(t[1]), mesh.vertex(t[2]), g) == Sign::negative) {
        out.triangles.push_back(t);
      }
      continue;
    }
    if (!any_in) continue;
    std::int32_t poly[4];
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const int ip = (e + 2) % 3;
      const Sign sp = s[ip], sq = s[e];
      if ((sp == Sign::positive && sq == Sign::negative) ||
          (sp == Sign::negative && sq == Sign::positive)) {
        poly[n++] = crossing(t[static_cast<std::size_t>(ip)], t[static_cast<std::size_t>(e)]);
      }
      if (sq != Sign::negative) poly[n++] = t[static_cast<std::size_t>(e)];
    }
    for (int m = 1; m + 1 < n; ++m)
      out.triangles.push_back({poly[0], poly[m], poly[m + 1]});
  }
  return cut;
}

using Edge = std::pair<std::int32_t, std::int32_t>;

// The mesh's border edges on the plane (no twin, both ends on it), directed as the mesh uses
// them: the cut's outline.
std::vector<Edge> border_on_plane(const Mesh& mesh, const std::vector<bool>& on_plane) {
  const std::unordered_set<Key> directed = directed_edges(mesh);
  std::vector<Edge> border;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const std::int32_t u = t[static_cast<std::size_t>(e)],
                         v = t[static_cast<std::size_t>((e + 1) % 3)];
      if (on_plane[static_cast<std::size_t>(u)] && on_plane[static_cast<std::size_t>(v)] &&
          !directed.contains(edge_key(v, u))) {
        border.emplace_back(u, v);
      }
    }
  }
  return border;
}

// The vertices projected along the normal's largest component (exact: a choice of coordinates,
// orientation kept for a positive component).
std::vector<Vec2> project_along(const std::vector<Vec3>& vertices, Vec3 n) {
  const int axis = std::fabs(n.x) >= std::fabs(n.y) && std::fabs(n.x) >= std::fabs(n.z)
                       ? 0
                       : (std::fabs(n.y) >= std::fabs(n.z) ? 1 : 2);
  std::vector<Vec2> pts(vertices.size());
  for (std::size_t v = 0; v < pts.size(); ++v) {
    const Vec3 p = vertices[v];
    pts[v] = axis == 0 ? Vec2{p.y, p.z} : (axis == 1 ? Vec2{p.z, p.x} : Vec2{p.x, p.y});
  }
  return pts;
}

// The cap lies on one side of every border edge: the left when the edges' total signed area is
// positive (loops counter-clockwise around the cap, clockwise around its holes), exactly.
bool cap_on_the_left(const std::vector<Edge>& border, const std::vector<Vec2>& pts) {
  std::vector<Segment2> segments;
  segments.reserve(border.size());
  for (const auto& [u, v] : border)
    segments.push_back({pts[static_cast<std::size_t>(u)], pts[static_cast<std::size_t>(v)]});
  return predicates::edges_orientation(segments) == Sign::positive;
}

// Of the unused border edges leaving the head of edge `in`, the one to follow. Where several
// leave one vertex (the cut passes through a vertex at which the cap touches itself or another
// loop), the first one turning from the reverse of the arriving edge towards the cap's side:
// clockwise for a cap on the left. This keeps the two sectors meeting there in separate loops
// (taking any one left edges without a twin). border.size() when none is left.
std::size_t next_edge(std::size_t in, const std::vector<Edge>& border,
                      const std::vector<std::size_t>& out_edges, const std::vector<char>& used,
                      const std::vector<Vec2>& pts, bool cap_left) {
  const std::int32_t u = border[in].first, v = border[in].second;
  std::size_t best = border.size();
  for (const std::size_t c : out_edges) {
    if (used[c]) continue;
    if (best == border.size()) {
      best = c;
      continue;
    }
    // Directions swept from the reverse of the arriving edge, v -> u, clockwise for a cap on
    // the left (counter-clockwise otherwise): 0 the first open half-plane, 1 straight on,
    // 2 the second half-plane, 3 back along v -> u (last).
    const Vec2 o = pts[static_cast<std::size_t>(v)], r = pts[static_cast<std::size_t>(u)];
    const Vec2 wc = pts[static_cast<std::size_t>(border[c].second)];
    const Vec2 wb = pts[static_cast<std::size_t>(border[best].second)];
    const int turn = cap_left ? -1 : 1;  // the sign of orient2d(o, r, w) swept first
    auto sector = [&](Vec2 w) {
      const int s = to_int(predicates::orient2d(o, r, w)) * turn;
      if (s != 0) return s > 0 ? 0 : 2;
      const bool same = (w.x > o.x) == (r.x > o.x) && (w.x < o.x) == (r.x < o.x) &&
                        (w.y > o.y) == (r.y > o.y) && (w.y < o.y) == (r.y < o.y);
      return same ? 3 : 1;
    };
    const int sc = sector(wc), sb = sector(wb);
    const bool earlier =
        sc != sb ? sc < sb
                 : (sc == 0 || sc == 2) && to_int(predicates::orient2d(o, wb, wc)) * turn < 0;
    if (earlier) best = c;
  }
  return best;
}

// The border edges chained into closed loops of at least three vertices (open chains dropped).
std::vector<std::vector<std::int32_t>> chain_loops(const std::vector<Edge>& border,
                                                   const std::vector<Vec2>& pts, bool cap_left) {
  std::unordered_map<std::int32_t, std::vector<std::size_t>> leaving;
  for (std::size_t i = 0; i < border.size(); ++i)
    leaving[border[i].first].push_back(i);
  std::vector<char> used(border.size(), 0);
  std::vector<std::vector<std::int32_t>> loops;
  for (std::size_t start = 0; start < border.size(); ++start) {
    if (used[start]) continue;
    std::vector<std::int32_t> loop;
    std::size_t e = start;
    bool closed = false;
    while (e < border.size() && !used[e]) {
      used[e] = 1;
      loop.push_back(border[e].first);
      if (border[e].second == border[start].first) {
        closed = true;
        break;
      }
      e = next_edge(e, border, leaving[border[e].second], used, pts, cap_left);
    }
    if (closed && loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

// Closes the cut with cap triangles over the loops of its outline on the plane of normal n.
void add_cap(Mesh& mesh, const std::vector<bool>& on_plane, Vec3 n) {
  weld_on_plane(mesh, on_plane);
  const std::vector<Edge> border = border_on_plane(mesh, on_plane);
  if (border.empty()) return;
  const std::vector<Vec2> pts = project_along(mesh.vertices, n);
  const bool cap_left = cap_on_the_left(border, pts);
  const auto loops = chain_loops(border, pts, cap_left);
  if (loops.empty()) return;
  // The cap runs along each loop against the mesh's direction: loops counter-clockwise around
  // the cap in the projection give clockwise cap triangles.
  for (const auto& t : detail::triangulate_loops(loops, pts, !cap_left))
    mesh.triangles.push_back({t[0], t[1], t[2]});
}

template <class F>
Mesh clip_step(const Mesh& mesh, const F& f, bool cap) {
  const Gradient g = gradient(f);
  Cut cut = cut_by(mesh, f, g);
  if (cap) add_cap(cut.mesh, cut.on_plane, g.approx);
  return std::move(cut.mesh);
}

Mesh compact(Mesh mesh) {
  std::vector<std::int32_t> remap(mesh.vertices.size(), -1);
  std::vector<Vec3> vertices;
  for (auto& t : mesh.triangles) {
    for (auto& i : t) {
      auto& r = remap[static_cast<std::size_t>(i)];
      if (r < 0) {
        r = static_cast<std::int32_t>(vertices.size());
        vertices.push_back(mesh.vertex(i));
      }
      i = r;
    }
  }
  mesh.vertices = std::move(vertices);
  return mesh;
}

template <class F>
Mesh clip_all(const Mesh& mesh, const std::vector<F>& functions, const MeshClipOptions& options) {
  Mesh current = mesh;
  for (const F& f : functions) {
    if (current.triangles.empty()) break;
    current = clip_step(current, f, options.cut == MeshCut::cap);
  }
  return compact(std::move(current));
}

}  // namespace

Mesh clip_mesh(const Mesh& mesh, std::span<const Plane> half_spaces,
               const MeshClipOptions& options) {
  return clip_all(mesh, detail::plane_functions(half_spaces), options);
}

Mesh clip_mesh(const Mesh& mesh, const Box3& box, const MeshClipOptions& options) {
  if (box.empty()) return {};
  return clip_mesh(mesh, box_halfspaces(box), options);
}

Mesh clip_mesh(const Mesh& mesh, const ConvexPolyhedron& polyhedron,
               const MeshClipOptions& options) {
  if (!polyhedron.faces().empty()) {
    // One cut per plane: a face coplanar with an earlier one (a quad split in two) would cut
    // again through the rounded crossings of the first.
    std::vector<predicates::FaceFunction> faces;
    for (const Triangle3& t : polyhedron.faces()) {
      const bool repeated = std::any_of(faces.begin(), faces.end(), [&](const auto& f) {
        return f.side(t.a) == Sign::zero && f.side(t.b) == Sign::zero && f.side(t.c) == Sign::zero;
      });
      if (!repeated) faces.push_back({t});
    }
    return clip_all(mesh, faces, options);
  }
  return clip_mesh(mesh, std::span<const Plane>(polyhedron.planes()), options);
}

std::vector<Segment3> mesh_section(const Mesh& mesh, const Plane& plane) {
  const predicates::PlaneFunction f{plane};
  const Cut cut = cut_by(mesh, f, gradient(f));
  std::vector<Segment3> out;
  for (const auto& [u, v] : border_on_plane(cut.mesh, cut.on_plane)) {
    out.push_back({cut.mesh.vertex(u), cut.mesh.vertex(v)});
  }
  return out;
}

}  // namespace contain::clip
