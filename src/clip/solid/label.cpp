// Stage 4 of the mesh boolean: the inputs whose winding number is positive on each side of every
// refined face, as the operations ask them (rule solid-labels in docs/robustness.md).
//
// Faces are grouped into patches: two faces are joined across an edge that exactly these two
// faces hold, in opposite directions, from the same input, and that lies on no intersection
// curve. Along a patch no other surface is crossed, so every input's winding number is the same
// on the patch's front side everywhere, and on its back side. Each patch is labelled by two rays
// from a point c strictly inside its largest face (a point of doubles where one is proven there,
// else the face's centroid): the winding number of each input at the perturbed
// points c + s (e^3, e, e^2), s = +1 and -1, e > 0 infinitesimal, counted by the crossings of the
// ray +x from there (Simulation of Simplicity in the style of Edelsbrunner and Mucke: every sign
// that is zero at e = 0 is decided by the first non-zero coefficient of its expansion in e, all
// of them signs of input doubles). A perturbed point lies on no surface, so the count is exact
// for the side of the face it lies on, faces coinciding with this one included; the side is the
// sign of the face normal's first non-zero component in the order y, z, x.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/edge_uses.h"
#include "clip/solid/engine.h"
#include "contain/bvh/bvh.h"
#include "contain/core/sort_few.h"
#include "contain/core/union_find.h"
#include "contain/predicates/orient3d.h"
#include "contain/values/box.h"

