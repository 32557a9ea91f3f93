#pragma once
/// \file
/// A prepared triangle mesh for many point-in-polyhedron queries: exact ray parity over a grid
/// that settles most of space at build time, or, for meshes that are not closed, the generalized
/// winding number.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "contain/core/huge_pages.h"
#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/inside/fast_winding_number.h"
#include "contain/inside/grid_axis.h"
#include "contain/inside/solid_rule.h"
#include "contain/predicates/sign.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/mesh_validation.h"
#include "contain/values/box.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// How a `MeshIndex` answers, chosen from the mesh's `MeshReport`.
enum class MeshRegime : std::uint8_t {
  /// A closed mesh: every directed edge (by its corners' positions) occurs as often as its
  /// reverse, or every edge has exactly two triangles. Exact: the solid of the mesh (winding
  /// number positive), or ray parity where only the second holds (inconsistent orientation).
  closed_exact,
  /// Any other mesh (border edges, unmatched non-manifold edges): inside where the generalized
  /// winding number is >= 0.5 (approximate near the surface); `boundary` is still exact.
  winding_number,
};

/// The enumerator's name: "closed_exact" or "winding_number" (io words it for a person).
[[nodiscard]] const char* to_string(MeshRegime regime);

/// How a `MeshIndex` is built.
struct MeshIndexOptions {
  /// Grid resolution for the exact regime: about this many cells per triangle ...
  double cells_per_triangle = 16.0;
  /// ... at least this many ...
  std::size_t min_cells = 4096;
  /// ... and at most this many (memory: about 5.25 bytes a cell, 4 per triangle-cell pair).
  std::size_t max_cells = std::size_t{1} << 24;
  /// Accuracy of the winding number regime (see `FastWindingNumberOptions`).
  double winding_accuracy = 3.0;
  /// How many points the caller means to locate (0: not known, many). Building the grid costs
  /// about as much as 260 queries without it (a measured cost model, mesh_index.cpp, whatever
  /// the mesh's size); for fewer queries the exact regime builds no grid and each query tests
  /// every triangle, with the same answers.
  std::size_t queries = 0;
};

/// A triangle mesh prepared for exact point location.
///
/// Regime `closed_exact`, the **solid's rule** (the rule of `clip::mesh_boolean` and of
/// ../shared/spec/cli.md, "Solids"), for a mesh whose directed edges all match (each occurs as
/// often as its reverse, by position; non-manifold edges allowed): the solid is where the winding
/// number is positive. Overlapping parts of a self-intersecting mesh count once; a shell turned
/// inside out subtracts (alone it is empty: a whole mesh turned inside out holds no point). The
/// winding number of a point off the surface is the signed count of the crossings of the
/// **perturbed +x ray rule** (docs/robustness.md; include/contain/predicates/perturbed_ray.h):
/// the ray from p along +x, its origin moved symbolically by (0, e, e^2), so that it never meets
/// an edge or a vertex; a crossing counts +1 where the triangle's normal points along +x, -1
/// where against. A point on a triangle (orient3d == 0 and the exact point in triangle) is
/// `boundary` only where it lies on the solid's boundary: the open cells around it, cut by the
/// triangles through it, are sampled symbolically beside every arc those triangles trace on a
/// small sphere about it (inside/surface_star.h) and it is `inside` if every one is inside (a
/// face buried in another part, the shared face of two touching shells), `outside` if none is (a
/// face of an inverted shell alone), else `boundary`.
/// A mesh whose every edge has exactly two triangles but whose orientation is inconsistent has
/// no winding number: there the answer is the crossing parity (odd is `inside`) and every
/// surface point is `boundary`. Exact on the given doubles for every point (checked against a
/// GMP oracle), deterministic.
///
/// Structure: a uniform grid over the bounding box; a point is assigned its cell by exact
/// comparisons with the grid lines (half-open cells, the last closed). Cells that no triangle's
/// closed box meets (an exact, conservative test) hold no surface, so one winding number holds in
/// the whole closed cell: it is computed once at build time, row by row from +x to -x. A cell the
/// surface may touch keeps its triangles; a query there follows its own ray along the row of
/// cells until the first empty cell, whose winding number it adds, counting the perturbed hits
/// inside each cell's half-open slab [X_i, X_i+1) of x (a hit exactly on a grid plane is decided
/// by the same perturbation), so each hit is counted once. (It takes the shortest of six such
/// walks: along +x, or -x subtracting the hits behind it from the empty cell's number, or along
/// y or z by the same rule on cyclically permuted coordinates; the winding number, and a count's
/// parity, are the same whichever ray counts them.)
///
/// Regime `winding_number` (any other mesh: border edges, unmatched edges): `boundary` exactly as
/// a point on a triangle, else `inside` where the generalized winding number is >= 0.5
/// (FastWindingNumber; floating point). `regime()` and `report()` say which regime applies and
/// why, as data (the command and the Python module word them with `io::mesh_warning`); pinch
/// vertices, inconsistent orientation and degenerate or duplicated triangles of a closed mesh
/// keep the exact regime.
///
/// Complexity: build O(n log n + C) for n triangles and C cells; a query O(1) outside the box or
/// in an empty cell, else O(triangles met along the run of surface cells); a point on the surface
/// O(triangles in the rows of cells from it along +x) plus O(k^2) filtered predicates for the k
/// triangles through it when two samples beside one face prove it `boundary` (the usual case),
/// else O(k) samples of O(k) crossing tests each (a vertex of degree 64 buried in another part:
/// about a millisecond), plus four samples where two of those triangles cross each other at the
/// point (a folded fan); winding regime about O(log n). Thread
/// safety: const queries may run concurrently; answers do not depend on the thread count.
/// Reference: "Algorithms of Informatics" vol. 2, § 22.4 (ray crossings), Edelsbrunner and Muecke
/// 1990 (SoS).
class MeshIndex {
 public:
  /// An empty index: every point is `outside`.
  MeshIndex() = default;
  /// Prepares `mesh` (validated: finite coordinates, indices in range; any topology).
  explicit MeshIndex(const Mesh& mesh, const MeshIndexOptions& options = {});
  /// The same; where the index keeps the mesh itself (the exact regime for few queries) it takes
  /// `mesh` over instead of copying it, else `mesh` is left as it was.
  explicit MeshIndex(Mesh&& mesh, const MeshIndexOptions& options = {});

