// The mesh boolean engine, stage by stage: soup, pair intersections, refinement, labels, output
// (engine.h names the file of each stage).

#include <span>
#include <vector>

#include "clip/solid/engine.h"

namespace contain::clip {

Result<MeshBooleanResult> mesh_boolean(std::span<const Mesh> inputs,
                                       const MeshBooleanOptions& options) {
  Result<solid::Soup> soup = solid::make_soup(inputs);
  if (!soup) return soup.error();
  solid::PointStore store;
  // The input vertices and room for the crossings (a few per hundred vertices on smooth
  // inputs; more grow the store): an index of 8 bytes a slot that stays in cache.
  store.reserve(soup->vertices.size() + soup->vertices.size() / 4);
  store.add_vertices(*soup);
  const std::vector<solid::TriangleWork> work = solid::intersect_pairs(*soup, store);
  const solid::Refinement refinement = solid::refine(*soup, work, store);
  const solid::FaceLabels labels = solid::label_faces(*soup, refinement, store);
  return solid::write_result(*soup, refinement, work, labels, store, options.op);
}

}  // namespace contain::clip
