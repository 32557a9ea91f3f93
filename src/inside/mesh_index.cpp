#include "contain/inside/mesh_index.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "contain/core/huge_pages.h"
#include "contain/core/radix_sort.h"
#include "contain/inside/point_in_triangle.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/perturbed_ray.h"
#include "contain/values/triangle.h"
#include "inside/index_bytes.h"
#include "inside/mesh_ray.h"
#include "inside/surface_star.h"

// Construction, stage by stage (derivation in mesh_index.h and predicates/perturbed_ray.h):
//  validate_mesh             the report, which picks the regime (not closed: winding number);
//  read_triangles            winding regime: vertices, ray-crossing signs and float boxes of
//                            the triangles;
//  grid_size                 exact regime: cells from the triangle count and the box's shape;
//  read_triangles_by_cell    the same records, in the order of their boxes' low cells (memory
//                            locality; a stable radix sort);
//  list_triangles_by_cell    each triangle's closed box marks the closed cells it meets (exact
//                            comparisons; big triangles tested against each cell's box along
//                            their normal) -> surface cells and their triangle lists;
//  settle_empty_cells        the winding number of each empty cell: each triangle's hits by
//                            the sample lines of the rows its box spans (one exact line test
//                            a row), then row by row from +x to -x the running sum of the hits
//                            beyond each empty cell.

namespace contain::inside {

namespace {

// A point strictly below `hi` in [lo, hi) when the span is not empty.
double inner_point(double lo, double hi) {
  const double m = 0.5 * lo + 0.5 * hi;
  return (m >= lo && m < hi) ? m : lo;
}

// The largest float <= v and the smallest float >= v (v finite): v rounded to nearest, then
// where that went past v one float back, by the bits (stepping away from or towards zero moves
// one float; infinity steps to the largest finite float; a zero steps to the smallest subnormal
// of v's side). Selects, not branches: whether the nearest float lies above or below v is a coin
// toss, six a triangle, and a mispredicted branch costs more than both steps.
float float_below(double v) {
  const auto f = static_cast<float>(v);
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const bool negative = (bits >> 31U) != 0;
  const std::uint32_t away = negative ? bits + 1 : bits - (bits != 0 ? 1U : 0U);
  const std::uint32_t down = (bits & 0x7FFFFFFFU) == 0 ? 0x80000001U : away;
  const std::uint32_t past = 0U - static_cast<std::uint32_t>(static_cast<double>(f) > v);
  return std::bit_cast<float>(bits ^ ((bits ^ down) & past));  // a mask: the compiler keeps no jump
}
float float_above(double v) {
  const auto f = static_cast<float>(v);
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const bool negative = (bits >> 31U) != 0;
  const std::uint32_t toward = negative ? bits - 1 : bits + 1;
  const std::uint32_t up = (bits & 0x7FFFFFFFU) == 0 ? 1U : toward;
  const std::uint32_t past = 0U - static_cast<std::uint32_t>(static_cast<double>(f) < v);
  return std::bit_cast<float>(bits ^ ((bits ^ up) & past));
}

// True only if a closed box and the triangle are certainly disjoint: their projections on the
// triangle's (floating-point) normal n, computed in floating point, are apart by more than a
// bound on the rounding errors of both. Any fixed n separates exactly when the exact
// projections are apart, so the answer needs no exact n. Overflow or NaN: never separated. The
// triangle's part is computed once (a big triangle is tested against many cells).
class PlaneSeparation {
 public:
  template <class Tri>
  explicit PlaneSeparation(const Tri& t) : n_(cross(t.b - t.a, t.c - t.a)) {
    const double ta = dot(n_, t.a), tb = dot(n_, t.b), tc = dot(n_, t.c);
    tmin_ = std::min({ta, tb, tc});
    tmax_ = std::max({ta, tb, tc});
    const double tv[3][3] = {{t.a.x, t.b.x, t.c.x}, {t.a.y, t.b.y, t.c.y}, {t.a.z, t.b.z, t.c.z}};
    for (int d = 0; d < 3; ++d)
      tabs_[d] = std::max({std::abs(tv[d][0]), std::abs(tv[d][1]), std::abs(tv[d][2])});
  }

  // One axis's part of the test for a box's span [lo, hi] along axis d: the least and greatest
  // of the two products with n's component, and the component's part of the error scale.
  struct AxisTerms {
    double least = 0.0, greatest = 0.0, scale = 0.0;
  };
  [[nodiscard]] AxisTerms axis_terms(int d, double lo, double hi) const {
    const double nv[3] = {n_.x, n_.y, n_.z};
    const double p = nv[d] * lo, q = nv[d] * hi;
    return {std::min(p, q), std::max(p, q),
            std::abs(nv[d]) * std::max({std::abs(lo), std::abs(hi), tabs_[d]})};
  }

  // Whether the plane separates the box whose spans along x, y and z have these terms (summed
  // x, y, z: the rounding the margin bounds; a caller computes each axis's terms once for all the
  // boxes that share the span).
  [[nodiscard]] bool separates(const AxisTerms& x, const AxisTerms& y, const AxisTerms& z) const {
    const double bmin = (x.least + y.least) + z.least;
    const double bmax = (x.greatest + y.greatest) + z.greatest;
    const double scale = (x.scale + y.scale) + z.scale;
    // Each side is a sum of three rounded products: error <= 3 u scale (+ underflow); 2^-40 is
    // a generous multiple of u = 2^-53.
    const double margin = 0x1p-40 * scale + 64 * std::numeric_limits<double>::denorm_min();
    return (bmin > tmax_ + margin) | (bmax < tmin_ - margin);
  }

