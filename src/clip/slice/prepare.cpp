// Stage 1 of slicing: the mesh welded by position, its triangles' extents along the axis and
// the pairing of their half-edges, and the triangles each plane of the sweep brings in.

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "clip/slice/stages.h"
#include "contain/shapes/mesh_closure.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::clip::slice {

Frame frame_of(Axis axis) {
  const int k = static_cast<int>(axis);
  return {k, (k + 1) % 3, (k + 2) % 3};
}

namespace {

// The mesh welded and in the frame, its half-edges not paired yet. The weld, and the copies it
// makes, are skipped when the vertices are distinct already (an OFF or OBJ file indexes its
// vertices): at 524k triangles the copies and their page faults cost as much as the sweep.
SweepMesh framed(const Mesh& mesh, const Frame& frame) {
  SweepMesh out;
  out.frame = frame;
  std::span<const Vec3> vertices = mesh.vertices;
  out.triangles = mesh.triangles;
  if (!vertices_distinct(mesh.vertices)) {
    WeldResult weld = weld_vertices(mesh);
    out.own_vertices = std::move(weld.mesh.vertices);
    out.own_triangles = std::move(weld.mesh.triangles);
    vertices = out.own_vertices;
    out.triangles = out.own_triangles;
  }
  if (frame.k != 2) {  // (u, v, k) = (x, y, z) for the axis z: no copy then
    std::vector<Vec3> moved;
    moved.reserve(vertices.size());
    for (const Vec3& p : vertices)
      moved.push_back({coord(p, frame.u), coord(p, frame.v), coord(p, frame.k)});
    out.own_vertices = std::move(moved);
    vertices = out.own_vertices;
  }
  out.vertices = vertices;
  return out;
}

}  // namespace

SweepMesh prepare(const Mesh& mesh, const Frame& frame) {
  SweepMesh out = framed(mesh, frame);
  std::optional<std::vector<std::int32_t>> twin =
      paired_half_edges(out.triangles, out.vertices.size());
  out.twin = twin ? std::move(*twin) : std::vector<std::int32_t>(3 * out.triangles.size(), -1);
  return out;
}

// The closedness test pairs the half-edges on the way (the walk of walk.cpp follows them); only
// an open mesh, or one too large to pair, runs the search that names an edge.
Status prepare_closed(const Mesh& mesh, const Frame& frame, SweepMesh& out) {
  out = framed(mesh, frame);
  std::optional<std::vector<std::int32_t>> twin =
      paired_half_edges(out.triangles, out.vertices.size());
  if (!twin) {
    if (Status closed = require_closed(weld_vertices(mesh)); !closed) return closed;
    twin.emplace(3 * out.triangles.size(), -1);
  }
  out.twin = std::move(*twin);
  return Ok{};
}

namespace {

// The first i with sorted[i] >= x (sorted.size() if none), through buckets of equal width over
// [sorted.front(), sorted.back()]: first[b] is the first plane whose bucket is b or later. The
// bucket of a value is monotone in the value (a rounded subtraction and product, then a clamp),
// so the answer for x in bucket b lies in [first[b], first[b + 1]], searched without branches
// on the data (the triangles' extents come in no order a branch predictor could follow): a few
// steps where a binary search over all planes takes log2 of their number.
class PlaneBuckets {
 public:
  explicit PlaneBuckets(std::span<const double> sorted) : sorted_(sorted) {
    if (sorted.empty()) return;
    const std::size_t buckets = 2 * sorted.size();
    lo_ = sorted.front();
    const double width = sorted.back() - lo_;
    // A zero or overflowing extent puts every value in the first bucket (a search of all).
    scale_ = width > 0 && std::isfinite(width) ? static_cast<double>(buckets) / width : 0.0;
    last_ = buckets - 1;
    first_.assign(buckets + 1, sorted.size());
    for (std::size_t i = sorted.size(); i-- > 0;)
      first_[bucket(sorted[i])] = i;
    for (std::size_t b = buckets; b-- > 0;)
      first_[b] = std::min(first_[b], first_[b + 1]);
  }

  [[nodiscard]] std::size_t first_at_or_above(double x) const {
    if (sorted_.empty()) return 0;
    const std::size_t b = bucket(x);
    const double* base = sorted_.data() + first_[b];
    std::size_t n = first_[b + 1] - first_[b] + 1;  // the candidates, and "past them"
    while (n > 1) {
      const std::size_t half = n / 2;
      base = base[half - 1] < x ? base + half : base;
      n -= half;
    }
    return static_cast<std::size_t>(base - sorted_.data());
  }

 private:
  [[nodiscard]] std::size_t bucket(double x) const {
    if (!(x > lo_) || scale_ == 0.0) return 0;
    const double d = (x - lo_) * scale_;
    return d < static_cast<double>(last_) ? static_cast<std::size_t>(d) : last_;
  }

  std::span<const double> sorted_;
  double lo_ = 0.0;
  double scale_ = 0.0;
  std::size_t last_ = 0;
  std::vector<std::size_t> first_;
};

}  // namespace

SweepStarts sweep_starts(const SweepMesh& mesh, std::span<const double> sorted) {
  const std::size_t n = mesh.triangles.size();
  // Per triangle its first plane, or sorted.size() when it meets none. A triangle flat along
  // the axis never crosses a plane of the sweep: in its own plane it adds no segment to either
  // side's curve.
  std::vector<std::size_t> first(n);
  SweepStarts out;
  out.start.assign(sorted.size() + 2, 0);
  const PlaneBuckets buckets(sorted);
  for (std::size_t t = 0; t < n; ++t) {
    std::size_t i = sorted.size();
    const auto [low, high] = mesh.extent(t);
    if (low < high) {
      i = buckets.first_at_or_above(low);
      if (i < sorted.size() && sorted[i] > high) i = sorted.size();
    }
    first[t] = i;
    ++out.start[i + 1];
  }
  for (std::size_t i = 1; i < out.start.size(); ++i)
    out.start[i] += out.start[i - 1];
  out.triangles.resize(out.start[sorted.size()]);
  std::vector<std::size_t> next(out.start.begin(), out.start.end() - 2);
  for (std::size_t t = 0; t < n; ++t) {
    if (first[t] < sorted.size()) out.triangles[next[first[t]]++] = static_cast<std::int32_t>(t);
  }
  out.start.pop_back();
  return out;
}

}  // namespace contain::clip::slice
