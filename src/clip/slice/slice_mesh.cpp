// Sections of a solid by many planes: the public entry, calling the stages of stages.h.

#include "contain/clip/slice_mesh.h"

#include <cstdio>
#include <optional>
#include <string>

#include "clip/slice/stages.h"
#include "contain/clip/mesh_slicer.h"
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
  auto slicer = MeshSlicer::make(mesh, values, options);
  if (!slicer) return slicer.error();
  return slicer->slice(0, values.size(), batch);
}

}  // namespace contain::clip