 private:
  Vec3 n_;
  double tmin_ = 0.0, tmax_ = 0.0;
  double tabs_[3] = {0.0, 0.0, 0.0};
};

// The plane test's terms of cells [first, last] along axis d (their spans between the axis's
// lines), into `terms` (resized; its capacity kept from triangle to triangle).
void fill_axis_terms(const PlaneSeparation& plane, int d, const GridAxis& axis, int first, int last,
                     std::vector<PlaneSeparation::AxisTerms>& terms) {
  terms.resize(static_cast<std::size_t>(last - first + 1));
  for (int i = first; i <= last; ++i)
    terms[static_cast<std::size_t>(i - first)] =
        plane.axis_terms(d, axis.line(i), axis.line(i + 1));
}

// The listing's two passes over its (cell, triangle) pairs, each a function of its own (not
// inlined): in the listing, GCC kept the count of cells in a stack slot (a store-to-load chain
// each pair) and reloaded the loop's end from the stack after every store. `counts` is zeroed: each
// cell's pairs are counted there; the return is the number of cells with a pair.
template <class Pair>
[[gnu::noinline]] std::size_t count_listed_pairs_by_cell(std::span<const Pair> pairs,
                                                         std::uint32_t* counts) {
  std::size_t cells = 0;
  for (const Pair& p : pairs)
    cells += counts[p.cell]++ == 0 ? 1 : 0;
  return cells;
}

// Each pair's triangle to its cell's list: `surface` numbers the cells, `cursor` holds each
// numbered cell's next slot in `to` (left at its list's end).
template <class Pair>
[[gnu::noinline]] void place_listed_triangles(std::span<const Pair> pairs,
                                              const std::uint32_t* surface, std::uint32_t* cursor,
                                              std::uint32_t* to) {
  for (const Pair& p : pairs)
    to[cursor[surface[p.cell]]++] = p.triangle;
}

// One row of the empty cells' pass, right to left from column `last`: the running sum of the
// hits at each column (`at_column`, left zeroed) settles each empty cell's state and count. A
// function of its own (not inlined), as the listing's passes: inline, GCC reloaded the state
// and count arrays' pointers and the rule after every byte stored.
[[gnu::noinline]] void settle_empty_row(int last, int* at_column, std::uint8_t* state,
                                        std::uint32_t* counts, SolidRule rule) {
  int count = 0;
  for (int i = last - 1; i >= 0; --i) {
    const auto column = static_cast<std::size_t>(i);
    count += at_column[column + 1];
    at_column[column + 1] = 0;
    // Masks, not a branch on the state (surface cells among empty ones: unpredictable; GCC
    // keeps a jump for `?:` here): a surface cell's state and number are written back as read.
    const std::uint32_t surface = 0U - static_cast<std::uint32_t>(state[column] == 2);
    const std::uint32_t inside = inside_by_count(rule, count) ? 1U : 0U;
    state[column] = static_cast<std::uint8_t>((surface & 2U) | (~surface & inside));
    counts[column] = (counts[column] & surface) | (static_cast<std::uint32_t>(count) & ~surface);
  }
}

// Cells along x, y and z: about options.cells_per_triangle per triangle (within min_cells and
// max_cells), cubes as far as the box allows. Half units keep the extents finite for any finite
// coordinates.
std::array<int, 3> grid_size(const Box3& bounds, std::size_t triangles,
                             const MeshIndexOptions& options) {
  const std::array<double, 3> half{0.5 * bounds.max.x - 0.5 * bounds.min.x,
                                   0.5 * bounds.max.y - 0.5 * bounds.min.y,
                                   0.5 * bounds.max.z - 0.5 * bounds.min.z};
  double target = std::max(options.cells_per_triangle * static_cast<double>(triangles),
                           static_cast<double>(options.min_cells));
  target =
      std::clamp(target, 1.0, static_cast<double>(std::max<std::size_t>(options.max_cells, 1)));
  // cell edge = (volume / target)^(1/dims) in half units, in logarithms: the volume of a box of
  // huge or tiny extents over- or underflows.
  double log_volume = 0.0;
  int dims = 0;
  for (double h : half) {
    if (h > 0.0) {
      log_volume += std::log(h);
      ++dims;
    }
  }
  std::array<int, 3> n{1, 1, 1};
  if (dims == 0) return n;
  const double log_edge = (log_volume - std::log(target)) / dims;
  double product = 1.0;
  for (int d = 0; d < 3; ++d) {
    const auto du = static_cast<std::size_t>(d);
    if (half[du] > 0.0) {
      const double cells = std::exp(std::log(half[du]) - log_edge);
      n[du] = static_cast<int>(std::clamp(std::round(cells), 1.0, 4096.0));
    }
    product *= n[du];
  }
  // Rounding may overshoot the cap: shrink the largest dimension until it fits.
  while (product > static_cast<double>(std::max<std::size_t>(options.max_cells, 1))) {
    int* largest = &n[0];
    for (int& v : n)
      largest = v > *largest ? &v : largest;
    if (*largest == 1) break;
    product = product / *largest * (*largest - 1);
    *largest -= 1;
  }
  return n;
}

// The cost model: building the grid takes about kGridCost a triangle, a query without it about
// kDirectCost a triangle (one pass over all of them); with the grid a query costs next to
// nothing. So the grid pays from about kGridCost / kDirectCost queries on, whatever the size.
// Measured on a 100k-triangle torus and on armadillo, one thread (bench/results/debian12-2core/
// point_in_mesh.txt): about 1.3 us a triangle to build, 4-6 ns a triangle a direct query.
constexpr double kGridCost = 1300.0, kDirectCost = 5.0;

// The triangles' numbers in the order of their boxes' low cells, mesh order within a cell. The
// arrays default-initialize (HugePageVector): every element is written before it is read, none
// is zeroed first.
template <class Cell>
HugePageVector<std::uint32_t> triangles_by_low_cell(const Mesh& mesh, const GridAxis& x,
                                                    const GridAxis& y, const GridAxis& z) {
  const std::size_t n = mesh.triangles.size();
  HugePageVector<Cell> cells(n);
  HugePageVector<std::uint32_t> order(n);
  for (std::size_t t = 0; t < n; ++t) {
    const Vec3 lo = bounding_box(mesh.triangle(t)).min;
    const auto i = static_cast<std::size_t>(x.cells_meeting(lo.x, lo.x).first);
    const auto j = static_cast<std::size_t>(y.cells_meeting(lo.y, lo.y).first);
    const auto k = static_cast<std::size_t>(z.cells_meeting(lo.z, lo.z).first);
    cells[t] = static_cast<Cell>(
        (k * static_cast<std::size_t>(y.cells()) + j) * static_cast<std::size_t>(x.cells()) + i);
    order[t] = static_cast<std::uint32_t>(t);
  }
  stable_radix_sort(cells, order,
                    static_cast<unsigned>(std::bit_width(static_cast<std::size_t>(x.cells()) *
                                                         static_cast<std::size_t>(y.cells()) *
                                                         static_cast<std::size_t>(z.cells()))));
  return order;
}

bool few_queries(std::size_t queries) {
  return queries > 0 && static_cast<double>(queries) * kDirectCost < kGridCost;
}

}  // namespace

const char* to_string(MeshRegime regime) {
  return regime == MeshRegime::closed_exact ? "closed_exact" : "winding_number";
}

MeshIndex::MeshIndex(const Mesh& mesh, const MeshIndexOptions& options)
    : report_(validate_mesh(mesh)) {
  if (prepare(mesh, options)) mesh_ = mesh;
}

MeshIndex::MeshIndex(Mesh&& mesh, const MeshIndexOptions& options) : report_(validate_mesh(mesh)) {
  if (prepare(mesh, options)) mesh_ = std::move(mesh);
}

MeshIndex::MeshIndex(const Mesh& mesh, const MeshIndexOptions& options, ForSaving /*tag*/)
    : report_(validate_mesh(mesh)), for_saving_(true) {
  if (prepare(mesh, options)) mesh_ = mesh;
}

// Everything but keeping the mesh, which the caller does (copied or moved) where this returns
// true: the exact regime without a grid.
bool MeshIndex::prepare(const Mesh& mesh, const MeshIndexOptions& options) {
  // The solid's closedness (every directed edge matched, by position) gives a winding number;
  // two triangles on every edge without it, ray parity (solid_rule.h).
  const SolidRule rule = solid_rule(mesh, report_);
  if (rule == SolidRule::none) {
    read_triangles(mesh);
    regime_ = MeshRegime::winding_number;
    // Built for saving, the tree is not: the file keeps its accuracy only (the loader builds it).
    const Mesh none;
    winding_ = FastWindingNumber(for_saving_ ? none : mesh, {.accuracy = options.winding_accuracy});
    return false;
  }
  regime_ = MeshRegime::closed_exact;
  by_parity_ = rule == SolidRule::parity;
  if (few_queries(options.queries)) {  // no grid, no records: locate_direct reads the mesh
    if (report_.referenced_vertices == mesh.vertices.size()) {  // the same box, read in order
      for (const Vec3& v : mesh.vertices)
        bounds_.expand(v);
    } else {
      for (const TriangleIndices& t : mesh.triangles)
        for (const std::int32_t v : t)
          bounds_.expand(mesh.vertex(v));
    }
    stats_.triangles = mesh.triangles.size();
    return true;
  }
  // The triangles' boxes give the bounds and the grid, then the records in cell order, made
  // once in that order (no second array of them to permute). The boxes are not kept: each stage
  // takes them from the corners again (bounding_box, the same doubles), which costs less than
  // writing and reading arrays of them.
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    bounds_.expand(bounding_box(mesh.triangle(t)));
  const std::array<int, 3> n = grid_size(bounds_, mesh.triangles.size(), options);
  x_ = GridAxis(bounds_.min.x, bounds_.max.x, n[0]);
  y_ = GridAxis(bounds_.min.y, bounds_.max.y, n[1]);
  z_ = GridAxis(bounds_.min.z, bounds_.max.z, n[2]);
  nx_ = n[0];
  ny_ = n[1];
  nz_ = n[2];
  stats_.cells =
      static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) * static_cast<std::size_t>(nz_);
  stats_.nx = nx_;
  stats_.ny = ny_;
  stats_.nz = nz_;
  read_triangles_by_cell(mesh);
  list_triangles_by_cell();
  settle_empty_cells();
  pack_states();
  return false;
}

