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
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/edge_uses.h"
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
std::int32_t third(std::span<const std::array<std::int32_t, 3>> faces, const Use& u) {
  const auto& v = faces[u.face];
  // corners: p at u.corner; q is the next (forward) or previous corner; the third is the other.
  const int q = u.forward ? (u.corner + 1) % 3 : (u.corner + 2) % 3;
  return v[static_cast<std::size_t>(3 - u.corner - q)];
}

// Sorts the uses of edge p q by angle about q - p. With A = q - p and spoke_i = A x (r_i - p)
// (the half-plane of face i), dot(spoke_i x spoke_j, A) = |A|^2 det[A, r_i - p, r_j - p]: each
// turn is an orientation of four exact points, decided by the filter where it can
// (filtered_orient3d) and by the spokes' big numbers, made only then, where it cannot.
void sort_around(std::vector<Use>& uses, std::int32_t p, std::int32_t q,
                 std::span<const std::array<std::int32_t, 3>> faces, const PointStore& store) {
  const ExactPoint& pp = store.point(p);
  const ExactPoint& pq = store.point(q);
  std::vector<const ExactPoint*> far;
  for (const Use& u : uses)
    far.push_back(&store.point(third(faces, u)));
  std::optional<BigVec3> axis;
  std::vector<std::optional<BigVec3>> spoke(uses.size());
  const auto exact_axis = [&]() -> const BigVec3& {
    if (!axis) axis = direction(pp, pq);
    return *axis;
  };
  const auto exact_spoke = [&](std::size_t i) -> const BigVec3& {
    if (!spoke[i]) spoke[i] = predicates::cross(exact_axis(), direction(pp, *far[i]));
    return *spoke[i];
  };
  const auto turn = [&](std::size_t i, std::size_t j) {
    if (const std::optional<Sign> s = filtered_orient3d(pp, pq, *far[i], *far[j])) return *s;
    return predicates::dot(predicates::cross(exact_spoke(i), exact_spoke(j)), exact_axis()).sign();
  };
  std::vector<int> half(uses.size());
  for (std::size_t i = 0; i < uses.size(); ++i) {
    if (i == 0) {
      // No turn from the first half-plane to itself: in the first half iff spoke_0 . spoke_0 >
      // 0, i.e. r_0 off the line p q, i.e. some projection of p, q, r_0 not collinear.
      bool off_line = false;
      for (int k = 0; k < 3 && !off_line; ++k)
        off_line = orient2d_dropped(pp, pq, *far[0], k) != Sign::zero;
      half[0] = off_line ? 0 : 1;
      continue;
    }
    const Sign s = turn(0, i);
    half[i] =
        s == Sign::positive ? 0
        : s == Sign::negative
            ? 1
            : (predicates::dot(exact_spoke(0), exact_spoke(i)).sign() == Sign::positive ? 0 : 1);
  }
  std::vector<std::size_t> order(uses.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (half[a] != half[b]) return half[a] < half[b];
    // Within a half-turn, b follows a when it lies counter-clockwise of a about the axis.
    return turn(a, b) == Sign::positive;
  });
  std::vector<Use> sorted;
  for (const std::size_t i : order)
    sorted.push_back(uses[i]);
  uses = std::move(sorted);
}

}  // namespace

namespace {

int q_corner(const Use& u) {
  return u.forward ? (u.corner + 1) % 3 : (u.corner + 2) % 3;
}

// The faces around one edge held by more than two, sorted by angle, and which pairing is used:
// each q -> p face with the face 1 + 2 shift places after it.
struct Fan {
  std::uint64_t key =
      0;  // the edge (fans are kept in key order: the same output on every platform)
  std::vector<Use> sorted;
  std::size_t shift = 0;
};

// The face each q -> p face of the fan is joined with. Sorted by angle, the faces of an exact
// result alternate in direction, and each q -> p face is paired with the face 1 + 2 shift places
// after it. Rounding can break the alternation: points merged into one vertex can bring two
// faces of opposite directions into one half-plane (a fold of zero width, sorted either way) or
// fold a face past another. There each q -> p face is paired with a p -> q face as brackets are
// (q -> p opens, p -> q closes, from the place where the open count is lowest), which pairs a
// fold's two faces when they sort in the alternating order and still when they do not: every
// directed edge is then matched once, and the check of the written mesh finds the fold's
// crossing as a pair to repair (a local snap round), not as an unmatched edge (a whole one).
std::vector<std::size_t> partners(const Fan& fan) {
  const std::size_t n = fan.sorted.size();
  std::vector<std::size_t> partner(n, 0);
  bool alternating = true;
  for (std::size_t i = 0; i < n; ++i)
    alternating = alternating && fan.sorted[i].forward != fan.sorted[(i + 1) % n].forward;
  if (alternating) {
    for (std::size_t i = 0; i < n; ++i)
      partner[i] = (i + 1 + 2 * fan.shift) % n;
    return partner;
  }
  // The faces of an edge are balanced (as many q -> p as p -> q: merging points and cancelling
  // faces keeps that), so after the lowest open count every bracket closes.
  std::ptrdiff_t open = 0, lowest = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < n; ++i) {
    open += fan.sorted[i].forward ? -1 : 1;
    if (open < lowest) {
      lowest = open;
      start = i + 1;
    }
  }
  std::vector<std::size_t> pending;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (start + k) % n;
    if (!fan.sorted[i].forward) {
      pending.push_back(i);
    } else if (!pending.empty()) {
      partner[pending.back()] = i;
      pending.pop_back();
    }
  }
  return partner;
}

