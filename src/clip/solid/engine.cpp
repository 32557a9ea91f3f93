// The mesh boolean engine, stage by stage: soup, pair intersections, refinement, labels, output
// (engine.h names the file of each stage).

#include <span>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/snap.h"

namespace contain::clip {

Result<MeshBooleanResult> mesh_boolean(std::span<const Mesh> inputs,
                                       const MeshBooleanOptions& options) {
  Result<solid::Soup> soup = solid::make_soup(inputs);
  if (!soup) return soup.error();
  solid::PointStore store;
  // The input vertices and room for the crossings (a few per hundred vertices on smooth
  // large inputs, relatively more on small ones: the crossings follow curves, about the
  // square root of the triangles; 1,020 at a pair of 2,048-triangle spheres, whose store grew
  // once without the 1,024; more grow the store): an index of 8 bytes a slot that stays in cache.
  store.reserve(soup->vertices.size() + soup->vertices.size() / 4 + 1024);
  store.add_vertices(*soup);
  solid::BoundaryFaces boundary;
  {
    // The pairs' work, the refinement and the labels are done with once the result's faces are
    // chosen: freed before the write phase, whose sheets and exact check then reuse their
    // memory (the process keeps freed memory) instead of faulting in fresh pages.
    const std::vector<solid::TriangleWork> work = solid::intersect_pairs(*soup, store);
    const solid::Refinement refinement = solid::refine(*soup, work, store);
    const solid::FaceLabels labels = solid::label_faces(*soup, refinement, store);
    boundary = solid::boundary_faces(*soup, refinement, work, labels, store, options.op);
  }
  return solid::write_result(*soup, boundary, store, options.op);
}

}  // namespace contain::clip