namespace contain::clip::solid {
namespace {

Sign sign_of_difference(double b, double a) {
  return b > a ? Sign::positive : (b < a ? Sign::negative : Sign::zero);
}

// The label point of a patch: a point strictly inside one of its faces (a point of doubles, as a
// centroid of three equal corners, or the face's centroid), and the plane of that face's input
// triangle (corners and exact normal), which holds the face's corners.
struct LabelPoint {
  LazyCentroid centroid;
  std::array<Vec3, 3> plane;
  const BigVec3* normal;
};

// Sign of the (y, z) orientation of a, b and the perturbed point.
Sign edge_side(Vec3 a, Vec3 b, const LabelPoint& p, int s) {
  const Sign o = p.centroid.orient2d(a, b, 0, p.plane, *p.normal);
  if (o != Sign::zero) return o;
  const Sign dz = sign_of_difference(b.z, a.z);
  if (dz != Sign::zero) return s > 0 ? -dz : dz;
  const Sign dy = sign_of_difference(b.y, a.y);
  return s > 0 ? dy : -dy;
}

// +1 / -1 when the +x ray from the perturbed point crosses triangle t (its normal pointing to
// +x / -x), 0 when it misses.
int crossing(const Soup& soup, std::size_t t, const LabelPoint& p, int s) {
  const BigVec3& n = soup.normal(t);
  const Sign nx = n.x.sign();
  if (nx == Sign::zero) return 0;  // parallel to the ray: a generic ray misses it
  const TriangleIndices& v = soup.triangles[t];
  const Vec3 a = soup.vertices[static_cast<std::size_t>(v[0])],
             b = soup.vertices[static_cast<std::size_t>(v[1])],
             c = soup.vertices[static_cast<std::size_t>(v[2])];
  if (edge_side(a, b, p, s) != nx || edge_side(b, c, p, s) != nx || edge_side(c, a, p, s) != nx) {
    return 0;
  }
  Sign side = p.centroid.plane_side(a, b, c, n);
  if (side == Sign::zero) {
    side = n.y.sign() != Sign::zero ? n.y.sign() : (n.z.sign() != Sign::zero ? n.z.sign() : nx);
    if (s < 0) side = -side;
  }
  // The crossing lies beyond the point when n . (p - a) and n_x have opposite signs.
  return side == -nx ? to_int(nx) : 0;
}

// The inputs filled at the perturbed point: each input's winding number summed from the
// crossings of its triangles (`crossings`: scratch, kept between calls), sorted by input. A ray
// meets few inputs' surfaces, so only those are counted, not every input.
SideLabel side_label(const Soup& soup, const bvh::Bvh& tree, const LabelPoint& p, int s,
                     std::vector<std::pair<std::int32_t, int>>& crossings) {
  // The exact point lies in its enclosure: the boxes that may hold a crossing.
  const Enclosure& e = p.centroid.enclosure();
  const Vec3 lo{e.lo[0], e.lo[1], e.lo[2]};
  const Vec3 hi{e.hi[0], e.hi[1], e.hi[2]};
  const auto reaches = [&](const Box3& b) {
    return b.max.x >= lo.x && b.min.y <= hi.y && b.max.y >= lo.y && b.min.z <= hi.z &&
           b.max.z >= lo.z;
  };
  crossings.clear();
  (void)tree.traverse([&](const bvh::Node& node, std::int32_t) { return reaches(node.box); },
                      [&](std::int32_t t) {
                        const auto k = static_cast<std::size_t>(t);
                        if (const int c = crossing(soup, k, p, s); c != 0) {
                          crossings.emplace_back(soup.input[k], c);
                        }
                        return bvh::Visit::proceed;
                      });
  std::sort(crossings.begin(), crossings.end());
  SideLabel side;
  for (std::size_t i = 0; i < crossings.size();) {
    const std::int32_t input = crossings[i].first;
    int winding = 0;
    for (; i < crossings.size() && crossings[i].first == input; ++i)
      winding += crossings[i].second;
    if (winding > 0) {
      ++side.filled;
      side.first_filled = side.first_filled || input == 0;
    }
  }
  return side;
}

}  // namespace

// The uses of each edge are found at its lower point from that point's corners (a counting
// sort of the 3 F corners by point, 4 bytes each): a corner at p whose next point q > p is a use
// p -> q of edge p q, one whose previous point q > p a use q -> p. The faces joined are those of
// the edges with exactly one use each way, as a grouping of every edge use would find them
// (8 bytes a use, sorted per lower point): the sets depend only on which faces are joined.
PatchSets face_patches(const Soup& soup, const Refinement& r) {
  const CornersByPoint by_point = corners_by_point(
      r.faces.size(),
      [&](std::size_t f) -> const std::array<std::int32_t, 3>& { return r.faces[f].v; });
  const std::size_t points = by_point.points;
  const ScratchVector<std::uint32_t>& end = by_point.end;
  const ScratchVector<std::uint32_t>& corner = by_point.corner;
  // Faces are numbered in 31 bits (a use keeps a direction bit beside its face): sets of half
  // the size of std::size_t ones.
  assert(r.faces.size() < (std::size_t{1} << 31U));
  PatchSets sets(r.faces.size());
  // The lower points of the curve edges: most edges have none there and skip the search.
  ScratchVector<char> starts_curve(points + 1, 0);
  for (const std::uint64_t e : r.curve_edges) {
    const std::size_t lo = e >> 32U;
    if (lo < starts_curve.size()) starts_curve[lo] = 1;
  }
  // The uses at one point: (higher point << 32) | (face << 1) | (1 for q -> p), ascending.
  std::vector<std::uint64_t> uses;
  const auto use = [](std::int32_t q, std::uint32_t face, std::uint64_t back) {
    return (std::uint64_t{static_cast<std::uint32_t>(q)} << 32U) | (std::uint64_t{face} << 1U) |
           back;
  };
  for (std::size_t p = 0; p < points; ++p) {
    uses.clear();
    const auto a = static_cast<std::int32_t>(p);
    for (std::size_t i = p == 0 ? 0 : end[p - 1]; i < end[p]; ++i) {
      const std::uint32_t face = corner[i] / 3, k = corner[i] % 3;
      const auto& v = r.faces[face].v;
      if (v[(k + 1) % 3] > a) uses.push_back(use(v[(k + 1) % 3], face, 0));
      if (v[(k + 2) % 3] > a) uses.push_back(use(v[(k + 2) % 3], face, 1));
    }
    sort_few(uses.begin(), uses.end(), 16);
    for (std::size_t i = 0; i < uses.size();) {
      const auto b = static_cast<std::int32_t>(uses[i] >> 32U);
      std::size_t j = i + 1;
      while (j < uses.size() && static_cast<std::int32_t>(uses[j] >> 32U) == b)
        ++j;
      if (j - i == 2 && (uses[i] & 1U) != (uses[i + 1] & 1U)) {
        const auto x = static_cast<std::uint32_t>((uses[i] & 0xffffffffU) >> 1U);
        const auto y = static_cast<std::uint32_t>((uses[i + 1] & 0xffffffffU) >> 1U);
        if (soup.input[static_cast<std::size_t>(r.faces[x].triangle)] ==
                soup.input[static_cast<std::size_t>(r.faces[y].triangle)] &&
            (starts_curve[p] == 0 ||
             !std::binary_search(r.curve_edges.begin(), r.curve_edges.end(), edge_key(a, b)))) {
          sets.unite(x, y);
        }
      }
      i = j;
    }
  }
  return sets;
}

namespace {

// A point of doubles strictly inside the face, where the mean of its corners' nearest doubles
// (a coordinate they share taken as it is) is one, proven: on the plane of its input triangle
// (`plane`) and strictly on the inner side of its three edges. The labels are the same at every
// point inside a face, and at a point of doubles the rays' predicates are predicates on doubles
// (a centroid of constructed corners is a rational function of them, its orientations against
// edges in the same planes exact zeros: big numbers). Inputs whose faces lie in planes of
// doubles (axis-aligned parts) have such points; others mostly not (then nothing).
std::optional<Vec3> inner_double(const Soup& soup, const RefinedFace& face, const PointStore& store,
                                 const std::array<Vec3, 3>& plane) {
  const Vec3 r0 = store.rounded(face.v[0]), r1 = store.rounded(face.v[1]),
             r2 = store.rounded(face.v[2]);
  const auto mean = [](double a, double b, double c) {
    return a == b && b == c ? a : (a + b + c) / 3.0;
  };
  const Vec3 q{mean(r0.x, r1.x, r2.x), mean(r0.y, r1.y, r2.y), mean(r0.z, r1.z, r2.z)};
  if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return std::nullopt;
  if (predicates::orient3d(plane[0], plane[1], plane[2], q) != Sign::zero) return std::nullopt;
  const int axis = soup.projection(static_cast<std::size_t>(face.triangle)).axis;
  const ExactPoint &f0 = store.point(face.v[0]), &f1 = store.point(face.v[1]),
                   &f2 = store.point(face.v[2]);
  const Sign turn = orient2d_dropped(f0, f1, f2, axis);
  const ExactPoint p = exact_point(q);
  if (turn == Sign::zero || orient2d_dropped(f0, f1, p, axis) != turn ||
      orient2d_dropped(f1, f2, p, axis) != turn || orient2d_dropped(f2, f0, p, axis) != turn) {
    return std::nullopt;
  }
  return q;
}

}  // namespace

FaceLabels label_faces(const Soup& soup, const Refinement& refinement, const PointStore& store) {
  const bvh::Bvh& tree = soup.tree;
  // Each face's root looked up as the faces are labelled (no array of roots first).
  PatchSets patch = face_patches(soup, refinement);
  FaceLabels labels;
  labels.patch.resize(refinement.faces.size());
  std::vector<std::pair<std::int32_t, int>> crossings;
  // Every face of a patch has its labels: each patch is labelled from its largest face (by the
  // area of its corners' nearest doubles), which most likely holds a point of doubles inside
  // (`inner_double`; slivers along intersection curves, where unions of many parts make many,
  // hold none, and their centroids' predicates are near or exact zeros). Kept in the root's
  // entry of labels.patch until the root is labelled.
  const auto area = [&](std::size_t f) {
    const auto& v = refinement.faces[f].v;
    const Vec3 a = store.rounded(v[0]), b = store.rounded(v[1]), c = store.rounded(v[2]);
    const Vec3 u = b - a, w = c - a;
    const Vec3 n{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
    return n.x * n.x + n.y * n.y + n.z * n.z;
  };
  // The largest area so far of the last root met: faces of a patch mostly follow each other
  // (the pieces of one input triangle, then its neighbours), so the leader's area is not made
  // again for every face, nor its corners read again from far away. Any face chosen gives the
  // same labels; this is the same choice.
  std::size_t cached_root = labels.patch.size();
  double cached_area = 0.0;
  for (std::size_t f = 0; f < labels.patch.size(); ++f) {
    const std::size_t root = patch.find(static_cast<std::uint32_t>(f));
    if (root == f) {
      labels.patch[f] = static_cast<std::uint32_t>(f);
      continue;
    }
    if (root != cached_root) {
      cached_root = root;
      cached_area = area(labels.patch[root]);
    }
    const double own = area(f);
    if (own > cached_area) {
      labels.patch[root] = static_cast<std::uint32_t>(f);
      cached_area = own;
    }
  }
  for (std::size_t f = 0; f < labels.patch.size(); ++f) {
    const std::size_t root = patch.find(static_cast<std::uint32_t>(f));
    if (root != f) {
      labels.patch[f] = labels.patch[root];  // the root is the patch's first face: seen before
      continue;
    }
    const RefinedFace& face = refinement.faces[labels.patch[f]];
    labels.patch[f] = static_cast<std::uint32_t>(labels.of_patch.size());
    const auto t = static_cast<std::size_t>(face.triangle);
    const BigVec3& n = soup.normal(t);
    const TriangleIndices& corners = soup.triangles[t];
    const std::array<Vec3, 3> plane = {soup.vertices[static_cast<std::size_t>(corners[0])],
                                       soup.vertices[static_cast<std::size_t>(corners[1])],
                                       soup.vertices[static_cast<std::size_t>(corners[2])]};
    const ExactPoint &f0 = store.point(face.v[0]), &f1 = store.point(face.v[1]),
                     &f2 = store.point(face.v[2]);
    const std::optional<Vec3> inner = inner_double(soup, face, store, plane);
    const LabelPoint c{
        inner ? LazyCentroid(exact_point(*inner), exact_point(*inner), exact_point(*inner))
              : LazyCentroid(f0, f1, f2),
        plane, &n};
    const Sign first = n.y.sign() != Sign::zero
                           ? n.y.sign()
                           : (n.z.sign() != Sign::zero ? n.z.sign() : n.x.sign());
    const SideLabel plus = side_label(soup, tree, c, 1, crossings);
    const SideLabel minus = side_label(soup, tree, c, -1, crossings);
    labels.of_patch.push_back(first == Sign::positive ? FaceLabel{plus, minus}
                                                      : FaceLabel{minus, plus});
  }
  return labels;
}

}  // namespace contain::clip::solid
