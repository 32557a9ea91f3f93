#include "contain/clip/polygon_boolean.h"

#include <vector>

#include "clip/boolean_arrangement.h"

namespace contain::clip {

MultiPolygon polygon_boolean(std::span<const Ring> a, std::span<const Ring> b,
                             const PolygonBooleanOptions& options, PolygonBooleanStats* stats) {
  detail::ArrangementInput input;
  input.add_rings(a, {.a = 1, .b = 0});
  input.add_rings(b, {.a = 0, .b = 1});
  const detail::Arrangement arrangement(input);
  if (stats != nullptr) {
    stats->input_edges = static_cast<std::int64_t>(input.segments.size());
    stats->crossings = arrangement.crossings;
    stats->noding_rounds = arrangement.rounds;
    stats->graph_edges = arrangement.edges;
    stats->converged = arrangement.converged;
  }
  const Fill fill = options.fill;
  const Op op = options.op;
  return arrangement.extract([fill, op](int wa, int wb) {
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
  });
}

MultiPolygon polygon_boolean(const MultiPolygon& a, const MultiPolygon& b,
                             const PolygonBooleanOptions& options) {
  const std::vector<Ring> ra = a.all_rings(), rb = b.all_rings();
  return polygon_boolean(ra, rb, options);
}

MultiPolygon polygon_boolean(const Polygon& a, const Polygon& b,
                             const PolygonBooleanOptions& options) {
  return polygon_boolean(a.rings, b.rings, options);
}

}  // namespace contain::clip
