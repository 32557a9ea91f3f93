#pragma once
/// \file
/// Exact continuous collision of moving primitives: a vertex against a triangle and an edge
/// against an edge, every point moving on a straight line from t = 0 to t = 1. The answer is
/// "no contact in [0, 1]" or the earliest time of contact rounded down to a double, exact on
/// every input double (no false contact, no missed contact, no wrong rounding).

#include <array>
#include <cstdint>
#include <limits>
#include <span>

#include "contain/core/parallel.h"
#include "contain/values/vec.h"

namespace contain::collide {

/// Eight points in the order of the CCD benchmark of Wang et al. (2021): four points at t = 0,
/// then the same four at t = 1. Vertex-face: the vertex, then the triangle's three corners.
/// Edge-edge: the two ends of edge a, then the two ends of edge b. Point i moves on the straight
/// line p_i(t) = (1 - t) q[i] + t q[i + 4], t in [0, 1] (real arithmetic; nothing is rounded).
/// Coordinates must be finite (the CLI and the Python module check it).
using CcdQuery = std::array<Vec3, 8>;

/// Which stage decided a query (for benchmarks and `--json`).
enum class CcdStage : std::uint8_t {
  boxes,        ///< the boxes swept by the two primitives are disjoint
  coplanarity,  ///< the four points are never coplanar (certified in floating point)
  filter,       ///< roots and inclusions certified in floating point, rounding in double-double
  exact,        ///< the exact big-number stage (`predicates/polynomial.h`), for the whole query or
                ///< for signs the filters left open at a certified root
};

/// "boxes", "coplanarity", "filter", "exact".
[[nodiscard]] constexpr const char* to_string(CcdStage stage) {
  switch (stage) {
    case CcdStage::boxes:
      return "boxes";
    case CcdStage::coplanarity:
      return "coplanarity";
    case CcdStage::filter:
      return "filter";
    case CcdStage::exact:
      break;
  }
  return "exact";
}

/// The answer of a continuous collision query.
struct Impact {
  /// The two primitives share a point at some time in [0, 1] (closed sets: touching counts).
  bool hit = false;
  /// hit: the largest double <= the earliest time of contact t* (so t <= t* < next double after
  /// t, and advancing to t never passes through the contact); 0 when they touch at t = 0.
  /// Miss: +infinity.
  double time = std::numeric_limits<double>::infinity();
  CcdStage stage = CcdStage::boxes;
};

/// Vertex against triangle: the earliest t in [0, 1] at which the vertex lies in the closed
/// triangle (a degenerate triangle is the segment or point it spans), exactly.
///
/// Rules (docs/robustness.md, "Continuous collision"): contact times are the roots of the
/// coplanarity cubic orient3d(a(t), b(t), c(t), v(t)) at which the vertex lies in the triangle
/// (three cross_dot signs, or on an edge); where the cubic is identically zero (the four points
/// coplanar all the time, zero motion, degenerate triangles) the first time of the closed
/// contact set is 0 or a root of one of the inclusion polynomials. Contact at t = 0 gives 0.
/// Stages: swept boxes, Bernstein signs of the cubic, root isolation and inclusion with
/// certified error bounds (double, then double-double for the rounding), exact big numbers.
/// Cost: most queries end in the box or filter stages; exactly degenerate ones reach the big
/// numbers (figures: docs/benchmarks.md). Thread safety: pure function.
/// References: Provot 1997 (the coplanarity cubic); Brochu, Edwards, Bridson 2012 and Tang et al.
/// 2014 (exact CCD); Wang et al. 2021 (the benchmark's semantics).
[[nodiscard]] Impact vertex_face_ccd(const CcdQuery& query);

/// Edge against edge: the earliest t in [0, 1] at which the two closed segments share a point
/// (a degenerate segment is its point), exactly. Rules and stages as `vertex_face_ccd`: the cubic
/// is orient3d(a0, a1, b0, b1); at its roots the segments meet when they cross (two cross_dot
/// signs) or an end lies on the other segment.
[[nodiscard]] Impact edge_edge_ccd(const CcdQuery& query);

/// out[i] = vertex_face_ccd(queries[i]) for every i (`out` has the inputs' size: `batch_size`), on
/// `options.threads` threads (the answers do not depend on the thread count).
void vertex_face_ccd(std::span<const CcdQuery> queries, std::span<Impact> out,
                     const BatchOptions& options = {});
/// out[i] = edge_edge_ccd(queries[i]), as above.
void edge_edge_ccd(std::span<const CcdQuery> queries, std::span<Impact> out,
                   const BatchOptions& options = {});

}  // namespace contain::collide
