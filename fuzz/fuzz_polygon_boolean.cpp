// libFuzzer target: polygon booleans on random and degenerate pairs (self-intersecting rings,
// repeated points, spikes, shared and collinear edges, zero-area rings, 2^±1000 scalings), every
// operation and fill rule. Claims checked:
// - every result is valid by the OGC rules the function promises (the exact checker of the
//   boolean tests, tests/clip/boolean_checks.h), and its noding converged (no round cap);
// - identical operands give A \ A = A xor A = empty;
// - areas add up: |A u B| = |A n B| + |A xor B| and |A \ B| + |A n B| = |A| (|A| being A's
//   normalised area, the union with nothing), within the documented rounding of crossings.
#include <algorithm>
#include <cmath>
#include <vector>

#include "clip/boolean_checks.h"
#include "contain/clip/polygon_boolean.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

double area(const MultiPolygon& m) {
  return test::exact_signed_area(m).get_d();
}

double extent(const std::vector<Ring>& a, const std::vector<Ring>& b) {
  double e = 0.0;
  for (const auto* rings : {&a, &b}) {
    for (const Ring& ring : *rings) {
      for (const Vec2& v : ring)
        e = std::max({e, std::abs(v.x), std::abs(v.y)});
    }
  }
  return 2 * e;
}

std::vector<Ring> read_rings(fuzz::FuzzInput& in) {
  std::vector<Ring> rings(1 + in.byte() % 2);
  for (Ring& ring : rings) {
    ring.resize(3 + in.byte() % 6);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::uint8_t how = in.byte();
      ring[i] = (i > 0 && how % 8 == 0) ? ring[how / 8 % i] : in.point2();
    }
  }
  return rings;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  const Fill fill = static_cast<Fill>(in.byte() % 4);
  const std::vector<Ring> a = read_rings(in);
  std::vector<Ring> b = read_rings(in);
  if (in.byte() % 8 == 0) b = a;  // identical inputs: every edge shared

  MultiPolygon results[4];
  for (const clip::Op op :
       {clip::Op::intersection, clip::Op::union_, clip::Op::difference, clip::Op::xor_}) {
    const auto [r, stats] = clip::polygon_boolean_with_stats(a, b, {.op = op, .fill = fill});
    const ::testing::AssertionResult valid = test::is_valid_ogc(r);
    if (!valid) std::fprintf(stderr, "op %d: %s\n", static_cast<int>(op), valid.message());
    FUZZ_CHECK(valid);
    FUZZ_CHECK(stats.converged);  // the noding ends before its round cap
    results[static_cast<int>(op)] = r;
  }
  // Identical operands share every edge, so A \ A and A xor A are empty whatever the rounding
  // of crossings (crossing points do not depend on which copy of an edge is visited first).
  if (a == b) {
    FUZZ_CHECK(results[2].empty() && results[3].empty());
  }
  const std::vector<Ring> none;
  const double area_a =
      area(clip::polygon_boolean(a, none, {.op = clip::Op::union_, .fill = fill}));
  const double both = area(results[0]), either = area(results[1]);
  const double a_only = area(results[2]), one = area(results[3]);
  const double e = extent(a, b);
  if (e * e < 1e300) {
    // Each result moves each crossing point by a few ulps of the extent; 16 edges of each input
    // give at most 256 crossings.
    const double tolerance = 1e-12 * e * e * 256;
    FUZZ_CHECK(std::abs(either - (both + one)) <= tolerance);
    FUZZ_CHECK(std::abs(area_a - (a_only + both)) <= tolerance);
    FUZZ_CHECK(both <= either + tolerance);
  }
  return 0;
}