MeshIndex::Tri MeshIndex::make_tri(Vec3 a, Vec3 b, Vec3 c) {
  Tri tri{a, b, c, {}, {}, predicates::projected_sign(a, b, c)};
  tri.lo[0] = float_below(std::min({a.x, b.x, c.x}));
  tri.lo[1] = float_below(std::min({a.y, b.y, c.y}));
  tri.lo[2] = float_below(std::min({a.z, b.z, c.z}));
  tri.hi[0] = float_above(std::max({a.x, b.x, c.x}));
  tri.hi[1] = float_above(std::max({a.y, b.y, c.y}));
  tri.hi[2] = float_above(std::max({a.z, b.z, c.z}));
  return tri;
}

void MeshIndex::read_triangles(const Mesh& mesh) {
  tris_.reserve(mesh.triangles.size());
  for (const TriangleIndices& t : mesh.triangles) {
    const Tri tri = make_tri(mesh.vertex(t[0]), mesh.vertex(t[1]), mesh.vertex(t[2]));
    if (for_saving_) records_hash_sum_ += index_bytes::hash_triangle(tri.a, tri.b, tri.c);
    bounds_.expand(tri.a);
    bounds_.expand(tri.b);
    bounds_.expand(tri.c);
    tris_.push_back(tri);
  }
  stats_.triangles = tris_.size();
}

// Triangles in the order of the cell of their box's low corner (rows along x are contiguous), in
// mesh order within a cell: a query's run along a row then reads triangles that lie close
// together in memory.
void MeshIndex::read_triangles_by_cell(const Mesh& mesh) {
  // Cell numbers in 32 bits where the grid allows (as in the listing): half the keys' memory.
  const HugePageVector<std::uint32_t> order =
      stats_.cells <= std::numeric_limits<std::uint32_t>::max()
          ? triangles_by_low_cell<std::uint32_t>(mesh, x_, y_, z_)
          : triangles_by_low_cell<std::size_t>(mesh, x_, y_, z_);
  tris_.reserve(order.size());
  // In cell order the triangles' corners are gathered from all over the mesh: each triangle's
  // indices are fetched 16 triangles ahead, its corners 8 ahead (prefetches: answers unchanged).
  constexpr std::size_t kIndicesAhead = 16, kCornersAhead = 8;
  const std::size_t n = order.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i + kIndicesAhead < n) __builtin_prefetch(&mesh.triangles[order[i + kIndicesAhead]]);
    if (i + kCornersAhead < n) {
      const TriangleIndices& ahead = mesh.triangles[order[i + kCornersAhead]];
      __builtin_prefetch(&mesh.vertex(ahead[0]));
      __builtin_prefetch(&mesh.vertex(ahead[1]));
      __builtin_prefetch(&mesh.vertex(ahead[2]));
    }
    const TriangleIndices& corners = mesh.triangles[order[i]];
    const Vec3 a = mesh.vertex(corners[0]), b = mesh.vertex(corners[1]),
               c = mesh.vertex(corners[2]);
    tris_.push_back(make_tri(a, b, c));
    // The fingerprint's part while the corners are at hand (hash_triangle: the file's sum).
    if (for_saving_) records_hash_sum_ += index_bytes::hash_triangle(a, b, c);
  }
  stats_.triangles = n;
}

