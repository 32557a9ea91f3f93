#pragma once
// The mesh boolean engine behind `clip::mesh_boolean`, stage by stage (one file each):
//   input.cpp      the inputs as one welded triangle soup, closedness checked
//   intersect.cpp  candidate pairs (BVH) and their exact intersections: constraints per triangle
//   refine.cpp     each triangle split by its constraints (triangulate.cpp: the constrained
//                  triangulation), points on shared edges given to every triangle on the edge
//   label.cpp      on both sides of each refined face, how many inputs fill it and whether
//                  the first input does
//   output.cpp     the faces on the result's boundary, coplanar ones merged (merge_faces.cpp),
//                  sheets kept apart (sheets.cpp), rounded and repaired by snap rounding
//                  (snap.cpp, snap.h), checked exactly (validate.cpp)
// Private to clip.

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "clip/solid/exact_point.h"
#include "clip/solid/scratch.h"
#include "contain/bvh/bvh.h"
#include "contain/clip/mesh_boolean.h"
#include "contain/core/result.h"
#include "contain/core/union_find.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"

namespace contain::clip::solid {

/// The points a PointTable numbers, in one array or two: point i is head[i] for i <
/// head.size(), else tail[i - head.size()]. Two, so that a point store keys its table by the
/// soup's vertices and its own later points without a copy of the vertices (PointStore).
struct PointKeys {
  std::span<const Vec3> head, tail;
  explicit(false) PointKeys(std::span<const Vec3> all) : head(all) {}
  template <class Allocator>
  explicit(false) PointKeys(const std::vector<Vec3, Allocator>& all) : head(all) {}
  PointKeys(std::span<const Vec3> first, std::span<const Vec3> then) : head(first), tail(then) {}
  [[nodiscard]] Vec3 operator[](std::size_t i) const {
    return i < head.size() ? head[i] : tail[i - head.size()];
  }
};

/// Numbers of points of doubles by value (+0 and -0 one key): open addressing, linear probing,
/// load at most 1/2, where a node-based map allocated per point and hashed each coordinate
/// byte by byte (the welding and the point store's index were a tenth of a boolean's time).
/// The table holds numbers and hash tags only (8 bytes a slot, so that it stays in cache); the
/// points are the caller's: `keys[i]` is the point numbered i.
class PointTable {
 public:
  void reserve(std::size_t points, PointKeys keys);
  /// The number stored under v and false; or `id`, now stored under v, and true (the caller
  /// then makes keys[id] == v).
  std::pair<std::int32_t, bool> try_emplace(Vec3 v, std::int32_t id, PointKeys keys);
  /// The number stored under v, or -1.
  [[nodiscard]] std::int32_t find(Vec3 v, PointKeys keys) const;
  [[nodiscard]] std::size_t size() const { return used_; }

 private:
  struct Slot {
    std::int32_t id = -1;
    std::uint32_t tag = 0;
  };
  [[nodiscard]] static std::uint64_t hash(Vec3 v);
  // The slot holding v, or the empty slot where it goes.
  [[nodiscard]] std::size_t slot_of(Vec3 v, std::uint64_t h, PointKeys keys) const;
  ScratchVector<Slot> slots_;
  std::size_t used_ = 0;
};

/// The points a store is given room for beside a soup's `vertices` (the crossings: a few per
/// hundred vertices on smooth large inputs, relatively more on small ones, about the square root
/// of the triangles; 1,020 at a pair of 2,048-triangle spheres). make_soup sizes its index for
/// this, so that the store takes the index over as its table (PointStore::add_vertices).
[[nodiscard]] inline std::size_t store_room(std::size_t vertices) {
  return vertices + vertices / 4 + 1024;
}

/// Every input's triangles in one soup, vertices welded by exact position across inputs.
class Soup {
 public:
  // Live through the whole call (no stage after reuses their memory): on the heap, as made.
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::vector<std::int32_t> input;  ///< the input of each triangle
  /// The exact normal (b - a) x (c - a) of triangle t, computed on first use (most triangles
  /// never need it). Not thread-safe: the engine runs on one thread.
  [[nodiscard]] const BigVec3& normal(std::size_t t) const;
  /// `dropped_axis` of `normal(t)` and that component's sign: by a filter in doubles, the exact
  /// normal only where the filter cannot tell (it is made for so many triangles otherwise).
  [[nodiscard]] Projection projection(std::size_t t) const;
  std::vector<bool> degenerate;  ///< zero area (normal zero): bounds nothing, skipped
  /// Empty, or one box per triangle for the pair stage and `tree` (a soup that gives some
  /// triangles empty boxes, region_soup in snap.cpp, or the boxes of a written mesh's check).
  /// Empty in a soup of make_soup: then a triangle's box is `triangle_box`, computed where
  /// needed (an array of them, 48 bytes a triangle, was the soup's largest, 12.6 MB of fresh
  /// pages at two 131k-triangle spheres, live through the pair stage at the process's peak).
  std::vector<Box3> boxes;
  bvh::Bvh tree;  ///< over the triangles' boxes: the pairs and the rays of the labels
  std::size_t inputs = 0;
  /// `vertices` numbered by value, as welded (empty for soups not made by make_soup).
  PointTable index;

