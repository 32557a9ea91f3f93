// Stage 2 of the mesh boolean: candidate pairs of triangles from one hierarchy over the soup,
// and the exact intersection of each pair as constraints of both triangles (rule
// solid-pair-intersection in docs/robustness.md).
//
// Two triangles T and U in different planes meet in a segment of the line where their planes
// meet (or nowhere): T's part of that line runs between T's vertices on U's plane and the points
// where T's edges cross it (orient3d signs on the input doubles decide which, exactly), U's part
// likewise, and the intersection is the overlap of the two parts, ordered along the line by a
// coordinate in which the line's direction nT x nU is non-zero. Its ends are input vertices or
// edge-plane points (`line_plane`). Triangles in one plane are overlaid in that plane: each
// gets the other's edges as constraints (the refinement keeps their pieces inside it) and the
// other as a coplanar partner (which of them writes the common part is decided at output).
// An intersection made only of corners the two share (neighbours in a mesh) is no constraint.
// Pairs that share a vertex proven by star_proof.h (most neighbours) are skipped untested, and so
// are the pairs within a subtree of the hierarchy proven an embedded patch by patch_proof.h.

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/patch_proof.h"
#include "clip/solid/star_proof.h"
#include "contain/bvh/bvh.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/values/box.h"

namespace contain::clip::solid {
namespace {

using predicates::orient3d;

Vec3 corner(const Soup& soup, std::int32_t t, int i) {
  return soup.vertices[static_cast<std::size_t>(
      soup.triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)])];
}

std::int32_t vertex_id(const Soup& soup, std::int32_t t, int i) {
  return soup.triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)];
}

// Signs of t's corners against u's plane; a corner u shares is on it without a test (the
// filter of orient3d cannot decide an exact zero, the expansion stage would).
std::array<Sign, 3> sides(const Soup& soup, std::int32_t t, std::int32_t u) {
  const Vec3 a = corner(soup, u, 0), b = corner(soup, u, 1), c = corner(soup, u, 2);
  const TriangleIndices& vu = soup.triangles[static_cast<std::size_t>(u)];
  std::array<Sign, 3> s{};
  for (int i = 0; i < 3; ++i) {
    const std::int32_t id = vertex_id(soup, t, i);
    s[static_cast<std::size_t>(i)] = (id == vu[0] || id == vu[1] || id == vu[2])
                                         ? Sign::zero
                                         : orient3d(a, b, c, corner(soup, t, i));
  }
  return s;
}

// The corners off the plane all on one side, none on it but `shared` of them: the triangle
// meets the plane at most in the corners the two triangles share (no corner shared: not at all).
bool one_side(const std::array<Sign, 3>& s, int shared) {
  int zeros = 0, positive = 0, negative = 0;
  for (const Sign x : s) {
    zeros += x == Sign::zero ? 1 : 0;
    positive += x == Sign::positive ? 1 : 0;
    negative += x == Sign::negative ? 1 : 0;
  }
  return zeros <= shared && zeros < 3 && (positive == 0 || negative == 0);
}

// The points of the pair stage for the engine: every crossing rounded and stored once. The
// crossing of an edge with a plane is asked by both triangles on the edge (each meets the
// plane's triangle): the second gets the first's number from a table of (edge, plane's
// triangle) instead of being rounded again, compared exactly and renumbered.
class StoredPoints {
 public:
  explicit StoredPoints(PointStore& store) : store_(store) {}

  std::int32_t crossing(std::uint64_t edge, std::int32_t plane, Vec3 p, Vec3 q, Vec3 a, Vec3 b,
                        Vec3 c) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    std::size_t i = slot_of(edge, plane);
    if (slots_[i].id >= 0) return slots_[i].id;
    slots_[i] = {edge, plane, store_.add(line_plane(p, q, a, b, c))};
    ++used_;
    return slots_[i].id;
  }
  [[nodiscard]] const ExactPoint& point(std::int32_t i) const { return store_.point(i); }

 private:
  struct Slot {
    std::uint64_t edge = 0;
    std::int32_t plane = 0;
    std::int32_t id = -1;
  };
  [[nodiscard]] std::size_t slot_of(std::uint64_t edge, std::int32_t plane) const {
    std::uint64_t h = (edge ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(plane)) *
                               0x9e3779b97f4a7c15ULL)) *
                      0xff51afd7ed558ccdULL;
    h ^= h >> 32U;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = static_cast<std::size_t>(h) & mask;; i = (i + 1) & mask) {
      const Slot& s = slots_[i];
      if (s.id < 0 || (s.edge == edge && s.plane == plane)) return i;
    }
  }
  void grow() {
    std::vector<Slot> old(std::max<std::size_t>(1024, 2 * slots_.size()));
    old.swap(slots_);
    for (const Slot& s : old) {
      if (s.id >= 0) slots_[slot_of(s.edge, s.plane)] = s;
    }
  }
  PointStore& store_;
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

