// libFuzzer target: exact booleans of two small solids (issue 25) from the fuzz bytes:
// tetrahedra and boxes of degenerate-biased coordinates (shared vertices, faces and edges,
// flat and inside-out shells, 2^±1000 scalings), triangle soups that are usually open, and
// identical or shifted copies. Claims checked:
// - nothing crashes or hangs, and every refusal is a stated one: an open input or a
//   non-finite coordinate (invalid_value), or a rounding that could not be repaired
//   (degenerate); closed inputs are never refused as open;
// - every result is the contract's mesh: finite vertices, indices in range, closed (each
//   directed edge as often as its reverse), no zero-area triangle (predicates::collinear, exact)
//   and no two triangles meeting other than at shared corners or a shared edge
//   (collide::self_intersections, exact);
// - every result is the boolean's answer: a sample point farther than 4e-9 x (the largest input
//   coordinate) from every input's surface (exact distance test) lies in the result exactly when
//   the operation of its places in the inputs (exact winding numbers) says so; the contract lets
//   the written mesh stray 1e-9 x that coordinate from the exact boundary, no more.
#include <algorithm>
#include <cmath>
#include <vector>

#include "contain/clip/mesh_boolean.h"
#include "contain/collide/self_intersections.h"
#include "contain/distance/mesh_distance.h"
#include "contain/inside/mesh_index.h"
#include "contain/predicates/closest_feature.h"
#include "contain/shapes/mesh_closure.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

Mesh tetrahedron(fuzz::FuzzInput& in) {
  Mesh m;
  for (int i = 0; i < 4; ++i)
    m.vertices.push_back(in.point3());
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};  // either orientation: sign free
  return m;
}

Mesh box(fuzz::FuzzInput& in) {
  const Vec3 a = in.point3(), b = in.point3();
  const Vec3 lo{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  const Vec3 hi{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  if (in.byte() % 4 == 0) {  // inside out: subtracts
    for (TriangleIndices& t : m.triangles)
      std::swap(t[1], t[2]);
  }
  return m;
}

Mesh soup(fuzz::FuzzInput& in) {
  Mesh m;
  const int vertices = in.small_int(3, 6);
  for (int i = 0; i < vertices; ++i)
    m.vertices.push_back(in.point3());
  const int triangles = in.small_int(0, 6);
  for (int t = 0; t < triangles; ++t) {
    m.triangles.push_back({in.byte() % vertices, in.byte() % vertices, in.byte() % vertices});
  }
  return m;
}

Mesh solid(fuzz::FuzzInput& in) {
  switch (in.byte() % 4) {
    case 0:
      return tetrahedron(in);
    case 1:
    case 2:
      return box(in);
    default:
      return soup(in);
  }
}

void check_result(const Mesh& m) {
  for (const Vec3& v : m.vertices)
    FUZZ_CHECK(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
  const auto n = static_cast<std::int32_t>(m.vertices.size());
  for (const TriangleIndices& t : m.triangles) {
    for (std::int32_t i : t)
      FUZZ_CHECK(i >= 0 && i < n);
  }
  FUZZ_CHECK(!unmatched_edge(m).has_value());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Triangle3 tri = m.triangle(t);
    FUZZ_CHECK(!predicates::collinear(tri.a, tri.b, tri.c));
  }
  FUZZ_CHECK(collide::self_intersections(m, {.keep = 1, .limit = 1}).empty());
}

bool holds(clip::Op op, std::size_t inputs, bool a, bool b) {
  if (inputs == 1) return a;
  switch (op) {
    case clip::Op::union_:
      return a || b;
    case clip::Op::intersection:
      return a && b;
    case clip::Op::difference:
      return a && !b;
    case clip::Op::xor_:
      return a != b;
  }
  return false;
}

// A point from the input: anywhere at the input's scale, or (mostly) a mean of four input
// vertices under positive weights (inside their tetrahedron), so that many land inside solids.
Vec3 sample(fuzz::FuzzInput& in, const std::vector<Mesh>& inputs) {
  const std::uint8_t how = in.byte();
  const Mesh& m = inputs[how % inputs.size()];
  if (how % 4 == 0 || m.vertices.empty()) return in.point3();
  Vec3 sum{0, 0, 0};
  double total = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Vec3 v = m.vertices[in.byte() % m.vertices.size()];
    const double w = 1 + in.byte() % 7;
    sum = {sum.x + w * v.x, sum.y + w * v.y, sum.z + w * v.z};
    total += w;
  }
  return {sum.x / total, sum.y / total, sum.z / total};
}

// Sample points from the rest of the input: where each is clear of every input's surface, the
// result must hold it exactly as the operation of its places in the inputs says.
void check_answers(fuzz::FuzzInput& in, const std::vector<Mesh>& inputs, clip::Op op,
                   const Mesh& result) {
  double largest = 0.0;
  for (const Mesh& m : inputs) {
    for (const Vec3& v : m.vertices)
      largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  const double margin = 4e-9 * largest;
  if (!std::isfinite(margin)) return;
  std::vector<inside::MeshIndex> places;
  std::vector<distance::MeshDistance> surfaces;
  for (const Mesh& m : inputs) {
    places.emplace_back(m, inside::MeshIndexOptions{.queries = 8});
    if (places.back().regime() != inside::MeshRegime::closed_exact) return;
    surfaces.emplace_back(m, distance::MeshDistanceOptions{.signs = false});
  }
  const inside::MeshIndex answer(result, {.queries = 8});
  for (int k = 0; k < 8 && !in.empty(); ++k) {
    const Vec3 p = sample(in, inputs);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    bool clear = true;
    for (const distance::MeshDistance& s : surfaces)
      clear = clear && !s.within(p, margin);
    if (!clear) continue;
    const bool a = places[0].locate(p) == Location::inside;
    const bool b = inputs.size() > 1 && places[1].locate(p) == Location::inside;
    FUZZ_CHECK((answer.locate(p) == Location::inside) == holds(op, inputs.size(), a, b));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  const auto op = static_cast<clip::Op>(in.byte() % 4);
  std::vector<Mesh> inputs{solid(in)};
  const std::uint8_t second = in.byte();
  if (second % 8 == 0) {
    inputs.push_back(inputs[0]);  // identical: every face shared
  } else if (second % 8 == 1) {
    Mesh shifted = inputs[0];  // shifted by a coordinate: faces coplanar, edges collinear
    const Vec3 by = in.point3();
    for (Vec3& v : shifted.vertices)
      v = {v.x + by.x, v.y + by.y, v.z + by.z};
    inputs.push_back(std::move(shifted));
  } else if (second % 8 != 2) {
    inputs.push_back(solid(in));
  }  // else one input: the repair
  const bool closed =
      !unmatched_edge(inputs[0]) && (inputs.size() < 2 || !unmatched_edge(inputs[1]));
  bool finite = true;
  for (const Mesh& m : inputs) {
    for (const Vec3& v : m.vertices)
      finite = finite && std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  }
  auto result = clip::mesh_boolean(inputs, {.op = inputs.size() == 1 ? clip::Op::union_ : op});
  if (!result) {
    const ErrorKind kind = result.error().kind;
    FUZZ_CHECK(kind == ErrorKind::invalid_value || kind == ErrorKind::degenerate);
    if (closed && finite) FUZZ_CHECK(kind == ErrorKind::degenerate);
    return 0;
  }
  FUZZ_CHECK(closed && finite);
  check_result(result->mesh);
  check_answers(in, inputs, op, result->mesh);
  return 0;
}
