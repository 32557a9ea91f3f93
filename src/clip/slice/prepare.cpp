// Stage 1 of slicing: the mesh welded by position, its triangles' extents along the axis and
// the pairing of their half-edges, and the triangles each plane of the sweep brings in.

#include <algorithm>
#include <utility>

#include "clip/slice/stages.h"
#include "contain/shapes/mesh_closure.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::clip::slice {

Frame frame_of(Axis axis) {
  const int k = static_cast<int>(axis);
  return {k, (k + 1) % 3, (k + 2) % 3};
}

SweepMesh prepare(const Mesh& mesh, const Frame& frame) {
  Mesh welded = weld_vertices(mesh).mesh;
  std::optional<std::vector<std::int32_t>> twin = paired_half_edges(welded);
  if (!twin) twin.emplace(3 * welded.triangles.size(), -1);
  return prepare_welded(std::move(welded), frame, std::move(*twin));
}

SweepMesh prepare_welded(Mesh welded, const Frame& frame, std::vector<std::int32_t> twin) {
  SweepMesh out;
  out.frame = frame;
  out.vertices.reserve(welded.vertices.size());
  for (const Vec3& p : welded.vertices)
    out.vertices.push_back({coord(p, frame.u), coord(p, frame.v), coord(p, frame.k)});
  out.triangles = std::move(welded.triangles);
  out.twin = std::move(twin);
  const std::size_t n = out.triangles.size();
  out.low.resize(n);
  out.high.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const TriangleIndices& tri = out.triangles[t];
    const double a = out.vertices[static_cast<std::size_t>(tri[0])].z;
    const double b = out.vertices[static_cast<std::size_t>(tri[1])].z;
    const double c = out.vertices[static_cast<std::size_t>(tri[2])].z;
    out.low[t] = std::min({a, b, c});
    out.high[t] = std::max({a, b, c});
  }
  return out;
}

namespace {

// The first i with sorted[i] >= x (sorted.size() if none), without branches on the data: the
// triangles' extents come in no order a branch predictor could follow.
std::size_t first_at_or_above(std::span<const double> sorted, double x) {
  if (sorted.empty()) return 0;
  const double* base = sorted.data();
  std::size_t n = sorted.size();
  while (n > 1) {
    const std::size_t half = n / 2;
    base = base[half] < x ? base + half : base;
    n -= half;
  }
  return static_cast<std::size_t>(base - sorted.data()) + (*base < x ? 1 : 0);
}

}  // namespace

SweepStarts sweep_starts(const SweepMesh& mesh, std::span<const double> sorted) {
  const std::size_t n = mesh.triangles.size();
  // Per triangle its first plane, or sorted.size() when it meets none. A triangle flat along
  // the axis never crosses a plane of the sweep: in its own plane it adds no segment to either
  // side's curve.
  std::vector<std::size_t> first(n);
  SweepStarts out;
  out.start.assign(sorted.size() + 2, 0);
  for (std::size_t t = 0; t < n; ++t) {
    std::size_t i = sorted.size();
    if (mesh.low[t] < mesh.high[t]) {
      i = first_at_or_above(sorted, mesh.low[t]);
      if (i < sorted.size() && sorted[i] > mesh.high[t]) i = sorted.size();
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