// Triangle boxes -> closed cells: one pass lists the (cell, triangle) pairs in triangle order, a
// counting sort by cell keeps that order within each cell.
void MeshIndex::list_triangles_by_cell() {
  // Cell numbers in 32 bits where the grid allows (any grid of the default options): pairs of
  // 8 bytes, not 16, half the memory to fault in and to read twice.
  if (stats_.cells <= std::numeric_limits<std::uint32_t>::max()) {
    list_triangles_by_cell_as<std::uint32_t>();
  } else {
    list_triangles_by_cell_as<std::size_t>();
  }
}

template <class Cell>
void MeshIndex::list_triangles_by_cell_as() {
  const std::size_t cell_count = stats_.cells;
  struct Pair {
    Cell cell;
    std::uint32_t triangle;
  };
  HugePageVector<Pair> pairs;  // trivial: resized without zeroing, every listed one written
  // About six cells a triangle where cells are about as big as triangles (the grid's aim); room
  // for eight to begin with. The pairs are written without a branch on the plane test (its
  // answer is not predictable: a mispredicted branch a cell cost more than the test), each
  // cell's pair stored and counted only where the plane does not separate.
  pairs.resize(8 * tris_.size());
  std::size_t listed = 0;
  // The plane test's terms of a triangle's columns, rows and layers (reused: no allocation a
  // triangle).
  std::vector<PlaneSeparation::AxisTerms> terms_x, terms_y, terms_z;
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    const Box3 b = bounding_box(Triangle3{tris_[t].a, tris_[t].b, tris_[t].c});
    const auto [i0, i1] = x_.cells_meeting(b.min.x, b.max.x);
    const auto [j0, j1] = y_.cells_meeting(b.min.y, b.max.y);
    const auto [k0, k1] = z_.cells_meeting(b.min.z, b.max.z);
    const auto span = static_cast<std::size_t>(i1 - i0 + 1) *
                      static_cast<std::size_t>(j1 - j0 + 1) * static_cast<std::size_t>(k1 - k0 + 1);
    if (listed + span > pairs.size()) pairs.resize(std::max(2 * pairs.size(), listed + span));
    // A triangle whose box spans several cells is tested against each cell's box along its
    // normal, conservatively (PlaneSeparation): fewer surface cells under big triangles. The
    // test's terms of each column, row and layer are computed once for all the cells they bound.
    const bool big = (i1 > i0) + (j1 > j0) + (k1 > k0) >= 2;
    if (big) {
      const PlaneSeparation plane(tris_[t]);
      fill_axis_terms(plane, 0, x_, i0, i1, terms_x);
      fill_axis_terms(plane, 1, y_, j0, j1, terms_y);
      fill_axis_terms(plane, 2, z_, k0, k1, terms_z);
      for (int k = k0; k <= k1; ++k) {
        const PlaneSeparation::AxisTerms& tz = terms_z[static_cast<std::size_t>(k - k0)];
        for (int j = j0; j <= j1; ++j) {
          const PlaneSeparation::AxisTerms& ty = terms_y[static_cast<std::size_t>(j - j0)];
          const std::size_t row = (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny_) +
                                   static_cast<std::size_t>(j)) *
                                  static_cast<std::size_t>(nx_);
          for (int i = i0; i <= i1; ++i) {
            pairs[listed] = {static_cast<Cell>(row + static_cast<std::size_t>(i)),
                             static_cast<std::uint32_t>(t)};
            const bool separated =
                plane.separates(terms_x[static_cast<std::size_t>(i - i0)], ty, tz);
            listed += separated ? 0 : 1;
          }
        }
      }
      continue;
    }
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const std::size_t c = (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny_) +
                                 static_cast<std::size_t>(j)) *
                                    static_cast<std::size_t>(nx_) +
                                static_cast<std::size_t>(i);
          pairs[listed++] = {static_cast<Cell>(c), static_cast<std::uint32_t>(t)};
        }
  }
  pairs.resize(listed);
  // surface_ holds each cell's count first, then its surface cell number: no temporary array
  // of the grid's size (1.6 M cells for 100k triangles) to zero and fault in.
  // state_ default-initializes: the scan below writes every cell's state.
  state_ = HugePageVector<std::uint8_t>(cell_count);
  surface_.assign(cell_count, 0);
  // Surface cells counted here: cell_start_ sized once, not grown by doubling.
  const std::size_t surface_cells =
      count_listed_pairs_by_cell(std::span<const Pair>(pairs), surface_.data());
  // cell_start_[k] is first surface cell k's list's start, the cursor of the fill below, which
  // leaves it at the list's end (the next list's start): then the array moves one place up.
  cell_start_.resize(surface_cells + 1);
  std::uint8_t* const state = state_.data();
  std::uint32_t* const surface = surface_.data();
  std::uint32_t* const start = cell_start_.data();
  std::uint32_t numbered = 0, listed_before = 0;
  auto settle_cell = [&](std::size_t c) {
    const std::uint32_t count = surface[c];
    state[c] = count == 0 ? 0 : 2;
    if (count == 0) return;
    surface[c] = numbered;
    start[numbered++] = listed_before;
    listed_before += count;
  };
  // Eight cells at a time where all eight are empty (most of the grid: the surface is thin), one
  // by one elsewhere.
  constexpr std::size_t kBlock = 8;
  std::size_t first = 0;
  for (; first + kBlock <= cell_count; first += kBlock) {
    std::uint64_t counts[kBlock / 2];
    std::memcpy(counts, surface + first, sizeof counts);
    if ((counts[0] | counts[1] | counts[2] | counts[3]) == 0) {
      std::memset(state + first, 0, kBlock);
      continue;
    }
    for (std::size_t c = first; c < first + kBlock; ++c)
      settle_cell(c);
  }
  for (std::size_t c = first; c < cell_count; ++c)
    settle_cell(c);
  start[surface_cells] = listed_before;
  // The lists: each pair's triangle number to its cell's next slot (2.5 MB for 100k triangles).
  refs_.resize(listed_before);
  place_listed_triangles(std::span<const Pair>(pairs), surface, start, refs_.data());
  // Each cursor now at its list's end, the next list's start: one place up, and 0 first.
  std::copy_backward(start, start + surface_cells, start + surface_cells + 1);
  start[0] = 0;
  stats_.surface_cells = surface_cells;
  stats_.cell_refs = listed_before;
}