// The points of the pair stage for the check of a written mesh, which asks only whether pairs
// meet: the soup's vertices, then each crossing as made (enclosed, not rounded, not merged with
// an equal one: a crossing lies inside an edge of each triangle that makes it, so it is never a
// corner of that triangle and the tests on shared corners do not change).
struct EnclosedPoints {
  std::vector<ExactPoint> points;
  std::int32_t crossing(std::uint64_t /*edge*/, std::int32_t /*plane*/, Vec3 p, Vec3 q, Vec3 a,
                        Vec3 b, Vec3 c) {
    points.push_back(line_plane_enclosed(p, q, a, b, c));
    return static_cast<std::int32_t>(points.size() - 1);
  }
  [[nodiscard]] const ExactPoint& point(std::int32_t i) const {
    return points[static_cast<std::size_t>(i)];
  }
};

// One or two point ids (a plane cut's ends), without an allocation per pair.
struct Ends {
  std::array<std::int32_t, 3> id{};
  std::size_t size = 0;
  void push_back(std::int32_t p) { id[size++] = p; }
};

// The ends (one or two point ids) of t's part of u's plane, given t's signs against it (not all
// zero and not all on one side).
template <class Points>
Ends plane_cut(const Soup& soup, std::int32_t t, std::int32_t u, const std::array<Sign, 3>& s,
               Points& store) {
  Ends ends;
  for (int i = 0; i < 3; ++i) {
    if (s[static_cast<std::size_t>(i)] == Sign::zero) ends.push_back(vertex_id(soup, t, i));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (to_int(s[static_cast<std::size_t>(i)]) * to_int(s[static_cast<std::size_t>(j)]) < 0) {
      ends.push_back(store.crossing(edge_key(vertex_id(soup, t, i), vertex_id(soup, t, j)), u,
                                    corner(soup, t, i), corner(soup, t, j), corner(soup, u, 0),
                                    corner(soup, u, 1), corner(soup, u, 2)));
    }
  }
  return ends;
}

// The ends ordered by coordinate k (ascending); one end is used twice.
template <class Points>
std::array<std::int32_t, 2> ordered(const Ends& ends, const Points& store, int k) {
  if (ends.size == 1) return {ends.id[0], ends.id[0]};
  if (compare_coordinate(store.point(ends.id[0]), store.point(ends.id[1]), k) == Sign::positive) {
    return {ends.id[1], ends.id[0]};
  }
  return {ends.id[0], ends.id[1]};
}

bool shares(const Soup& soup, std::int32_t t, std::int32_t id) {
  const TriangleIndices& v = soup.triangles[static_cast<std::size_t>(t)];
  return v[0] == id || v[1] == id || v[2] == id;
}

int shared_corners(const Soup& soup, std::int32_t t, std::int32_t u) {
  int n = 0;
  for (int i = 0; i < 3; ++i)
    n += shares(soup, u, vertex_id(soup, t, i)) ? 1 : 0;
  return n;
}

