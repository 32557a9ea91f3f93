#pragma once
// The boolean engine behind `clip::polygon_boolean`, stage by stage: its input (far edges
// replaced, far_edges.h), the arrangement (noding, graph, face labels: arrangement.h) and the
// extraction of the kept faces (extract.cpp). Private to clip.

#include <span>

#include "clip/boolean/arrangement.h"
#include "contain/clip/polygon_boolean.h"

namespace contain::clip::detail {

/// The segments of A and B for the arrangement. For an intersection or difference, the larger
/// operand's edges far from the other operand are replaced by frame paths (rule
/// clip-far-edges). False when the result is empty without an arrangement (an operand without
/// edges, or boxes whose intersection has no interior).
[[nodiscard]] bool boolean_input(std::span<const Ring> a, std::span<const Ring> b, Op op,
                                 ArrangementInput& input);

/// Whether a face with winding numbers wa, wb is in `op`'s result under `fill`.
[[nodiscard]] bool keep_face(Op op, Fill fill, int wa, int wb);

/// The whole boolean: input, arrangement, extraction.
[[nodiscard]] MultiPolygon boolean_engine(std::span<const Ring> a, std::span<const Ring> b,
                                          const PolygonBooleanOptions& options,
                                          PolygonBooleanStats* stats);

}  // namespace contain::clip::detail
