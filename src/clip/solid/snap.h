#pragma once
// The last stages of the mesh boolean: the result's faces merged where coplanar
// (merge_faces.cpp), rounded to doubles and repaired by iterated snap rounding until the exact
// check passes (snap.cpp; rule solid-output in docs/robustness.md). Private to clip.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"

namespace contain::clip::solid {

using Faces = ScratchVector<std::array<std::int32_t, 3>>;

/// The faces on the result's boundary, oriented with the result behind them, and the input
/// triangle each one is a piece of.
struct BoundaryFaces {
  Faces faces;
  ScratchVector<std::int32_t> triangle;
};

/// The refined faces where `op` differs on the two sides, one of each set of coinciding faces
/// (output.cpp).
[[nodiscard]] BoundaryFaces boundary_faces(const Soup& soup, const Refinement& refinement,
                                           const PairWork& work, const FaceLabels& labels,
                                           const PointStore& store, Op op);

/// The result of `op` with the faces `boundary` (boundary_faces): merged where coplanar,
/// written, checked and repaired (output.cpp).
[[nodiscard]] Result<MeshBooleanResult> write_result(const Soup& soup,
                                                     const BoundaryFaces& boundary,
                                                     PointStore& store, Op op);

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
/// magnitude; `rounds`, when given, receives the number of repair rounds run (0: the faces
/// written at their nearest doubles passed); `one_shell`, when given, whether the check that
/// passed found the mesh one shell (false: several, or not known). Errors:
/// `ErrorKind::degenerate` when no round passes.
[[nodiscard]] Result<Mesh> snap_round(const Faces& faces, const PointStore& store, double scale,
                                      std::size_t* rounds = nullptr, bool* one_shell = nullptr);

/// The leader (smallest index) of each point's cluster: points within `h` of each other in every
/// coordinate joined transitively (the hot cells of a snap round). nullopt when a cluster would
/// move a point by more than 2h in a coordinate (a chain of close points: that grid is not used).
[[nodiscard]] std::optional<std::vector<std::size_t>> cluster_points(std::span<const Vec3> points,
                                                                     double h);

/// The soup with its vertices merged by cluster_points on the grid of side ulp(scale) 2^level
/// (each leader keeps its position): every input moved by at most 2^(level + 1) ulps of scale in
/// each coordinate, and still closed (merging corners keeps each directed edge as often as its
/// reverse); triangles that lose their area are degenerate. nullopt when the grid is not used
/// (above level 16 also when it is not stable: its clusters differ from those of level + 3) or
/// merges nothing.
[[nodiscard]] std::optional<Soup> snapped_soup(const Soup& soup, int level, double scale);

/// The result of `op` on the inputs snapped on growing grids (snapped_soup, levels 2 to 28),
/// each arranged exactly and written by snap_round, the first that passes: what the engine does
/// when snap rounding of the exact result ended in `failure` (surfaces ulps apart, whose
/// crossings fold again at every rounding). Grids above 2^16 ulps are used only when stable (the
/// clusters of a grid 8 times coarser are the same) and their results only when every vertex is
/// proven within 0.999e-9 scale of `exact_faces`, the exact result's boundary (points of
/// `exact_store`). `failure`, completed, when none passes.
[[nodiscard]] Result<Mesh> snap_inputs(const Soup& soup, Op op, double scale,
                                       const Faces& exact_faces, const PointStore& exact_store,
                                       Error failure);

}  // namespace contain::clip::solid