  /// Where `point` lies.
  [[nodiscard]] Location locate(Vec3 point) const;

  /// The location every point of the closed box `box` has, when the index knows it without
  /// looking at a point (regime `closed_exact` only): the box wholly beyond the triangles'
  /// bounds (`outside`), or strictly inside one grid cell that no triangle's box meets (its
  /// stored answer); none otherwise (a box touching a cell's side, a surface cell, a box over
  /// several cells, no grid, the winding regime). Exact comparisons only, so an answer given is
  /// `locate(p)` for every p in the box. O(1).
  [[nodiscard]] std::optional<Location> locate_settled(const Box3& box) const;
  /// Locates `points[i]` into `out[i]` for every i (`out` has the points' size: `batch_size`), in
  /// parallel on `options.threads` threads (0: all). Deterministic.
  void locate(std::span<const Vec3> points, std::span<Location> out,
              const BatchOptions& options = {}) const;

  /// The regime in use.
  [[nodiscard]] MeshRegime regime() const { return regime_; }
  /// How a signed crossing count reads (solid_rule.h): `winding` or `parity` in regime
  /// `closed_exact`, `none` in regime `winding_number`.
  [[nodiscard]] SolidRule rule() const {
    if (regime_ == MeshRegime::winding_number) return SolidRule::none;
    return by_parity_ ? SolidRule::parity : SolidRule::winding;
  }
  /// Regime `closed_exact` only: whether a point whose signed crossing count (as the class
  /// comment counts it) is `count` is inside: `count > 0` (the solid's rule), or `count` odd for
  /// a mesh without a winding number (every edge of two triangles, inconsistent orientation).
  [[nodiscard]] bool inside_by_count(int count) const {
    return inside::inside_by_count(by_parity_ ? SolidRule::parity : SolidRule::winding, count);
  }
  /// The validation of the mesh.
  [[nodiscard]] const MeshReport& report() const { return report_; }
  /// The bounding box of the triangles.
  [[nodiscard]] const Box3& bounds() const { return bounds_; }

  /// Sizes of the structure, for benchmarks and tuning.
  struct Stats {
    std::size_t triangles = 0;
    std::size_t cells = 0;          ///< grid cells (exact regime; 0 without a grid: few queries)
    std::size_t surface_cells = 0;  ///< cells some triangle's box meets
    std::size_t cell_refs = 0;      ///< triangle-cell pairs
    int nx = 0, ny = 0, nz = 0;
  };
  [[nodiscard]] Stats stats() const { return stats_; }

 private:
  // The cell p's doubles guess (the exact cell may be a neighbour); -1 outside the box.
  [[nodiscard]] std::ptrdiff_t guessed_cell(Vec3 p) const {
    if (!bounds_.contains(p)) return -1;
    return (static_cast<std::ptrdiff_t>(z_.guess(p.z)) * ny_ + y_.guess(p.y)) * nx_ + x_.guess(p.x);
  }
  // Saving and loading (src/inside/mesh_index_file.cpp) read and write every member.
  friend struct MeshIndexFile;

  struct Tri {
    Vec3 a, b, c;
    float lo[3], hi[3];  // box rounded outward to float: a quick, safe rejection test
    Sign s;              // sign of the (y, z) projection: zero if never crossed by an x ray
    // The padding, explicit and zeroed: index files store the records as they lie in memory.
    std::uint8_t zero[7] = {};
  };