// Empty cells. The winding number in an empty cell of a row is the signed count of the perturbed
// hits of the row's sample line (the perturbed ray's line through (y, z), the inner points of the
// row's y and z spans) beyond the cell's lower plane x = X_i. No hit lies in the closed box of an
// empty cell (its triangle would meet the cell: listed there), so a hit of a triangle whose box
// spans the closed cells [i0, i1] of the row counts in every empty cell left of i0 (X_i+1 < the
// box's x, exact comparisons), in none right of i1, and in an empty cell between (a big
// triangle's box over cells its plane misses) where hit_side says it lies beyond X_i. So one
// pass over the triangles finds each hit once (a perturbed line test for each row its box
// spans), as (row, column): the empty cells left of `column` count it; rows without a hit keep
// the zeros the listing left (count 0: outside by either rule).
void MeshIndex::settle_empty_cells() {
  std::vector<double> ys(static_cast<std::size_t>(ny_)), zs(static_cast<std::size_t>(nz_));
  for (int j = 0; j < ny_; ++j)
    ys[static_cast<std::size_t>(j)] = inner_point(y_.line(j), y_.line(j + 1));
  for (int k = 0; k < nz_; ++k)
    zs[static_cast<std::size_t>(k)] = inner_point(z_.line(k), z_.line(k + 1));
  struct Hit {
    std::uint32_t row;  // k * ny + j
    int column;         // the empty cells left of it count the hit
    int sign;
  };
  // Huge pages (26k hits, 310 kB, for the 100k torus): 4 kB pages cost more to fault in.
  HugePageVector<Hit> hits;
  hits.reserve(tris_.size() / 2);
  for (const Tri& tri : tris_) {
    if (tri.s == Sign::zero) continue;
    const Box3 b = bounding_box(Triangle3{tri.a, tri.b, tri.c});
    const auto [i0, i1] = x_.cells_meeting(b.min.x, b.max.x);
    const auto [j0, j1] = y_.cells_meeting(b.min.y, b.max.y);
    const auto [k0, k1] = z_.cells_meeting(b.min.z, b.max.z);
    for (int k = k0; k <= k1; ++k) {
      const double z = zs[static_cast<std::size_t>(k)];
      if (z < tri.lo[2] || z > tri.hi[2]) continue;
      for (int j = j0; j <= j1; ++j) {
        const double y = ys[static_cast<std::size_t>(j)];
        if (y < tri.lo[1] || y > tri.hi[1]) continue;
        const Vec3 q{x_.line(i0), y, z};
        if (!predicates::perturbed_line_hits_unboxed(tri.a, tri.b, tri.c, tri.s, q)) continue;
        const std::uint32_t row = static_cast<std::uint32_t>(k) * static_cast<std::uint32_t>(ny_) +
                                  static_cast<std::uint32_t>(j);
        const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(nx_);
        int column = i0;
        for (int i = i0; i <= i1; ++i) {
          if (state_[first + static_cast<std::size_t>(i)] != 2 &&
              predicates::hit_side(tri.a, tri.b, tri.c, tri.s, {x_.line(i), y, z}) > 0) {
            column = i + 1;
          }
        }
        hits.push_back({row, column, to_int(tri.s)});
      }
    }
  }
  // Row by row (a counting sort of the hits by row), right to left: the running sum of the hits
  // right of each empty cell.
  const std::size_t rows = static_cast<std::size_t>(ny_) * static_cast<std::size_t>(nz_);
  std::vector<std::uint32_t> start(rows + 1, 0);
  for (const Hit& h : hits)
    ++start[h.row + 1];
  for (std::size_t r = 0; r < rows; ++r)
    start[r + 1] += start[r];
  HugePageVector<Hit> by_row(hits.size());  // default-initialized: every element written
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const Hit& h : hits)
      by_row[next[h.row]++] = h;
  }
  std::vector<int> at_column(static_cast<std::size_t>(nx_) + 1, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    if (start[r] == start[r + 1]) continue;
    int last = 0;
    for (std::uint32_t h = start[r]; h < start[r + 1]; ++h) {
      at_column[static_cast<std::size_t>(by_row[h].column)] += by_row[h].sign;
      last = std::max(last, by_row[h].column);
    }
    const std::size_t first = r * static_cast<std::size_t>(nx_);
    settle_empty_row(last, at_column.data(), state_.data() + first, surface_.data() + first,
                     by_parity_ ? SolidRule::parity : SolidRule::winding);
    at_column[0] = 0;
  }
}

// The states four to a byte (packed_state_).
void MeshIndex::pack_states() {
  const std::size_t cells = state_.size();
  packed_state_ = HugePageVector<std::uint8_t>((cells + 3) / 4);
  const std::uint8_t* const state = state_.data();
  std::uint8_t* const packed = packed_state_.data();
  std::size_t c = 0;
  for (; c + 4 <= cells; c += 4) {
    packed[c / 4] = static_cast<std::uint8_t>(state[c] | state[c + 1] << 2U | state[c + 2] << 4U |
                                              state[c + 3] << 6U);
  }
  if (c < cells) {
    unsigned last = 0;
    for (std::size_t k = c; k < cells; ++k)
      last |= static_cast<unsigned>(state[k]) << (2 * (k - c));
    packed[c / 4] = static_cast<std::uint8_t>(last);
  }
}

bool MeshIndex::on_triangle(const Tri& t, Vec3 p) const {
  // Outside the outward-rounded box: certainly not on the triangle.
  if ((p.x < t.lo[0]) | (p.x > t.hi[0]) | (p.y < t.lo[1]) | (p.y > t.hi[1]) | (p.z < t.lo[2]) |
      (p.z > t.hi[2])) {
    return false;
  }
  if (predicates::orient3d(t.a, t.b, t.c, p) != Sign::zero) return false;
  return point_in_triangle(Triangle3{t.a, t.b, t.c}, p) != Location::outside;
}

