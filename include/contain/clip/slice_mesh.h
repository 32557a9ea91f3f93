#pragma once
/// \file
/// Sections of a solid by many parallel planes, and its shadow: exact 2D regions for layers of
/// 3D printing, section views and footprints (issue 26; `contain slice` in ../shared/spec/cli.md).

#include <cstdint>
#include <span>
#include <vector>

#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"

namespace contain::clip {

/// The axis the planes are perpendicular to. The section's 2D coordinates are the next two
/// axes in cyclic order, so that (u, v, axis) is right-handed: (x, y) for z, (y, z) for x,
/// (z, x) for y; counter-clockwise in (u, v) is counter-clockwise seen from +axis.
enum class Axis : std::uint8_t { x, y, z };

struct SliceOptions {
  Axis axis = Axis::z;
};

/// The section of a solid by one plane, with provenance.
struct Section {
  double value = 0.0;  ///< the plane: coordinate `axis` == value
  MultiPolygon region;
  /// For each ring of `region` (polygons in order, each shell then its holes: the order of
  /// `region.all_rings()`), for each edge k (vertex k to vertex k + 1, the last one closing the
  /// ring), the index of a mesh triangle (in `mesh.triangles`) that the edge lies on.
  std::vector<std::vector<std::int32_t>> triangles;
};

/// The sections of the solid bounded by `mesh` by the planes `coordinate axis == values[i]`,
/// one `Section` per value, in the order given.
///
/// The solid is the set of points where the mesh's winding number is positive (the solids of
/// ../shared/spec/cli.md): parts that overlap count once, a shell turned inside out subtracts.
/// The section is exactly the closure of the set of points of the plane that are interior
/// points of the solid: a face lying in the plane that the solid touches from one side only adds
/// nothing; the shared face of two stacked boxes gives their square. Decided without nudging
/// the plane (rule slice-two-sides in docs/robustness.md): the curves of the planes just above
/// and just below (symbolic perturbation: a vertex on the plane counts below, then above) are
/// chained from the triangles' crossing segments through shared mesh edges and vertices (no
/// tolerance), and the section is the intersection of the two under `Fill::positive`
/// (`polygon_boolean`); a plane through no vertex has one curve and one pass of the engine.
///
/// Output: OGC-valid polygons as `polygon_boolean` writes them. A vertex where a mesh edge
/// crosses the plane is the double nearest to the exact crossing point
/// (`predicates::rounded_axis_crossing`) or the mesh vertex on the plane; a vertex where two
/// section edges meet (faces in the plane, overlapping parts) is rounded as the 2D booleans
/// round (within a few ulps). Every output edge lies on the crossing segment of its triangle,
/// up to that rounding.
///
/// Errors: an open mesh (a directed edge, by position, occurring more often than its reverse:
/// `shapes::unmatched_edge`) is `ErrorKind::degenerate` naming the edge and its first triangle;
/// a value that is NaN or infinite is `ErrorKind::invalid_value` naming its index.
///
/// Complexity: O(n log P) to file the n triangles under the first of the P planes they reach
/// (after the weld and the closedness test, O(n) and a sort of each vertex's few edges), then a
/// sweep over the planes in sorted order (each thread sweeps its own run of planes): per plane
/// O(k) for its k crossing triangles when it passes through no vertex of a manifold stretch
/// (walked along the surface), else O(k log k), plus the 2D boolean of the curves where the
/// rings are not proven simple and apart. Answers are the same whatever `batch.threads`.
[[nodiscard]] Result<std::vector<Section>> slice_mesh(const Mesh& mesh,
                                                      std::span<const double> values,
                                                      const SliceOptions& options = {},
                                                      const BatchOptions& batch = {});

/// The shadow of the mesh on a plane perpendicular to `options.axis`: the union of the
/// projections of its triangles, in the section's 2D coordinates. For a closed mesh (a solid)
/// this is the union of the triangles facing +axis (those projected counter-clockwise, exact
/// `orient2d`); an open mesh (a surface, a sheet, a box without its lid) has no solid but the
/// same union is well defined: every triangle counts, turned counter-clockwise. Triangles seen
/// edge-on have no area and add nothing (a vertical wall alone has an empty shadow). Edges that
/// two counted triangles share in opposite directions cancel before the one call of the 2D
/// engine under `Fill::positive`, so the work is that of the silhouette (and folds), not of n
/// triangles. No error for finite coordinates (the precondition of every exact predicate).
/// O(n log n) plus the 2D boolean of the remaining edges.
[[nodiscard]] Result<MultiPolygon> shadow(const Mesh& mesh, const SliceOptions& options = {});

}  // namespace contain::clip