  [[nodiscard]] static Tri make_tri(Vec3 a, Vec3 b, Vec3 c);

  // An index built only to be saved (MeshIndexToSave, index_file.h): the records' hashes are
  // summed as they are made and the winding regime's tree is not built; such an index answers
  // no query.
  struct ForSaving {};
  MeshIndex(const Mesh& mesh, const MeshIndexOptions& options, ForSaving /*tag*/);

  // Construction, stage by stage (mesh_index.cpp).
  [[nodiscard]] bool prepare(const Mesh& mesh, const MeshIndexOptions& options);
  void read_triangles(const Mesh& mesh);
  void read_triangles_by_cell(const Mesh& mesh);
  void list_triangles_by_cell();
  template <class Cell>
  void list_triangles_by_cell_as();
  void settle_empty_cells();
  void pack_states();
  // A cell's state (as state_) from the packed copy: two bits a cell.
  [[nodiscard]] std::uint8_t packed_state(std::size_t cell) const {
    return static_cast<std::uint8_t>((packed_state_[cell / 4] >> (2 * (cell % 4))) & 3U);
  }

  [[nodiscard]] static bool outside_box(const Tri& r, Vec3 p) {
    return (p.x < r.lo[0]) | (p.x > r.hi[0]) | (p.y < r.lo[1]) | (p.y > r.hi[1]) | (p.z < r.lo[2]) |
           (p.z > r.hi[2]);
  }
  [[nodiscard]] bool on_triangle(const Tri& t, Vec3 p) const;
  // The signed crossing count of a point in a surface cell along an axis (mesh_index.cpp, "Walks").
  template <int Axis>
  [[nodiscard]] int count_walk(Vec3 p, std::size_t cell, int first, int step) const;
  [[nodiscard]] int count_shortest_walk(Vec3 p, std::size_t cell, int i, int j, int k) const;
  [[nodiscard]] Location locate_exact(Vec3 p) const;
  [[nodiscard]] Location locate_direct(Vec3 p) const;
  [[nodiscard]] Location locate_direct_on_surface(Vec3 p,
                                                  const std::vector<std::uint8_t>& sides) const;
  [[nodiscard]] Location locate_on_surface(Vec3 p) const;
  [[nodiscard]] Location classify_on_surface(Vec3 p, const std::vector<std::uint32_t>& near) const;
  [[nodiscard]] Location classify_near(Vec3 p, std::span<const Triangle3> near) const;
  [[nodiscard]] Location locate_winding(Vec3 p) const;

  MeshRegime regime_ = MeshRegime::closed_exact;
  bool by_parity_ = false;  // closed_exact without a winding number: inside where the count is odd
  MeshReport report_;
  Box3 bounds_;
  HugePageVector<Tri> tris_;  // huge pages: the big arrays are built in one pass each
  // Exact regime for few queries (no grid): the mesh itself, tris_ left empty (its records would
  // be four times the mesh's bytes, written for one pass over them).
  Mesh mesh_;
  // Grid (exact regime).
  GridAxis x_, y_, z_;
  int nx_ = 0, ny_ = 0, nz_ = 0;  // their cell counts
  // Per cell: 0 outside, 1 inside (empty cells), 2 surface cell, a byte each: what the build
  // settles and the index file holds; the queries read packed_state_.
  HugePageVector<std::uint8_t> state_;
  // The same states, four cells a byte (cell c: bits 2 (c % 4) and up of byte c / 4), read by the
  // queries' first look at a cell: a quarter of the bytes (400 kB for the 1.6 M cells of 100k
  // triangles) stays in the L2 cache while the points stream past, where state_ did not.
  HugePageVector<std::uint8_t> packed_state_;
  // Per cell: where state 2, its surface cell number k; in an empty cell, its signed crossing
  // count (the winding number), as the two's complement bits of an int32.
  HugePageVector<std::uint32_t> surface_;

  HugePageVector<std::uint32_t> cell_start_;  // surface cell k: refs_[cell_start_[k] .. [k + 1])
  // The surface cells' lists: the triangles' numbers (into tris_), 4 bytes a reference. A copy of
  // each triangle's box beside its number (28 bytes) made the lists 18 MB for 100k triangles,
  // most of the build's time spent by the kernel zeroing their pages; the box is read from the
  // record instead (the triangles lie in cell order, so a cell's records lie close together).
  HugePageVector<std::uint32_t> refs_;
  bool for_saving_ = false;
  // Built for saving only: the sum of the records' triangle hashes (the file's fingerprint of the
  // mesh, index_file.h), added as the records are made, not in a second read of their 10 MB.
  std::uint64_t records_hash_sum_ = 0;
  // Winding regime.
  FastWindingNumber winding_;
  Stats stats_;
};

}  // namespace contain::inside