// Two coplanar triangles sharing an edge overlap only when folded onto each other: their third
// corners on the same side of the edge, whichever way each triangle runs along it. Exactly: the
// four points lie in one plane, so their projection dropping an axis in which t's normal is
// non-zero (the plane's normal, u's too) keeps which side of the edge each third corner lies
// on, and neither lies on the edge's line (both triangles non-degenerate): orient2d of doubles
// (the normals' dot product in big numbers gave the same answer, at a hundred times the cost).
bool folded(const Soup& soup, std::int32_t t, std::int32_t u) {
  std::int32_t p = -1, q = -1, x = -1, y = -1;
  for (int i = 0; i < 3; ++i) {
    const std::int32_t v = vertex_id(soup, t, i);
    if (!shares(soup, u, v)) {
      x = v;
      p = vertex_id(soup, t, (i + 1) % 3);
      q = vertex_id(soup, t, (i + 2) % 3);
    }
    const std::int32_t w = vertex_id(soup, u, i);
    if (!shares(soup, t, w)) y = w;
  }
  const int axis = soup.projection(static_cast<std::size_t>(t)).axis;
  const auto at = [&](std::int32_t i) {
    return drop_axis(soup.vertices[static_cast<std::size_t>(i)], axis);
  };
  return predicates::orient2d(at(p), at(q), at(x)) == predicates::orient2d(at(p), at(q), at(y));
}

// The first axis in which the direction nt x nu of the planes' line is non-zero (nt, nu the
// normals (b - a) x (c - a), the triangles in different planes): the filter of `line_axis`, the
// exact normals where it does not decide.
int line_axis(const Soup& soup, std::int32_t t, std::int32_t u) {
  const std::optional<int> k =
      filtered_line_axis({corner(soup, t, 0), corner(soup, t, 1), corner(soup, t, 2)},
                         {corner(soup, u, 0), corner(soup, u, 1), corner(soup, u, 2)});
  if (k) return *k;
  const BigVec3 line = predicates::cross(soup.normal(static_cast<std::size_t>(t)),
                                         soup.normal(static_cast<std::size_t>(u)));
  int axis = 0;
  while (component(line, axis).is_zero())
    ++axis;
  return axis;
}

void add_coplanar(const Soup& soup, std::int32_t t, std::int32_t u, PairWork& work) {
  for (const auto& [to, from] : {std::pair{t, u}, std::pair{u, t}}) {
    work.add_coplanar(to, from);
    for (int i = 0; i < 3; ++i) {
      const std::int32_t a = vertex_id(soup, from, i), b = vertex_id(soup, from, (i + 1) % 3);
      work.add_constraint(to, {a, b, edge_key(a, b)});
    }
  }
}

template <class Points>
void intersect_pair(const Soup& soup, std::int32_t t, std::int32_t u, Points& store,
                    PairWork& work) {
  if (soup.degenerate[static_cast<std::size_t>(t)] ||
      soup.degenerate[static_cast<std::size_t>(u)]) {
    return;
  }
  const int shared = shared_corners(soup, t, u);
  if (shared == 2) {
    // Neighbours across an edge meet beyond it only when folded into one plane.
    const std::array<Sign, 3> su = sides(soup, u, t);
    if (su[0] == Sign::zero && su[1] == Sign::zero && su[2] == Sign::zero && folded(soup, t, u)) {
      add_coplanar(soup, t, u, work);
    }
    return;
  }
  const std::array<Sign, 3> su = sides(soup, u, t);
  if (one_side(su, shared)) return;
  if (su[0] == Sign::zero && su[1] == Sign::zero && su[2] == Sign::zero) {
    add_coplanar(soup, t, u, work);
    return;
  }
  const std::array<Sign, 3> st = sides(soup, t, u);
  if (one_side(st, shared)) return;
  const int k = line_axis(soup, t, u);
  const std::array<std::int32_t, 2> a = ordered(plane_cut(soup, t, u, st, store), store, k);
  const std::array<std::int32_t, 2> b = ordered(plane_cut(soup, u, t, su, store), store, k);
  const std::int32_t lo =
      compare_coordinate(store.point(a[0]), store.point(b[0]), k) == Sign::negative ? b[0] : a[0];
  const std::int32_t hi =
      compare_coordinate(store.point(a[1]), store.point(b[1]), k) == Sign::positive ? b[1] : a[1];
  if (compare_coordinate(store.point(lo), store.point(hi), k) == Sign::positive) return;
  if (shares(soup, t, lo) && shares(soup, u, lo) && shares(soup, t, hi) && shares(soup, u, hi)) {
    return;
  }
  work.add_constraint(t, {lo, hi});
  work.add_constraint(u, {lo, hi});
}