namespace {

// The coordinates of v cyclically permuted so that axis `Axis` comes first: (x, y, z), (y, z, x)
// or (z, x, y). A cyclic permutation keeps orientations (every orient3d and orient2d sign), so the
// perturbed +x ray rule applied to permuted points is the same rule for a ray along +y or +z (its
// origin moved symbolically along the next two axes), and a crossing's sign, the sign of the
// normal's component along the ray, counts the winding number as along x.
template <int Axis>
Vec3 axis_first(Vec3 v) {
  if constexpr (Axis == 0) {
    return v;
  } else if constexpr (Axis == 1) {
    return {v.y, v.z, v.x};
  } else {
    return {v.z, v.x, v.y};
  }
}

double coordinate(Vec3 v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

}  // namespace

// Walks. A point p in a surface cell, not on the surface, has the winding number of every point
// near it, and the winding number is the signed count of the perturbed hits of any ray from p
// along an axis (the rule above, on permuted coordinates for y and z), or of the line's part
// behind p subtracted from the count of a point behind: W(p) = W(q) - (hits at or before p and
// beyond q) for q on the same line behind p. An empty cell's stored count is the winding number
// of every point of its closed box and of points infinitely near it (no surface meets the closed
// box; for a mesh read by parity, a count of the parity of every such point), so a walk from p's
// cell along an axis, either way, stops at the first empty cell and adds (ahead) or subtracts
// from (behind) its count the hits in the surface cells between; off the grid the count is 0.
// Each hit is counted in one slab [L_m, L_m+1) of the walk's axis (hit_side at the planes, the
// perturbation deciding hits exactly on one); a plane next to an empty cell needs no test (no
// hit lies in the empty cell's closed box, and a triangle listed here with a hit beyond it
// would meet it: the row's argument in mesh_index.h). locate_exact takes the walk through the
// fewest cells (the states are in cache): in the 100k torus (10^6 random points, 39,556 in
// surface cells) 1.9 cells a walk, where along +x alone it was 6.5 (23% of the runs 7 cells or
// more: where the surface lies flat along x).
template <int Axis>
int MeshIndex::count_walk(Vec3 p, std::size_t cell, int first, int step) const {
  const GridAxis& axis = Axis == 0 ? x_ : (Axis == 1 ? y_ : z_);
  const int n = axis.cells();
  const std::ptrdiff_t stride =
      Axis == 0 ? 1
                : (Axis == 1 ? static_cast<std::ptrdiff_t>(nx_)
                             : static_cast<std::ptrdiff_t>(nx_) * static_cast<std::ptrdiff_t>(ny_));
  constexpr int d1 = (Axis + 1) % 3, d2 = (Axis + 2) % 3;  // the other two axes
  const double u = coordinate(p, d1), v = coordinate(p, d2);
  const Vec3 q = axis_first<Axis>(p);
  int between = 0;  // the signed hits counted so far
  for (int m = first; m >= 0 && m < n; m += step) {
    const auto c = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) +
                                            static_cast<std::ptrdiff_t>(m - first) * stride);
    if (packed_state(c) < 2) {
      const auto count = static_cast<std::int32_t>(surface_[c]);
      return step > 0 ? between + count : count - between;
    }
    // Ahead (step +1): hits beyond p in p's cell, else at or beyond the lower plane; below the
    // upper plane unless the next cell is empty or there is none. Behind (step -1): hits at or
    // before p in p's cell, else below the upper plane; at or beyond the lower plane unless the
    // cell before is empty or there is none.
    const auto surface_at = [&](std::ptrdiff_t offset) {
      return packed_state(static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + offset)) == 2;
    };
    const bool test_lower = step > 0 ? m != first : m > 0 && surface_at(-stride);
    const bool test_upper = step > 0 ? m + 1 < n && surface_at(stride) : m != first;
    const Vec3 lower{axis.line(m), q.y, q.z};
    const Vec3 upper{axis.line(m + 1), q.y, q.z};
    const std::uint32_t k = surface_[c];
    for (std::uint32_t r = cell_start_[k]; r < cell_start_[k + 1]; ++r) {
      const Tri& t = tris_[refs_[r]];
      if ((u < t.lo[d1]) | (u > t.hi[d1]) | (v < t.lo[d2]) | (v > t.hi[d2])) continue;
      const Vec3 a = axis_first<Axis>(t.a), b = axis_first<Axis>(t.b), cc = axis_first<Axis>(t.c);
      const Sign s = Axis == 0 ? t.s : predicates::projected_sign(a, b, cc);
      if (s == Sign::zero || !predicates::perturbed_line_hits_unboxed(a, b, cc, s, q)) continue;
      if (m == first) {
        const int side = predicates::hit_side(a, b, cc, s, q);
        if (step > 0 ? side <= 0 : side > 0) continue;
      }
      if (test_lower && predicates::hit_side(a, b, cc, s, lower) < 0) continue;
      if (test_upper && predicates::hit_side(a, b, cc, s, upper) >= 0) continue;
      between += to_int(s);
    }
  }
  return step > 0 ? between : -between;  // off the grid: nothing beyond
}

// The signed crossing count of p (in surface cell `cell`, (i, j, k), not on the surface) by the
// walk through the fewest cells (a walk's length: its surface cells and the empty cell that ends
// it, read from the packed states); +x first, which wins ties. Every walk gives the same count
// (the rule above), so the choice is only a cost: the probes stop at the first walk of at most two
// cells (its next cell empty or off the grid: none but a one-cell walk is shorter, and the probes
// along y and z each read a cache line of their own), and p's own cell is not read again (it is
// a surface cell).
int MeshIndex::count_shortest_walk(Vec3 p, std::size_t cell, int i, int j, int k) const {
  const std::array<int, 3> at{i, j, k};
  const std::array<int, 3> size{nx_, ny_, nz_};
  const std::array<std::ptrdiff_t, 3> stride{
      1, static_cast<std::ptrdiff_t>(nx_),
      static_cast<std::ptrdiff_t>(nx_) * static_cast<std::ptrdiff_t>(ny_)};
  int best_axis = 0, best_step = 1, best = std::numeric_limits<int>::max();
  for (const int axis : {0, 2, 1}) {
    for (const int step : {1, -1}) {
      const auto a = static_cast<std::size_t>(axis);
      int length = 1;  // p's own cell
      auto c = static_cast<std::ptrdiff_t>(cell) + step * stride[a];
      for (int m = at[a] + step; m >= 0 && m < size[a] && length < best;
           m += step, c += step * stride[a]) {
        ++length;
        if (packed_state(static_cast<std::size_t>(c)) < 2) break;
      }
      if (length < best) {
        best = length;
        best_axis = axis;
        best_step = step;
      }
      if (best <= 2) break;
    }
    if (best <= 2) break;
  }
  const int first = at[static_cast<std::size_t>(best_axis)];
  if (best_axis == 0) return count_walk<0>(p, cell, first, best_step);
  if (best_axis == 1) return count_walk<1>(p, cell, first, best_step);
  return count_walk<2>(p, cell, first, best_step);
}

