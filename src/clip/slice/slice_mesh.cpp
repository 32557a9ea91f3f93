// Sections of a solid by many planes: the public entry, calling the stages of stages.h.

#include "contain/clip/slice_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <string>
#include <utility>

#include "clip/slice/stages.h"
#include "contain/shapes/mesh_closure.h"

namespace contain::clip {

namespace {

std::string point_text(Vec3 p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g %.17g %.17g)", p.x, p.y, p.z);
  return buffer;
}

}  // namespace

namespace slice {

// An open mesh has no winding number off its surface: refused, naming one unbalanced edge.
Status require_closed(const WeldResult& weld) {
  const std::optional<UnmatchedEdge> edge = unmatched_edge(weld);
  if (!edge) return Ok{};
  return Error{ErrorKind::degenerate, "the mesh is not closed: the edge " + point_text(edge->from) +
                                          " -> " + point_text(edge->to) + " of triangle " +
                                          std::to_string(edge->triangle) + " occurs " +
                                          std::to_string(edge->count) + " times and its reverse " +
                                          std::to_string(edge->reverse) + " times"};
}

}  // namespace slice

Result<std::vector<Section>> slice_mesh(const Mesh& mesh, std::span<const double> values,
                                        const SliceOptions& options, const BatchOptions& batch) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      return Error{ErrorKind::invalid_value,
                   "plane value " + std::to_string(i) + " is not a finite number"};
    }
  }
  slice::SweepMesh prepared;
  if (Status closed = slice::prepare_closed(mesh, slice::frame_of(options.axis), prepared); !closed)
    return closed.error();
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> sorted(values.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    sorted[i] = values[order[i]];
  const slice::SweepStarts starts = slice::sweep_starts(prepared, sorted);
  std::vector<Section> out(values.size());
  // One plane is a whole 2D boolean: chunks of a single plane are worth a thread.
  parallel_for(values.size(), batch, std::size_t{1}, [&](std::size_t begin, std::size_t end) {
    slice::sweep(prepared, starts, sorted, order, begin, end, out);
  });
  return out;
}

}  // namespace contain::clip