// Whether t and u share a corner that is a proven vertex of the soup (`corners` from
// `proven_corners`): then they meet only there or along their common edge, and `intersect_pair`
// would give nothing (star_proof.h).
bool share_proven_corner(const Soup& soup, const ScratchVector<std::uint8_t>& corners,
                         std::int32_t t, std::int32_t u) {
  const unsigned bits = corners[static_cast<std::size_t>(t)];
  const TriangleIndices& a = soup.triangles[static_cast<std::size_t>(t)];
  const TriangleIndices& b = soup.triangles[static_cast<std::size_t>(u)];
  // Without a branch per corner (which corners are shared varies from pair to pair).
  unsigned shared = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const unsigned in_b = static_cast<unsigned>(a[k] == b[0]) |
                          static_cast<unsigned>(a[k] == b[1]) | static_cast<unsigned>(a[k] == b[2]);
    shared |= in_b << k;
  }
  return (bits & shared) != 0;
}

// The item pairs of a leaf pair (a and b the same span: one leaf's pairs i < j) whose boxes
// meet, as bits i * 4 + j, tested without a branch per pair (whether two boxes of neighbouring
// triangles meet is a coin toss for the branch predictor). Leaves of at most 4 items.
template <class BoxOf>
std::uint32_t meeting_boxes(const BoxOf& box_of, std::span<const std::int32_t> a,
                            std::span<const std::int32_t> b) {
  const bool same = a.data() == b.data();
  // Each box once (computed from its corners where the soup keeps none).
  std::array<Box3, 4> qs;
  for (std::size_t j = 0; j < b.size(); ++j)
    qs[j] = box_of(b[j]);
  std::uint32_t bits = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Box3 p = same ? qs[i] : box_of(a[i]);
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Box3& q = qs[j];
      // As Box3::overlaps, with & for && (an empty box still meets nothing).
      const bool meet = (p.min.x <= q.max.x) & (q.min.x <= p.max.x) & (p.min.y <= q.max.y) &
                        (q.min.y <= p.max.y) & (p.min.z <= q.max.z) & (q.min.z <= p.max.z) &
                        (!same | (j > i));
      bits |= static_cast<std::uint32_t>(meet) << (4 * i + j);
    }
  }
  return bits;
}

template <class Points, class BoxOf>
PairWork pairs_of(const Soup& soup, Points& store, Neighbours neighbours, const BoxOf& box_of) {
  PairWork work(soup.triangles.size());
  // Pairs sharing a proven vertex are settled without their test.
  const bool patches_pay =
      neighbours == Neighbours::proven && soup.triangles.size() >= patch_proofs_from;
  ProvenStars stars;
  if (patches_pay) {
    stars = proven_stars(soup, StarOrder::leaf);
  } else if (neighbours == Neighbours::proven) {
    stars.corners = proven_corners(soup);
  } else {
    stars.corners.assign(soup.triangles.size(), 0);
  }
  // The pairs within a subtree proven an embedded patch of proven vertices are skipped
  // (patch_proof.h); the rest in the order of traverse_self (the order numbers the crossing
  // points).
  std::optional<PatchProofs> patches;
  if (patches_pay) {
    patches.emplace(PatchProofs::from_leaf_order(soup, stars));
    // What the proofs read once, given back before the walk, whose allocations (constraints,
    // the table of crossings, the store's growth) then take it over instead of fresh pages (the
    // call's pool, or the heap where the process keeps freed memory; each fresh page a fault).
    ScratchVector<std::uint8_t>().swap(stars.turns);
  }
  const ScratchVector<std::uint8_t>& corners = stars.corners;
  const auto pair = [&](std::int32_t t, std::int32_t u) {
    const std::int32_t lo = std::min(t, u), hi = std::max(t, u);
    if (!share_proven_corner(soup, corners, lo, hi)) intersect_pair(soup, lo, hi, store, work);
  };
  (void)bvh::traverse_self_leaves(
      soup.tree, [](const bvh::Node& a, const bvh::Node& b) { return a.box.overlaps(b.box); },
      [&](std::span<const std::int32_t> a, std::span<const std::int32_t> b) {
        if (a.size() > 4 || b.size() > 4) {
          const bool same = a.data() == b.data();
          for (std::size_t i = 0; i < a.size(); ++i) {
            for (std::size_t j = same ? i + 1 : 0; j < b.size(); ++j) {
              if (box_of(a[i]).overlaps(box_of(b[j]))) pair(a[i], b[j]);
            }
          }
          return bvh::Visit::proceed;
        }
        for (std::uint32_t bits = meeting_boxes(box_of, a, b); bits != 0; bits &= bits - 1) {
          const auto k = static_cast<std::size_t>(std::countr_zero(bits));
          pair(a[k / 4], b[k % 4]);
        }
        return bvh::Visit::proceed;
      },
      [&](std::int32_t node) { return !patches || !patches->settled(node); });
  work.finish();
  return work;
}

