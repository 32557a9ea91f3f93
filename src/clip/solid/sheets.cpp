// Stage 6a of the mesh boolean: sheets kept apart where the result touches itself (rule
// solid-sheets in docs/robustness.md).
//
// Around an edge p q held by more than one pair of faces (two cubes sharing only an edge, the
// xor of overlapping boxes), the faces are sorted by angle about the axis q - p (exactly: the
// sign of det[q - p, r1 - p, r2 - p] within a half-turn from the first face's half-plane). A
// face running q -> p has the result on its side of increasing angle (its normal, the result
// behind it, points the other way), a face running p -> q on its side of decreasing angle: each
// q -> p face bounds one wedge of the result with the next face counter-clockwise, and these two
// are joined across the edge. Then the corners of faces joined across an edge (the one pair of a
// manifold edge, the pairs found at the others) are grouped; each group is one written vertex,
// so sheets meeting along an edge or at a point get their own vertices there.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/core/union_find.h"

namespace contain::clip::solid {
namespace {

struct Use {
  std::size_t face;
  int corner;    // the face's corner at the edge's first point (p of p q, the smaller id)
  bool forward;  // the face runs p -> q
};

// The corner of the face that is on neither end of the edge.
std::int32_t third(const std::vector<std::array<std::int32_t, 3>>& faces, const Use& u) {
  const auto& v = faces[u.face];
  // corners: p at u.corner; q is the next (forward) or previous corner; the third is the other.
  const int q = u.forward ? (u.corner + 1) % 3 : (u.corner + 2) % 3;
  return v[static_cast<std::size_t>(3 - u.corner - q)];
}

// Sorts the uses of edge p q by angle about q - p.
void sort_around(std::vector<Use>& uses, std::int32_t p, std::int32_t q,
                 const std::vector<std::array<std::int32_t, 3>>& faces, const PointStore& store) {
  const ExactPoint& pp = store.point(p);
  const BigVec3 axis = direction(pp, store.point(q));
  std::vector<BigVec3> spoke;  // d x (r - p): the direction of each half-plane about the axis
  for (const Use& u : uses)
    spoke.push_back(predicates::cross(axis, direction(pp, store.point(third(faces, u)))));
  const BigVec3 ref = spoke[0];
  std::vector<int> half(uses.size());
  for (std::size_t i = 0; i < uses.size(); ++i) {
    const Sign s = predicates::dot(predicates::cross(ref, spoke[i]), axis).sign();
    half[i] = s == Sign::positive ? 0
              : s == Sign::negative
                  ? 1
                  : (predicates::dot(ref, spoke[i]).sign() == Sign::positive ? 0 : 1);
  }
  std::vector<std::size_t> order(uses.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (half[a] != half[b]) return half[a] < half[b];
    // Within a half-turn, b follows a when it lies counter-clockwise of a about the axis.
    return predicates::dot(predicates::cross(spoke[a], spoke[b]), axis).sign() == Sign::positive;
  });
  std::vector<Use> sorted;
  for (const std::size_t i : order)
    sorted.push_back(uses[i]);
  uses = std::move(sorted);
}

}  // namespace

Sheets separate_sheets(const std::vector<std::array<std::int32_t, 3>>& faces,
                       const PointStore& store) {
  std::unordered_map<std::uint64_t, std::vector<Use>> uses;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = faces[f][static_cast<std::size_t>(k)],
                         b = faces[f][static_cast<std::size_t>((k + 1) % 3)];
      // Record the corner at the smaller id.
      uses[edge_key(a, b)].push_back({f, a < b ? k : (k + 1) % 3, a < b});
    }
  }
  UnionFind<std::size_t> corners(3 * faces.size());
  const auto join = [&](const Use& a, const Use& b) {
    // a's corner at p with b's corner at p, and the two corners at q.
    corners.unite(3 * a.face + static_cast<std::size_t>(a.corner),
                  3 * b.face + static_cast<std::size_t>(b.corner));
    const int qa = a.forward ? (a.corner + 1) % 3 : (a.corner + 2) % 3;
    const int qb = b.forward ? (b.corner + 1) % 3 : (b.corner + 2) % 3;
    corners.unite(3 * a.face + static_cast<std::size_t>(qa),
                  3 * b.face + static_cast<std::size_t>(qb));
  };
  for (auto& [key, list] : uses) {
    if (list.size() == 2) {
      join(list[0], list[1]);
      continue;
    }
    if (list.size() < 2) continue;  // left to the check
    const auto p = static_cast<std::int32_t>(key >> 32U),
               q = static_cast<std::int32_t>(key & 0xffffffffU);
    sort_around(list, p, q, faces, store);
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Use& u = list[i];
      const Use& next = list[(i + 1) % list.size()];
      if (!u.forward && next.forward) join(u, next);
    }
  }
  Sheets out;
  std::unordered_map<std::size_t, std::int32_t> vertex;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::array<std::int32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [it, fresh] =
          vertex.try_emplace(corners.find(3 * f + k), static_cast<std::int32_t>(out.points.size()));
      if (fresh) out.points.push_back(faces[f][k]);
      t[k] = it->second;
    }
    out.faces.push_back(t);
  }
  return out;
}

}  // namespace contain::clip::solid
