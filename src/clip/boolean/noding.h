#pragma once
// Noding of a set of segments: every segment becomes a chain of pieces such that no two pieces
// of any chains meet except at shared endpoints (they may coincide exactly: the arrangement
// merges them). Private to the polygon booleans and the polyline clipper.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/values/vec.h"

namespace contain::clip::detail {

struct NodingInput {
  Vec2 a;
  Vec2 b;
};

/// Chains in compressed rows: chain i is points[first[i]] .. points[first[i + 1] - 1], from the
/// input segment's a to its b (both bit for bit).
struct Noded {
  std::vector<Vec2> points;
  std::vector<std::uint32_t> first;
  /// Per point: 1 when the arrangement must treat it as a vertex of its own: a point made by a
  /// split, or an endpoint that another piece meets (shares, touches, overlaps) other than the
  /// next piece of a linked segment at their common joint. A point left 0 is met by no piece but
  /// its two neighbours along its path.
  std::vector<char> event;
  std::int64_t crossings = 0;
  std::int64_t rounds = 0;
  bool converged = true;
};

/// Splits the segments (none of zero length) until no two pieces cross, touch or overlap except
/// at shared endpoints. Touching points and overlap ends are input doubles (exact splits); a
/// proper crossing point is computed in extended precision, rounded to doubles and clamped to
/// both segments' boxes, and the pieces through it are checked again in the next round (rule
/// clip-noding, docs/robustness.md). Every decision is an exact orient2d sign. `magnitude`, when
/// positive, replaces the largest coordinate of the segments in the hot-pixel size (the booleans
/// pass the one of their whole input when they leave far edges out, so that the pixels stay the
/// same).
/// `links` (empty, or one per segment): links[i] != 0 when segment i + 1 starts where segment i
/// ends and continues the same path; the first round then takes candidate pairs from maximal
/// monotone chains of linked segments (rule clip-noding-chains) and the joints are not events.
[[nodiscard]] Noded node_segments(std::span<const NodingInput> segments,
                                  std::span<const char> links = {}, double magnitude = 0.0);

}  // namespace contain::clip::detail
