#include "inside/surface_star.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "contain/predicates/big_float.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"

namespace contain::inside::detail {
namespace {

// Outline. Near p the surface is the union of the cones from p of the triangles through it (the
// star); on a small sphere about p each traces an arc: between its two other vertices (p is a
// vertex), a half circle (p inside an edge) or a whole great circle (p inside the triangle). The
// open cells around p are the regions of the sphere off these arcs, the winding number constant
// in each; p is inside if every cell is, outside if none is, else boundary.
// Every region's closure holds a vertex of the arcs (an arc's end, or a point where two arcs
// cross), or the region is a half sphere bounded by one whole circle; at a vertex every angular
// wedge of the region's side lies next to one of the arcs leaving it. So a sample on both sides
// of every arc leaving every vertex reaches every region:
// - at the direction of a vertex e of the star (e != p): for every triangle T whose plane holds e
//   and every vertex v of T off the line pe, the arc of T's great circle from e towards v, and
//   beside it the samples p + e1 (e - p) + e2 (v - p) +- e3 axis (0 < e3 << e2 << e1), with an
//   axis off T's plane. These are all the arcs leaving e (and a few more, whose samples are
//   merely redundant: any sample off the surface is a cell). Every term is an input point or an
//   axis, so the crossing tests decide them with the filtered predicates;
// - where two arcs of different planes cross inside both (a folded or self-intersecting star),
//   at Y = +-(n1 x n2): the four samples p + e1 Y + e2 (+-(n1 x Y)) + e3 (+-(n2 x Y)), the only
//   exact vectors. Two arcs between vertices of p cross where the four orientations of each
//   arc's ends against the other's plane say so, with no vector built unless they do.
// Every sample lies off every plane through p (its terms span space), so on no triangle.

using predicates::BigVec3;
using predicates::orient3d;
using predicates::to_big;

enum class At : std::uint8_t { vertex, edge, interior };

// A triangle of the star as seen from p.
struct Face {
  Triangle3 t;
  At at = At::interior;
  std::array<Vec3, 2>
      ends{};    // vertex: the two other corners, in the triangle's order; edge: its ends
  Vec3 apex;     // edge: the third corner
  int axis = 0;  // an axis along which the triangle's normal has a non-zero part
};

Face read_face(const Triangle3& t, Vec3 p) {
  Face f{t};
  const std::array<Vec3, 3> c{t.a, t.b, t.c};
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3 u = c[(i + 1) % 3], w = c[(i + 2) % 3];
    if (c[i] == p) {
      f.at = At::vertex;
      f.ends = {u, w};
    } else if (f.at == At::interior && predicates::collinear(u, w, p)) {
      f.at = At::edge;
      f.ends = {u, w};
      f.apex = c[i];
    }
  }
  if (predicates::orient2d({t.a.y, t.a.z}, {t.b.y, t.b.z}, {t.c.y, t.c.z}) != Sign::zero) {
    f.axis = 0;
  } else if (predicates::orient2d({t.a.z, t.a.x}, {t.b.z, t.b.x}, {t.c.z, t.c.x}) != Sign::zero) {
    f.axis = 1;
  } else {
    f.axis = 2;
  }
  return f;
}

Sign side(const Face& f, Vec3 v) {
  return orient3d(f.t.a, f.t.b, f.t.c, v);
}

BigVec3 normal(const Face& f) {
  const BigVec3 a = to_big(f.t.a);
  return cross(to_big(f.t.b) - a, to_big(f.t.c) - a);
}

Sign det(const BigVec3& u, const BigVec3& v, const BigVec3& w) {
  return dot(cross(u, v), w).sign();
}

// Y, a direction in f's plane, lies inside f's arc (not at its ends).
bool inside_arc(const Face& f, const BigVec3& y, Vec3 p) {
  const BigVec3 n = normal(f);
  if (f.at == At::vertex) {
    const BigVec3 bp = to_big(p);
    return det(to_big(f.ends[0]) - bp, y, n) == Sign::positive &&
           det(y, to_big(f.ends[1]) - bp, n) == Sign::positive;
  }
  if (f.at == At::edge) {  // on the apex's side of the edge's line
    const BigVec3 e0 = to_big(f.ends[0]), d = to_big(f.ends[1]) - e0;
    return det(d, y, n) == det(d, to_big(f.apex) - e0, n);
  }
  return true;
}

// g's arc meets f's plane at a point inside the arc, away from f's plane elsewhere.
bool arc_crosses_plane(const Face& f, const Face& g) {
  if (g.at == At::vertex) {
    const Sign s = side(f, g.ends[0]);
    return s != Sign::zero && side(f, g.ends[1]) == -s;
  }
  if (g.at == At::edge) return side(f, g.ends[0]) != Sign::zero;
  return side(f, g.t.a) != Sign::zero || side(f, g.t.b) != Sign::zero ||
         side(f, g.t.c) != Sign::zero;
}

class StarSampler {
 public:
  StarSampler(std::span<const Triangle3> star, Vec3 p, const MeshRay& ray,
              const std::function<bool(int)>& inside_at)
      : p_(p), ray_(ray), inside_at_(inside_at) {
    faces_.reserve(star.size());
    for (const Triangle3& t : star)
      faces_.push_back(read_face(t, p));
  }