 private:
  // One pointer per triangle, not the normal itself (120 bytes): most are never computed. On
  // the heap: made at the first normal asked for, mid-call, and live to the end, it would pin a
  // block amid the stages' blocks in the call's pool.
  mutable std::vector<std::unique_ptr<BigVec3>> normals_;
};

/// The box of triangle t of a soup from its corners (empty for a degenerate one: it meets
/// nothing), the box `Soup::boxes` would hold.
[[nodiscard]] inline Box3 triangle_box(const Soup& soup, std::size_t t) {
  Box3 box;
  if (soup.degenerate[t]) return box;
  for (const std::int32_t i : soup.triangles[t])
    box.expand(soup.vertices[static_cast<std::size_t>(i)]);
  return box;
}

/// Hashing and equality of points of doubles by value (+0 and -0 are one key: they are equal).
struct Vec3Hash {
  [[nodiscard]] std::size_t operator()(Vec3 v) const {
    const std::hash<double> h;
    return h(v.x + 0.0) ^ (h(v.y + 0.0) * 0x9e3779b97f4a7c15ULL) ^
           (h(v.z + 0.0) * 0xc2b2ae3d27d4eb4fULL);
  }
};
struct Vec3Equal {
  [[nodiscard]] bool operator()(Vec3 a, Vec3 b) const {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
};

/// Every exact point of the arrangement once; the input vertices first (point i is vertex i).
/// Lifetime: a store that took a soup's index (add_vertices) reads that soup's `vertices` where
/// they are, so the soup must outlive the store and keep its vertices unchanged (neither
/// modified nor reallocated) while the store is used.
class PointStore {
 public:
  /// Room for `points` in all, the first `soup_vertices` of them a soup's vertices that
  /// add_vertices will take (their doubles are read from the soup, not held: no room for them).
  void reserve(std::size_t points);
  /// The point's number, new or that of an equal point already stored.
  std::int32_t add(const ExactPoint& p);
  /// The same for a point of doubles (its own nearest doubles: no rounding to compute).
  std::int32_t add(Vec3 v);
  /// A soup's vertices as points 0 ... n - 1, in an empty store: as `add` of each, but a soup
  /// made by make_soup brings its index of them (distinct by welding), copied whole instead of
  /// rebuilt by one scattered insert per vertex (a tenth of a large boolean). Then the store
  /// reads `soup.vertices` in place: the soup must outlive the store, vertices unchanged.
  void add_vertices(const Soup& soup);
  /// The same with the soup's index given up to the store (moved, not copied): made by
  /// make_soup with room for `store_room` of its vertices, it is the store's table as it is,
  /// with no copy and no rebuild (a fresh table of megabytes, two copies of it before). Where
  /// the index is taken (both forms, a soup of make_soup into an empty store), the soup's
  /// `vertices` stay the doubles of points 0 ... n - 1, read where they are, not copied (3 MB
  /// of fresh pages at two 131k-triangle spheres): the soup must outlive the store and keep
  /// its vertices unchanged (neither modified nor reallocated).
  void add_vertices(const Soup& soup, PointTable&& index);
  [[nodiscard]] const ExactPoint& point(std::int32_t i) const {
    return points_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] Vec3 rounded(std::int32_t i) const { return keys()[static_cast<std::size_t>(i)]; }
  /// Whether point i is written exactly at `rounded(i)`: a point of doubles, or an implicit point
  /// whose enclosure is one double in every coordinate (others count as rounded even when exact).
  /// A byte per point kept as points are added: the written mesh asks it of every point it
  /// writes, where reading each 56-byte point was half of that stage's time (a cache miss each).
  [[nodiscard]] bool written_exactly(std::int32_t i) const {
    return exact_double_[static_cast<std::size_t>(i)] != 0;
  }
  [[nodiscard]] std::size_t size() const { return points_.size(); }
  /// The first stored point with the same nearest doubles as point i (i itself when none).
  [[nodiscard]] std::int32_t representative(std::int32_t i) const;
  /// The first stored point whose nearest doubles are r, or -1.
  [[nodiscard]] std::int32_t first_rounded_to(Vec3 r) const { return first_.find(r, keys()); }