// The faces' corners (3 face + k) in sets of 32-bit numbers, half the memory of std::size_t
// ones: the written vertices, one per set, are numbered in 32 bits anyway.
using CornerSets = UnionFind<std::uint32_t>;

std::uint32_t corner_number(std::size_t face, int k) {
  return static_cast<std::uint32_t>(3 * face + static_cast<std::size_t>(k));
}

void join_across(CornerSets& sets, const Use& a, const Use& b) {
  sets.unite(corner_number(a.face, a.corner), corner_number(b.face, b.corner));
  sets.unite(corner_number(a.face, q_corner(a)), corner_number(b.face, q_corner(b)));
}

struct Grouping {
  // The corners joined across the edges held by two faces, joined as they are found (no list
  // of the pairs: one per edge of the result); the sets depend only on which corners are
  // joined, not on the order (UnionFind's representative is the smallest element).
  CornerSets manifold;
  std::vector<Fan> fans;

  [[nodiscard]] CornerSets corners() const {
    CornerSets sets = manifold;
    for (const Fan& fan : fans) {
      const std::vector<std::size_t> partner = partners(fan);
      for (std::size_t i = 0; i < fan.sorted.size(); ++i) {
        if (!fan.sorted[i].forward) join_across(sets, fan.sorted[i], fan.sorted[partner[i]]);
      }
    }
    return sets;
  }

  // Fans whose passes end in the same vertex pair (the edge would be written twice) move on to
  // their next pairing; false when there was none.
  bool shift_pinched(CornerSets& sets) {
    bool any = false;
    for (Fan& fan : fans) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
      for (const Use& u : fan.sorted) {
        if (u.forward) continue;
        ends.emplace_back(sets.find(corner_number(u.face, u.corner)),
                          sets.find(corner_number(u.face, q_corner(u))));
      }
      std::sort(ends.begin(), ends.end());
      if (std::adjacent_find(ends.begin(), ends.end()) != ends.end()) {
        fan.shift = (fan.shift + 1) % std::max<std::size_t>(fan.sorted.size() / 2, 1);
        any = true;
      }
    }
    return any;
  }
};

}  // namespace

std::optional<Sheets> single_umbrellas(std::span<const std::array<std::int32_t, 3>> faces) {
  // The corners (3 face + k, corner_number) of each point (32-bit: faces are numbered in 32
  // bits).
  const CornersByPoint by_point = corners_by_point(
      faces.size(), [&](std::size_t f) -> const std::array<std::int32_t, 3>& { return faces[f]; });
  const std::size_t points = by_point.points;
  const ScratchVector<std::uint32_t>& end = by_point.end;
  const ScratchVector<std::uint32_t>& corner = by_point.corner;
  // Around each point: the corners' next and previous points, each corner's successor across
  // the edge to its next point (the one corner whose previous point that is), and one walk.
  constexpr std::size_t most = 64;  // a point with more corners takes the general way
  std::array<std::int32_t, most> next{}, previous{};
  std::array<std::uint8_t, most> successor{}, hit{};
  for (std::size_t p = 0; p < points; ++p) {
    const std::size_t first = p == 0 ? 0 : end[p - 1];
    const std::size_t count = end[p] - first;
    if (count == 0) continue;
    if (count > most) return std::nullopt;
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint32_t c = corner[first + i];
      const auto& v = faces[c / 3];
      const std::uint32_t k = c % 3;
      next[i] = v[(k + 1) % 3];
      previous[i] = v[(k + 2) % 3];
      hit[i] = 0;
      if (next[i] == static_cast<std::int32_t>(p) || previous[i] == static_cast<std::int32_t>(p)) {
        return std::nullopt;  // a repeated corner
      }
    }
    for (std::size_t i = 0; i < count; ++i) {
      std::size_t found = count;
      for (std::size_t j = 0; j < count; ++j) {
        if (previous[j] != next[i]) continue;
        if (found != count) return std::nullopt;  // the edge held twice the other way
        found = j;
      }
      if (found == count || hit[found] != 0) return std::nullopt;  // open, or held twice
      hit[found] = 1;
      successor[i] = static_cast<std::uint8_t>(found);
    }
    // A permutation (each corner hit once): the walk returns to corner 0 within count steps.
    std::size_t at = successor[0], steps = 1;
    for (; at != 0 && steps <= count; ++steps)
      at = successor[at];
    if (steps != count) return std::nullopt;  // several umbrellas: a pinched point
  }
  // One set per point: written vertices numbered by first use, as the general way numbers the
  // corner sets.
  Sheets out;
  out.paired = true;
  ScratchVector<std::int32_t> vertex(points, -1);
  out.faces.reserve(faces.size());
  for (const auto& f : faces) {
    std::array<std::int32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      std::int32_t& w = vertex[static_cast<std::size_t>(f[k])];
      if (w < 0) {
        w = static_cast<std::int32_t>(out.points.size());
        out.points.push_back(f[k]);
      }
      t[k] = w;
    }
    out.faces.push_back(t);
  }
  return out;
}

