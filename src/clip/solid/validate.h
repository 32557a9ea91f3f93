#pragma once
// The exact check of a written mesh (rule solid-output in docs/robustness.md). Private to clip.

#include <cstdint>
#include <vector>

#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/values/triangle.h"

namespace contain::clip::solid {

/// Ok when, on the mesh's doubles exactly: every directed edge occurs once and its reverse
/// once, no triangle has zero area, and no two triangles meet other than at corners at the same
/// positions or a shared edge. Otherwise `ErrorKind::degenerate` naming what failed. Every pair
/// of triangles whose boxes meet is tested (the full check).
[[nodiscard]] Status check_written(const Mesh& mesh);

/// The same check, with the pairs of triangles whose corners are all `kept` left out: kept[v]
/// says that vertex v is written exactly at its exact point, the only point of the exact
/// arrangement the engine wrote there, so that a triangle with three kept corners is a face of
/// that exact arrangement itself. The faces of the exact arrangement meet only at shared
/// corners or shared edges (validate.cpp says why), so such a pair can not fail; every other
/// pair holds a triangle with a corner that is not kept, and is tested exactly as by the full
/// check. Edges and areas are checked on every triangle. kept.size() == mesh.vertices.size().
/// With `crossing`, the check goes on after a failure of a pair or an area and appends every
/// triangle of a pair that meets wrongly (ascending; zero-area triangles are not in it): the
/// region a snap-rounding round repairs. An edge failure returns at once with every triangle
/// appended.
/// `edges`: `known_matched` skips the edge test for a mesh whose directed edges are known to
/// occur once each with their reverse (Sheets::paired).
/// With `one_shell`: set to whether the check found the mesh's triangles connected through
/// shared vertex numbers (one shell); false when it did not get that far.
enum class Edges : std::uint8_t { checked, known_matched };
[[nodiscard]] Status check_written(const Mesh& mesh, const std::vector<bool>& kept,
                                   std::vector<std::int32_t>* crossing = nullptr,
                                   Edges edges = Edges::checked, bool* one_shell = nullptr);

/// Whether triangles a and b (neither of zero area) meet beyond the corners they share (corners
/// at the same position) and the edge they share, exactly: the pair test of check_written. The
/// same triangle twice (either way round) meets.
[[nodiscard]] bool written_pair_meets(const Triangle3& a, const Triangle3& b);

/// Zero area, exactly: the three projections onto the coordinate planes have zero area.
[[nodiscard]] bool zero_area(Vec3 a, Vec3 b, Vec3 c);

}  // namespace contain::clip::solid
