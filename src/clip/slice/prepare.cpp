// Stage 1 of slicing: the mesh welded by position, its triangles' extents along the axis, and
// the order of the sweep.

#include <algorithm>
#include <numeric>

#include "clip/slice/stages.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::clip::slice {

Frame frame_of(Axis axis) {
  const int k = static_cast<int>(axis);
  return {k, (k + 1) % 3, (k + 2) % 3};
}

SweepMesh prepare(const Mesh& mesh, const Frame& frame) {
  return prepare_welded(weld_vertices(mesh).mesh, frame);
}

SweepMesh prepare_welded(Mesh welded, const Frame& frame) {
  SweepMesh out;
  out.frame = frame;
  out.vertices.reserve(welded.vertices.size());
  for (const Vec3& p : welded.vertices)
    out.vertices.push_back({coord(p, frame.u), coord(p, frame.v), coord(p, frame.k)});
  out.triangles = std::move(welded.triangles);
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
    // A triangle flat along the axis never crosses a plane of the sweep: in its own plane it
    // adds no segment to either side's curve.
    if (out.low[t] < out.high[t]) out.by_low.push_back(static_cast<std::int32_t>(t));
  }
  std::stable_sort(out.by_low.begin(), out.by_low.end(), [&](std::int32_t a, std::int32_t b) {
    return out.low[static_cast<std::size_t>(a)] < out.low[static_cast<std::size_t>(b)];
  });
  return out;
}

}  // namespace contain::clip::slice