 private:
  std::int32_t add(const ExactPoint& p, Vec3 r);
  // The nearest doubles of every point: the soup's vertices, then the points added after.
  [[nodiscard]] PointKeys keys() const { return {vertices_, rounded_}; }

  ScratchVector<ExactPoint> points_;
  std::span<const Vec3> vertices_;    // a soup's vertices (add_vertices), points 0 ... n - 1
  ScratchVector<Vec3> rounded_;       // the nearest doubles of the points after them
  PointTable first_;                  // the first point of each nearest doubles
  ScratchVector<std::int32_t> next_;  // the next point with the same nearest doubles, or -1
  // The first point with the same nearest doubles as each (itself for the first): known when
  // the point is added, where a lookup of its doubles was a probe of the table per point.
  ScratchVector<std::int32_t> first_of_;
  ScratchVector<std::uint8_t> exact_double_;  // written_exactly of each point
};

/// The key of the undirected input edge between welded vertices a and b.
[[nodiscard]] inline std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  const auto lo = static_cast<std::uint32_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (std::uint64_t{lo} << 32U) | hi;
}
inline constexpr std::uint64_t no_edge = ~std::uint64_t{0};

/// A segment (or a point, a == b) that a triangle must have as edges of its refinement.
struct Constraint {
  std::int32_t a = 0, b = 0;
  std::uint64_t edge = no_edge;  ///< the input edge it lies along (a coplanar partner's edge)
};

/// What the pair stage found for one triangle (views into its `PairWork`).
struct TriangleWork {
  std::span<const Constraint> constraints;  ///< in the order found
  std::span<const std::int32_t> coplanar;   ///< triangles in its plane whose boxes meet it
};

/// What the pair stage found for every triangle of a soup, in flat arrays grouped by triangle
/// (offsets into one array of constraints, the few coplanar partners by a search): most
/// triangles get nothing, and a vector of two vectors per triangle (48 bytes, 12.6 MB of fresh
/// pages at two 131k-triangle spheres) was the pair stage's largest allocation, live at the
/// process's peak.
class PairWork {
 public:
  PairWork() = default;
  explicit PairWork(std::size_t triangles) : triangles_(triangles) {}
  /// While the pairs are found: constraint c of triangle t, after those given before.
  void add_constraint(std::int32_t t, const Constraint& c) { found_.push_back({t, c}); }
  /// While the pairs are found: coplanar partner u of triangle t, after those given before.
  void add_coplanar(std::int32_t t, std::int32_t u) { partners_.push_back({t, u}); }
  /// Groups what was added by triangle, each triangle's in the order added; called once, after
  /// the last add and before any read.
  void finish();
  [[nodiscard]] std::size_t size() const { return triangles_; }
  [[nodiscard]] TriangleWork operator[](std::size_t t) const {
    // Before finish the partners are unsorted and coplanar_ empty: the search below would read
    // out of bounds.
    assert(found_.empty() && coplanar_.size() == partners_.size());
    TriangleWork w;
    if (!first_.empty()) {
      w.constraints = std::span<const Constraint>(constraints_)
                          .subspan(first_[t], static_cast<std::size_t>(first_[t + 1] - first_[t]));
    }
    if (!partners_.empty()) {
      const auto key = static_cast<std::int32_t>(t);
      const auto lo = std::lower_bound(partners_.begin(), partners_.end(), key,
                                       [](const Partner& p, std::int32_t x) { return p.t < x; });
      auto hi = lo;
      while (hi != partners_.end() && hi->t == key)
        ++hi;
      w.coplanar = std::span<const std::int32_t>(coplanar_).subspan(
          static_cast<std::size_t>(lo - partners_.begin()), static_cast<std::size_t>(hi - lo));
    }
    return w;
  }
  /// The constraints of all triangles.
  [[nodiscard]] std::size_t constraints() const { return constraints_.size(); }

