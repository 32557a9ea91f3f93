#pragma once
// The last stages of the mesh boolean: the result's faces merged where coplanar
// (merge_faces.cpp), rounded to doubles and repaired by iterated snap rounding until the exact
// check passes (snap.cpp; rule solid-output in docs/robustness.md). Private to clip.

#include <array>
#include <cstdint>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"

namespace contain::clip::solid {

using Faces = std::vector<std::array<std::int32_t, 3>>;

/// The faces on the result's boundary, oriented with the result behind them, and the input
/// triangle each one is a piece of.
struct BoundaryFaces {
  Faces faces;
  std::vector<std::int32_t> triangle;
};

/// The refined faces where `op` differs on the two sides, one of each set of coinciding faces
/// (output.cpp).
[[nodiscard]] BoundaryFaces boundary_faces(const Soup& soup, const Refinement& refinement,
                                           const std::vector<TriangleWork>& work,
                                           const std::vector<FaceLabel>& labels,
                                           const PointStore& store, Op op);

/// The faces with every region of adjacent faces in one plane (same orientation, joined across
/// edges held by just those two faces) re-triangulated without the points inside it that no
/// other face uses. Adds the corners of enclosing triangles to `store`.
[[nodiscard]] Faces merge_coplanar(const Soup& soup, const BoundaryFaces& boundary,
                                   PointStore& store);

/// The faces written as doubles and checked exactly (check_written with the vertices written
/// exactly marked kept); where the check fails, iterated snap rounding: the written mesh's own
/// arrangement computed exactly again (its crossings and overlaps resolved as a union, only the
/// pairs of the triangles the check named intersected) and rounded, then with points merged on
/// coarser grids, for a bounded number of rounds. `scale` is the largest input coordinate's
/// magnitude. Errors: `ErrorKind::degenerate` when no round passes.
[[nodiscard]] Result<Mesh> snap_round(const Faces& faces, const PointStore& store, double scale);

}  // namespace contain::clip::solid
