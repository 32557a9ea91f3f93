// The boolean engine, stage by stage: input (far edges replaced), arrangement, extraction.

#include "clip/boolean/engine.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "clip/boolean/far_edges.h"

namespace contain::clip::detail {

bool keep_face(Op op, Fill fill, int wa, int wb) {
  const bool in_a = is_filled(fill, wa), in_b = is_filled(fill, wb);
  switch (op) {
    case Op::intersection:
      return in_a && in_b;
    case Op::union_:
      return in_a || in_b;
    case Op::difference:
      return in_a && !in_b;
    case Op::xor_:
      return in_a != in_b;
  }
  return false;
}

bool boolean_input(std::span<const Ring> a, std::span<const Ring> b, Op op,
                   ArrangementInput& input) {
  bool reduced = false;
  if (op == Op::intersection || op == Op::difference) {
    const Operand oa = measure(a), ob = measure(b);
    input.reserve(oa.edges + ob.edges + 64);
    const double magnitude = std::max(oa.magnitude, ob.magnitude);
    if (oa.edges == 0 || (op == Op::intersection && ob.edges == 0)) return false;
    // Faces with w != 0 lie inside the operand's box: an intersection of boxes without interior
    // has no such face.
    if (op == Op::intersection && ob.edges > 0 &&
        !(std::max(oa.box.min.x, ob.box.min.x) < std::min(oa.box.max.x, ob.box.max.x) &&
          std::max(oa.box.min.y, ob.box.min.y) < std::min(oa.box.max.y, ob.box.max.y))) {
      return false;
    }
    // The operand to reduce, and the box R it must stay right on.
    const bool reduce_a = op == Op::intersection && oa.edges > ob.edges;
    const Operand& big = reduce_a ? oa : ob;
    const Operand& small = reduce_a ? ob : oa;
    if (big.edges > 0 && magnitude > 0.0) {
      const double margin = std::ldexp(1.0, std::ilogb(magnitude) - 20);
      Box2 r = small.box;
      r.min.x -= margin;
      r.min.y -= margin;
      r.max.x += margin;
      r.max.y += margin;
      if (!covers(r, big.box)) {
        Box2 frame;
        frame.min.x = std::min({oa.box.min.x, ob.box.min.x, r.min.x}) - margin;
        frame.min.y = std::min({oa.box.min.y, ob.box.min.y, r.min.y}) - margin;
        frame.max.x = std::max({oa.box.max.x, ob.box.max.x, r.max.x}) + margin;
        frame.max.y = std::max({oa.box.max.y, ob.box.max.y, r.max.y}) + margin;
        const bool finite = std::isfinite(frame.min.x) && std::isfinite(frame.min.y) &&
                            std::isfinite(frame.max.x) && std::isfinite(frame.max.y);
        FarEdges far(r, frame);
        input.magnitude = magnitude;
        if (!finite) {
          reduced = false;
        } else if (reduce_a) {
          reduced = far.add(a, {.a = 1, .b = 0}, input);
          if (reduced) input.add_rings(b, {.a = 0, .b = 1});
        } else {
          input.add_rings(a, {.a = 1, .b = 0});
          reduced = far.add(b, {.a = 0, .b = 1}, input);
        }
        if (!reduced) input = {};
      }
    }
  }
  if (!reduced) {
    input.add_rings(a, {.a = 1, .b = 0});
    input.add_rings(b, {.a = 0, .b = 1});
  }
  return true;
}

MultiPolygon boolean_engine(std::span<const Ring> a, std::span<const Ring> b,
                            const PolygonBooleanOptions& options, PolygonBooleanStats* stats) {
  ArrangementInput input;
  if (!boolean_input(a, b, options.op, input)) {
    if (stats != nullptr) *stats = {};
    return {};
  }
  const Arrangement arrangement(input);
  if (stats != nullptr) {
    stats->input_edges = static_cast<std::int64_t>(input.segments.size());
    stats->crossings = arrangement.crossings;
    stats->noding_rounds = arrangement.rounds;
    stats->graph_edges = arrangement.edges;
    stats->converged = arrangement.converged;
  }
  const Fill fill = options.fill;
  const Op op = options.op;
  return arrangement.extract([fill, op](int wa, int wb) { return keep_face(op, fill, wa, wb); });
}

}  // namespace contain::clip::detail