// pairs_of with the soup's boxes: kept (one per triangle) or, in a soup of make_soup, computed
// from the corners.
template <class Points>
PairWork pairs_of(const Soup& soup, Points& store, Neighbours neighbours) {
  if (soup.boxes.empty()) {
    return pairs_of(soup, store, neighbours, [&soup](std::int32_t t) {
      return triangle_box(soup, static_cast<std::size_t>(t));
    });
  }
  assert(soup.boxes.size() == soup.triangles.size());
  return pairs_of(soup, store, neighbours,
                  [&soup](std::int32_t t) { return soup.boxes[static_cast<std::size_t>(t)]; });
}

EnclosedPoints enclosed_vertices(const Soup& soup) {
  EnclosedPoints points;
  // Room for the crossings too: three per vertex (1,384 crossings of 456 vertices at a written
  // union of two 2,048-triangle spheres) where growing by doubling took fresh pages thrice.
  points.points.reserve(4 * soup.vertices.size() + 64);
  for (const Vec3 v : soup.vertices)
    points.points.push_back(exact_point(v));
  return points;
}

}  // namespace

PairWork intersect_pairs(const Soup& soup, PointStore& store, Neighbours neighbours) {
  StoredPoints points(store);
  return pairs_of(soup, points, neighbours);
}

PairWork meeting_pairs(const Soup& soup) {
  EnclosedPoints points = enclosed_vertices(soup);
  // Every pair tested: the check of a written mesh stays independent of the proofs, and gets
  // little from them (its soup is the neighbourhood of the rounded triangles, whose stars are
  // mostly open at its border or cut by the result's creases: at the 131k union 3,910 of the
  // 43,000 pairs reaching the tests shared a proven vertex, for a proof of every vertex).
  return pairs_of(soup, points, Neighbours::tested);
}

bool pair_gives_work(const Soup& soup, std::int32_t t, std::int32_t u) {
  EnclosedPoints points = enclosed_vertices(soup);
  const std::size_t before = points.points.size();
  PairWork work(soup.triangles.size());
  intersect_pair(soup, t, u, points, work);
  work.finish();
  if (points.points.size() != before) return true;
  return !work[static_cast<std::size_t>(t)].constraints.empty() ||
         !work[static_cast<std::size_t>(t)].coplanar.empty() ||
         !work[static_cast<std::size_t>(u)].constraints.empty() ||
         !work[static_cast<std::size_t>(u)].coplanar.empty();
}

void PairWork::finish() {
  if (!found_.empty()) {
    // A counting sort by triangle, stable: each triangle's constraints in the order found.
    // Counts, then the end of each triangle's run, then filled from the back, which leaves
    // first_[t] at the run's start (no second array of positions).
    first_.assign(triangles_ + 1, 0);
    for (const Found& f : found_)
      ++first_[static_cast<std::size_t>(f.t)];
    for (std::size_t t = 1; t <= triangles_; ++t)
      first_[t] += first_[t - 1];
    constraints_.resize(found_.size());
    for (auto f = found_.rbegin(); f != found_.rend(); ++f)
      constraints_[--first_[static_cast<std::size_t>(f->t)]] = f->c;
    ScratchVector<Found>().swap(found_);
  }
  std::stable_sort(partners_.begin(), partners_.end(),
                   [](const Partner& a, const Partner& b) { return a.t < b.t; });
  coplanar_.resize(partners_.size());
  for (std::size_t i = 0; i < partners_.size(); ++i)
    coplanar_[i] = partners_[i].u;
}

}  // namespace contain::clip::solid