Location MeshIndex::locate(Vec3 p) const {
  if (regime_ == MeshRegime::winding_number) return locate_winding(p);
  return locate_exact(p);
}

std::optional<Location> MeshIndex::locate_settled(const Box3& box) const {
  if (regime_ == MeshRegime::winding_number) return std::nullopt;
  // Wholly beyond the closed bounds: locate_exact's first test answers `outside` for every point.
  if (box.min.x > bounds_.max.x || box.max.x < bounds_.min.x || box.min.y > bounds_.max.y ||
      box.max.y < bounds_.min.y || box.min.z > bounds_.max.z || box.max.z < bounds_.min.z) {
    return Location::outside;
  }
  if (state_.empty()) return std::nullopt;  // few queries: no grid
  // Strictly between two lines on each axis (so within the bounds): every point of the box lies
  // in that cell, however it was found (the floating-point guess; where it is wrong, the test
  // fails and the point is read in full), and an empty cell's state holds in its closed box.
  const int i = x_.guess(box.min.x);
  if (!(x_.line(i) < box.min.x && box.max.x < x_.line(i + 1))) return std::nullopt;
  const int j = y_.guess(box.min.y);
  if (!(y_.line(j) < box.min.y && box.max.y < y_.line(j + 1))) return std::nullopt;
  const int k = z_.guess(box.min.z);
  if (!(z_.line(k) < box.min.z && box.max.z < z_.line(k + 1))) return std::nullopt;
  const std::size_t cell =
      (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny_) + static_cast<std::size_t>(j)) *
          static_cast<std::size_t>(nx_) +
      static_cast<std::size_t>(i);
  const std::uint8_t state = packed_state(cell);
  if (state < 2) return state == 1 ? Location::inside : Location::outside;
  return std::nullopt;
}

Location MeshIndex::locate_exact(Vec3 p) const {
  if (!bounds_.contains(p)) return Location::outside;
  if (state_.empty()) return locate_direct(p);  // few queries: no grid
  const int i = x_.cell_of(p.x);
  const int j = y_.cell_of(p.y);
  const int k = z_.cell_of(p.z);
  const std::size_t row =
      (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny_) + static_cast<std::size_t>(j)) *
      static_cast<std::size_t>(nx_);
  const std::uint8_t state = packed_state(row + static_cast<std::size_t>(i));
  if (state < 2) return state == 1 ? Location::inside : Location::outside;
  const std::uint32_t cell = surface_[row + static_cast<std::size_t>(i)];
  for (std::uint32_t r = cell_start_[cell]; r < cell_start_[cell + 1]; ++r) {
    const Tri& t = tris_[refs_[r]];
    if (!outside_box(t, p) && on_triangle(t, p)) {
      return by_parity_ ? Location::boundary : locate_on_surface(p);
    }
  }
  // On the top faces of the box the perturbed ray leaves the grid's rows: it meets nothing, and
  // a point there that is not on the surface is outside (the solid's interior is open).
  if (p.y == bounds_.max.y || p.z == bounds_.max.z) return Location::outside;
  const int count = count_shortest_walk(p, row + static_cast<std::size_t>(i), i, j, k);
  return inside_by_count(count) ? Location::inside : Location::outside;
}

namespace {

// Where a vertex lies against the closed ray from p along +x, a bit for each side of it the
// vertex is strictly beyond: left of p, below or above it in y, in z. The closed box of a
// triangle misses the ray iff its three corners share a bit (exact comparisons): such a triangle
// neither holds p nor is crossed by the perturbed ray.
std::uint8_t side_of_ray(Vec3 v, Vec3 p) {
  return static_cast<std::uint8_t>(
      static_cast<unsigned>(v.x < p.x) | static_cast<unsigned>(v.y < p.y) << 1U |
      static_cast<unsigned>(v.y > p.y) << 2U | static_cast<unsigned>(v.z < p.z) << 3U |
      static_cast<unsigned>(v.z > p.z) << 4U);
}

// The sides of every vertex: a byte each, read in order; the triangles then test their boxes
// against the ray with three bytes, not nine coordinates scattered over the vertex array.
std::vector<std::uint8_t> sides_of_ray(std::span<const Vec3> vertices, Vec3 p) {
  std::vector<std::uint8_t> sides(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v)
    sides[v] = side_of_ray(vertices[v], p);
  return sides;
}

bool box_meets_ray(const std::vector<std::uint8_t>& sides, const TriangleIndices& t) {
  return (sides[static_cast<std::size_t>(t[0])] & sides[static_cast<std::size_t>(t[1])] &
          sides[static_cast<std::size_t>(t[2])]) == 0;
}

}  // namespace

// Without a grid (few queries): every triangle of the mesh, the tests of the grid's queries.
Location MeshIndex::locate_direct(Vec3 p) const {
  const std::vector<std::uint8_t> sides = sides_of_ray(mesh_.vertices, p);
  int count = 0;
  for (const TriangleIndices& t : mesh_.triangles) {
    if (!box_meets_ray(sides, t)) continue;
    const Vec3 a = mesh_.vertex(t[0]), b = mesh_.vertex(t[1]), c = mesh_.vertex(t[2]);
    if (predicates::orient3d(a, b, c, p) == Sign::zero &&
        point_in_triangle(Triangle3{a, b, c}, p) != Location::outside) {
      return by_parity_ ? Location::boundary : locate_direct_on_surface(p, sides);
    }
    const Sign s = predicates::projected_sign(a, b, c);
    if (s != Sign::zero && predicates::perturbed_line_hits_unboxed(a, b, c, s, p) &&
        predicates::hit_side(a, b, c, s, p) > 0) {
      count += to_int(s);
    }
  }
  return inside_by_count(count) ? Location::inside : Location::outside;
}

// p on the surface, without a grid: every triangle whose box meets the closed ray from p.
Location MeshIndex::locate_direct_on_surface(Vec3 p, const std::vector<std::uint8_t>& sides) const {
  std::vector<Triangle3> near;
  for (const TriangleIndices& t : mesh_.triangles) {
    if (box_meets_ray(sides, t))
      near.push_back({mesh_.vertex(t[0]), mesh_.vertex(t[1]), mesh_.vertex(t[2])});
  }
  return classify_near(p, near);
}

