// The mesh boolean engine, stage by stage: soup, pair intersections, refinement, labels, output
// (engine.h names the file of each stage).

#include <span>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/scratch.h"
#include "clip/solid/snap.h"

namespace contain::clip {

Result<MeshBooleanResult> mesh_boolean(std::span<const Mesh> inputs,
                                       const MeshBooleanOptions& options) {
  // The call's scratch memory (scratch.h): declared first, so that every stage's arrays are
  // given back to it before it frees what it holds, whatever the process's malloc settings;
  // or none, the heap, where the caller asks for it (MeshBooleanOptions::scratch_pool).
  solid::ScratchPool pool;
  const solid::ScratchScope scope(options.scratch_pool ? &pool : nullptr);
  Result<solid::Soup> soup = solid::make_soup(inputs);
  if (!soup) return soup.error();
  solid::PointStore store;
  // The input vertices and room for the crossings (store_room; more grow the store): the
  // soup's index, made with that room, becomes the store's table as it is.
  store.reserve(solid::store_room(soup->vertices.size()));
  store.add_vertices(*soup, std::move(soup->index));
  solid::BoundaryFaces boundary;
  {
    // The pairs' work, the refinement and the labels are done with once the result's faces are
    // chosen: freed before the write phase, whose sheets and exact check then reuse their
    // blocks (the call's pool) instead of faulting in fresh pages.
    const solid::PairWork work = solid::intersect_pairs(*soup, store);
    const solid::Refinement refinement = solid::refine(*soup, work, store);
    const solid::FaceLabels labels = solid::label_faces(*soup, refinement, store);
    boundary = solid::boundary_faces(*soup, refinement, work, labels, store, options.op);
  }
  return solid::write_result(*soup, boundary, store, options.op);
}

}  // namespace contain::clip