 private:
  struct Found {
    std::int32_t t;
    Constraint c;
  };
  struct Partner {
    std::int32_t t, u;
  };
  std::size_t triangles_ = 0;
  ScratchVector<Found> found_;  // as added; emptied by finish
  ScratchVector<Constraint> constraints_;
  ScratchVector<std::uint32_t> first_;  // triangle t's constraints from first_[t] to first_[t + 1]
  ScratchVector<Partner> partners_;     // by triangle after finish (stable)
  ScratchVector<std::int32_t> coplanar_;  // partners_[i].u
};

/// One triangle of the refined surface, oriented as its input triangle.
struct RefinedFace {
  std::array<std::int32_t, 3> v{};
  std::int32_t triangle = 0;
};

/// The refined surface: faces, and the edges that lie on intersection curves (sorted pairs).
struct Refinement {
  ScratchVector<RefinedFace> faces;
  ScratchVector<std::uint64_t> curve_edges;  ///< edge_key of each piece of a constraint, sorted
};

/// What the operations ask of the inputs' winding numbers on one side of a face: how many
/// inputs fill that side (winding number > 0) and whether the first input does. (Every input's
/// number a patch made a union of n parts cost n a patch: n^2 in all.)
struct SideLabel {
  std::uint32_t filled = 0;
  bool first_filled = false;
};

/// The two sides of a face (front: where its normal points).
struct FaceLabel {
  SideLabel front, back;
};

/// The labels of the refined faces: one per patch (faces joined across edges that cross no
/// other surface share their labels), each face numbering its patch's (a copy per face was a
/// tenth of the labels' time, two allocations each).
struct FaceLabels {
  ScratchVector<FaceLabel> of_patch;
  ScratchVector<std::uint32_t> patch;  ///< of each face, an index into of_patch
};

/// The axis whose normal component is largest in magnitude (and non-zero): the one dropped to
/// work in a triangle's plane.
[[nodiscard]] int dropped_axis(const BigVec3& n);

/// The refined faces' patches (label_faces): two faces are joined across an edge held by exactly
/// these two, one each way, of triangles of the same input, that is not a curve edge; the set
/// of each face is its smallest face (UnionFind::find).
using PatchSets = UnionFind<std::uint32_t, ScratchAllocator<std::uint32_t>>;
[[nodiscard]] PatchSets face_patches(const Soup& soup, const Refinement& r);

[[nodiscard]] Result<Soup> make_soup(std::span<const Mesh> inputs);
/// Whether the pair stage first proves the soup's vertices (star_proof.h) and skips the pairs
/// that share a proven vertex, or tests every pair (the check of a written mesh; the tests that
/// compare the two).
enum class Neighbours : std::uint8_t { proven, tested };
[[nodiscard]] PairWork intersect_pairs(const Soup& soup, PointStore& store,
                                       Neighbours neighbours = Neighbours::proven);
/// The same decisions (the same constraints of each triangle, the same coplanar partners) with
/// points numbered apart from any store: the soup's vertices first, then each crossing as made,
/// enclosed but not rounded (for the check of a written mesh and the bounds of a snap round,
/// which ask only which pairs meet; the exact rounding of crossings of nearly parallel planes
/// was most of a failing snap's time).
[[nodiscard]] PairWork meeting_pairs(const Soup& soup);
[[nodiscard]] Refinement refine(const Soup& soup, const PairWork& work, PointStore& store);
/// Triangles of the constrained triangulation of triangle `corners` (oriented positively in
/// the projection dropping `axis` after multiplying orientations by `sense`) with `points`
/// (inside it or on its edges) and `pieces` (non-crossing, no point in their interiors).
[[nodiscard]] std::vector<std::array<std::int32_t, 3>> triangulate(
    const std::array<std::int32_t, 3>& corners, std::span<const std::int32_t> points,
    std::span<const std::array<std::int32_t, 2>> pieces, const PointStore& store, int axis,
    Sign sense);
[[nodiscard]] FaceLabels label_faces(const Soup& soup, const Refinement& refinement,
                                     const PointStore& store);
/// Faces with their corners renumbered so that sheets meeting along an edge or at a point have
/// their own vertices there: `points[i]` is the exact point of new vertex i.
struct Sheets {
  ScratchVector<std::array<std::int32_t, 3>> faces;
  ScratchVector<std::int32_t> points;
  /// Every edge of the given faces is held by exactly two of them, in opposite directions: then
  /// each directed edge of `faces` occurs once and its reverse once (the two faces of an edge
  /// share their renumbered corners at both its ends, and only they map to that edge's points).
  bool paired = false;
};
[[nodiscard]] Sheets separate_sheets(std::span<const std::array<std::int32_t, 3>> faces,
                                     const PointStore& store);

/// The sheets when every point's faces form one umbrella: its corners' faces joined across
/// their edges at the point, each edge there held by one face each way, in one cycle (a
/// closed 2-manifold's vertices). Then each point is one written vertex (numbered by first use)
/// and every edge is paired: what separate_sheets' grouping of edge uses gives, found from each
/// point's few corners without grouping the edges nor a union-find of every corner. nullopt when
/// some point is not such (an edge held once or by more than two faces, the same way twice, a
/// repeated corner, a point pinched between umbrellas, more than 64 corners at a point).
[[nodiscard]] std::optional<Sheets> single_umbrellas(
    std::span<const std::array<std::int32_t, 3>> faces);

/// separate_sheets by the faces' edge uses, every edge's faces paired around it, whatever the
/// faces: the general way.
[[nodiscard]] Sheets sheets_by_edges(std::span<const std::array<std::int32_t, 3>> faces,
                                     const PointStore& store);

}  // namespace contain::clip::solid