// A point on some triangle: the solid near it (inside/mesh_ray.h). Every triangle that the ray
// from a sample near p may meet meets the closed segment from p along +x to the grid's end, so
// it is listed in a closed cell of the rows whose closed (y, z) span holds p, from p's column on.
Location MeshIndex::locate_on_surface(Vec3 p) const {
  const auto [i0, i1] = x_.cells_meeting(p.x, p.x);
  const auto [j0, j1] = y_.cells_meeting(p.y, p.y);
  const auto [k0, k1] = z_.cells_meeting(p.z, p.z);
  (void)i1;
  std::vector<std::uint32_t> near;
  for (int k = k0; k <= k1; ++k) {
    for (int j = j0; j <= j1; ++j) {
      const std::size_t row = (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny_) +
                               static_cast<std::size_t>(j)) *
                              static_cast<std::size_t>(nx_);
      for (int i = i0; i < nx_; ++i) {
        const std::size_t c = row + static_cast<std::size_t>(i);
        if (packed_state(c) != 2) continue;
        const std::uint32_t cell = surface_[c];
        for (std::uint32_t r = cell_start_[cell]; r < cell_start_[cell + 1]; ++r) {
          const Tri& t = tris_[refs_[r]];
          if ((p.x > t.hi[0]) | (p.y < t.lo[1]) | (p.y > t.hi[1]) | (p.z < t.lo[2]) |
              (p.z > t.hi[2])) {
            continue;
          }
          near.push_back(refs_[r]);
        }
      }
    }
  }
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  return classify_on_surface(p, near);
}

// p on the surface, `near` every triangle that the ray from a sample near p may meet.
Location MeshIndex::classify_on_surface(Vec3 p, const std::vector<std::uint32_t>& near) const {
  std::vector<Triangle3> corners;
  corners.reserve(near.size());
  for (const std::uint32_t t : near)
    corners.push_back({tris_[t].a, tris_[t].b, tris_[t].c});
  return classify_near(p, corners);
}

Location MeshIndex::classify_near(Vec3 p, std::span<const Triangle3> near) const {
  detail::MeshRay ray(p);
  std::vector<Triangle3> star;  // the triangles through p
  for (const Triangle3& t : near) {
    ray.add(t.a, t.b, t.c);
    if (detail::face_through(t.a, t.b, t.c, p)) star.push_back(t);
  }
  return detail::classify_surface_point(star, p, ray,
                                        [&](int count) { return inside_by_count(count); });
}

Location MeshIndex::locate_winding(Vec3 p) const {
  if (tris_.empty()) return Location::outside;
  bool on = false;
  (void)winding_.hierarchy().traverse(
      [&](const bvh::Node& node, std::int32_t) { return node.box.contains(p); },
      [&](std::int32_t t) {
        on = on_triangle(tris_[static_cast<std::size_t>(t)], p);
        return on ? bvh::Visit::stop : bvh::Visit::proceed;
      });
  if (on) return Location::boundary;
  return winding_.evaluate(p) >= 0.5 ? Location::inside : Location::outside;
}

void MeshIndex::locate(std::span<const Vec3> points, std::span<Location> out,
                       const BatchOptions& options) const {
  const std::size_t count = batch_size(points.size(), out.size());
  if (regime_ == MeshRegime::winding_number || state_.empty()) {
    parallel_for(count, options, [&](std::size_t begin, std::size_t end) {
      for (std::size_t q = begin; q < end; ++q)
        out[q] = locate(points[q]);
    });
    return;
  }
  // Random points read random cells: a software pipeline prefetches, a few points ahead, the
  // cell's state byte, then (for a surface cell) its number and its triangle list. Prefetches
  // only warm the cache (the guessed cell need not be the exact one): answers do not change.
  constexpr std::size_t kAhead = 16, kNumberAhead = 11, kStartAhead = 7, kListAhead = 3;
  parallel_for(count, options, [&](std::size_t begin, std::size_t end) {
    std::array<std::ptrdiff_t, kAhead> guessed{};
    // The surface cell of the guessed cell of point q, or -1.
    auto surface_cell = [&](std::size_t q) -> std::ptrdiff_t {
      const std::ptrdiff_t c = guessed[q % kAhead];
      if (c < 0 || packed_state(static_cast<std::size_t>(c)) != 2) return -1;
      return c;
    };
    for (std::size_t q = begin; q < std::min(end, begin + kAhead); ++q)
      guessed[q % kAhead] = guessed_cell(points[q]);
    for (std::size_t q = begin; q < end; ++q) {
      if (q + kNumberAhead < end) {
        const std::ptrdiff_t c = surface_cell(q + kNumberAhead);
        if (c >= 0) __builtin_prefetch(&surface_[static_cast<std::size_t>(c)]);
      }
      if (q + kStartAhead < end) {
        const std::ptrdiff_t c = surface_cell(q + kStartAhead);
        if (c >= 0) __builtin_prefetch(&cell_start_[surface_[static_cast<std::size_t>(c)]]);
      }
      if (q + kListAhead < end) {
        const std::ptrdiff_t c = surface_cell(q + kListAhead);
        if (c >= 0) {
          const char* first = reinterpret_cast<const char*>(
              &refs_[cell_start_[surface_[static_cast<std::size_t>(c)]]]);
          __builtin_prefetch(first);  // 16 references a line: most cells' whole list
        }
      }
      if (q + 1 < end) {
        // The triangles of the next point's cell: their records (each one's box is read there).
        const std::ptrdiff_t c = surface_cell(q + 1);
        if (c >= 0) {
          const std::uint32_t cell = surface_[static_cast<std::size_t>(c)];
          for (std::uint32_t r = cell_start_[cell]; r < cell_start_[cell + 1]; ++r) {
            const char* record = reinterpret_cast<const char*>(&tris_[refs_[r]]);
            __builtin_prefetch(record);
            __builtin_prefetch(record + 64);
          }
        }
      }
      out[q] = locate_exact(points[q]);
      if (q + kAhead < end) {
        const std::ptrdiff_t c = guessed_cell(points[q + kAhead]);
        guessed[q % kAhead] = c;
        if (c >= 0) {
          __builtin_prefetch(&packed_state_[static_cast<std::size_t>(c) / 4]);
        }
      }
    }
  });
}

}  // namespace contain::inside