// A pairing of the faces by angle joins the sheets that bound one wedge of the result; where a
// sheet touches itself along an edge and is connected around both its ends (a vertex pinched
// by the edge: boxes stacked in a staircase around a corner), that pairing leaves the two
// passes with the same vertices at both ends, and the edge is paired the other way (each q -> p
// face with a later face running p -> q). Both pairings hold the same triangles: the check of
// the written mesh judges the result.
Sheets separate_sheets(std::span<const std::array<std::int32_t, 3>> faces,
                       const PointStore& store) {
  if (std::optional<Sheets> simple = single_umbrellas(faces)) return std::move(*simple);
  return sheets_by_edges(faces, store);
}

Sheets sheets_by_edges(std::span<const std::array<std::int32_t, 3>> faces,
                       const PointStore& store) {
  // Every use grouped by its edge, in face order within an edge (the order the fans start
  // from): EdgeUses, a counting sort of the edges' lower points.
  const EdgeUses uses = edge_uses(
      faces.size(), [&](std::size_t f) -> const std::array<std::int32_t, 3>& { return faces[f]; });
  // The use of the i-th entry of an edge p q's group (a face holding the edge twice is there
  // twice: its uses in order of corner).
  const auto use = [&](std::int32_t p, std::int32_t q, std::span<const std::uint64_t> group,
                       std::size_t i) {
    const std::uint32_t face = EdgeUses::face(group[i]);
    int nth = 0;  // the face's uses before this one (a face {a, a, a} holds its edge thrice)
    for (std::size_t j = i; j > 0 && EdgeUses::face(group[j - 1]) == face; --j)
      ++nth;
    const int k = corner_of_edge(faces[face], p, q, nth);
    const std::int32_t a = faces[face][static_cast<std::size_t>(k)],
                       b = faces[face][static_cast<std::size_t>((k + 1) % 3)];
    return Use{face, a < b ? k : (k + 1) % 3, a < b};
  };
  Grouping grouping{CornerSets(3 * faces.size()), {}};
  bool paired = true;
  for_each_edge(uses, [&](std::int32_t p, std::int32_t q, std::span<const std::uint64_t> group) {
    if (group.size() == 2) {
      const Use a = use(p, q, group, 0), b = use(p, q, group, 1);
      paired = paired && a.forward != b.forward;
      join_across(grouping.manifold, a, b);
      return;
    }
    paired = false;
    if (group.size() < 2) return;  // a single face is left to the check
    std::vector<Use> list;
    for (std::size_t k = 0; k < group.size(); ++k)
      list.push_back(use(p, q, group, k));
    sort_around(list, p, q, faces, store);
    grouping.fans.push_back({edge_key(p, q), std::move(list), 0});
  });
  // Visited in key order already (the same output on every platform).
  // With no fans the manifold sets are the corner sets (no copy of them).
  CornerSets corners = grouping.fans.empty() ? std::move(grouping.manifold) : grouping.corners();
  for (int round = 0; round < 8 && grouping.shift_pinched(corners); ++round) {
    corners = grouping.corners();
  }
  Sheets out;
  out.paired = paired;
  std::vector<std::int32_t> vertex(3 * faces.size(), -1);  // of each corner set's root
  out.faces.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::array<std::int32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      std::int32_t& v = vertex[corners.find(corner_number(f, static_cast<int>(k)))];
      if (v < 0) {
        v = static_cast<std::int32_t>(out.points.size());
        out.points.push_back(faces[f][k]);
      }
      t[k] = v;
    }
    out.faces.push_back(t);
  }
  return out;
}

}  // namespace contain::clip::solid