  Location run() {
    if (faces_.empty()) {
      record(LocalSample{});
    } else {
      at_vertices();
      for (std::size_t i = 0; i < faces_.size() && !decided(); ++i) {
        for (std::size_t j = i + 1; j < faces_.size() && !decided(); ++j)
          at_crossing(faces_[i], faces_[j]);
      }
    }
    if (seen_in_ && seen_out_) return Location::boundary;
    return seen_in_ ? Location::inside : Location::outside;
  }

 private:
  bool decided() const { return seen_in_ && seen_out_; }

  void record(const LocalSample& sample) {
    (inside_at_(ray_.winding(sample)) ? seen_in_ : seen_out_) = true;
  }

  void at_vertices() {
    std::vector<Vec3> points;
    for (const Face& f : faces_) {
      for (const Vec3 v : {f.t.a, f.t.b, f.t.c})
        if (v != p_) points.push_back(v);
    }
    const auto less = [](Vec3 u, Vec3 v) {
      return u.x != v.x ? u.x < v.x : (u.y != v.y ? u.y < v.y : u.z < v.z);
    };
    std::sort(points.begin(), points.end(), less);
    points.erase(std::unique(points.begin(), points.end()), points.end());
    for (const Vec3 e : points) {
      for (const Face& f : faces_) {
        if (side(f, e) != Sign::zero) continue;
        for (const Vec3 v : {f.t.a, f.t.b, f.t.c}) {
          if (predicates::collinear(p_, e, v)) continue;
          for (const int s : {1, -1}) {
            LocalSample sample;
            sample.terms[0] = {.kind = LocalTerm::Kind::point, .point = e};
            sample.terms[1] = {.kind = LocalTerm::Kind::point, .point = v};
            sample.terms[2] = {.kind = LocalTerm::Kind::axis, .axis = f.axis, .sign = s};
            sample.count = 3;
            record(sample);
            if (decided()) return;
          }
        }
      }
    }
  }

  void at_crossing(const Face& f, const Face& g) {
    if (!arc_crosses_plane(f, g) || !arc_crosses_plane(g, f)) return;
    if (f.at == At::vertex && g.at == At::vertex) {
      // With A, B (C, D) the ends of f's (g's) arc from p: n_f x n_g lies inside both arcs iff
      // det(C, D, A) > 0 > det(C, D, B) and det(A, B, D) > 0 > det(A, B, C), its opposite iff
      // all four are reversed (arc_crosses_plane has made each pair opposite already).
      const Sign a = side(g, f.ends[0]), c = side(f, g.ends[0]);
      if (a != -c) return;
    }
    const BigVec3 nf = normal(f), ng = normal(g), x = cross(nf, ng);
    for (const BigVec3& y : {x, -x}) {
      if (!inside_arc(f, y, p_) || !inside_arc(g, y, p_)) continue;
      const BigVec3 along_f = cross(nf, y), along_g = cross(ng, y);
      const BigVec3 across[4] = {along_f, -along_f, along_g, -along_g};
      for (int s = 0; s < 4; ++s) {
        LocalSample sample;
        sample.terms[0] = {.kind = LocalTerm::Kind::vector, .vector = &y};
        sample.terms[1] = {.kind = LocalTerm::Kind::vector, .vector = &across[s & 1]};
        sample.terms[2] = {.kind = LocalTerm::Kind::vector, .vector = &across[2 + (s >> 1)]};
        sample.count = 3;
        record(sample);
        if (decided()) return;
      }
    }
  }

  Vec3 p_;
  const MeshRay& ray_;
  const std::function<bool(int)>& inside_at_;
  std::vector<Face> faces_;
  bool seen_in_ = false;
  bool seen_out_ = false;
};

}  // namespace

Location classify_surface_point(std::span<const Triangle3> star, Vec3 p, const MeshRay& ray,
                                const std::function<bool(int)>& inside_at) {
  return StarSampler(star, p, ray, inside_at).run();
}

}  // namespace contain::inside::detail
