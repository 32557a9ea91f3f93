// libFuzzer target: sections and shadows of closed meshes of fixed topology (cube, octahedron,
// two tetrahedra, a cube and an inside-out cube) whose vertices are fuzzed: flat, folded,
// self-intersecting, with coincident vertices and zero-area triangles, at 2^±1000 scales, cut
// by planes through vertices, edge midpoints and anywhere. Claims checked:
// - the closed mesh is accepted and every section is OGC-valid (exact checks of boolean_checks);
// - every ring edge names a triangle of the mesh, and the triangle meets the plane (closed
//   interval of its corners along the axis);
// - answers are the same for one thread and two, and for each plane alone;
// - the shadow is OGC-valid; a mesh with a triangle removed is refused.
#include <algorithm>
#include <array>
#include <vector>

#include "clip/boolean_checks.h"
#include "contain/clip/slice_mesh.h"
#include "fuzz_meshes.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

using fuzz::kCube;
using fuzz::kOctahedron;
using fuzz::kTwoTetrahedra;

double coord(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

Mesh fuzzed_mesh(fuzz::FuzzInput& in) {
  Mesh mesh;
  const std::uint8_t kind = in.byte() % 4;
  if (kind == 0) mesh.triangles.assign(kCube.begin(), kCube.end());
  if (kind == 1) mesh.triangles.assign(kOctahedron.begin(), kOctahedron.end());
  if (kind == 2) mesh.triangles.assign(kTwoTetrahedra.begin(), kTwoTetrahedra.end());
  if (kind == 3) {  // a cube and a second one turned inside out: a cavity, or a subtraction
    mesh.triangles.assign(kCube.begin(), kCube.end());
    for (TriangleIndices t : kCube)
      mesh.triangles.push_back({t[0] + 8, t[2] + 8, t[1] + 8});
  }
  std::int32_t count = 0;
  for (const TriangleIndices& t : mesh.triangles)
    count = std::max({count, t[0] + 1, t[1] + 1, t[2] + 1});
  mesh.vertices.resize(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const std::uint8_t how = in.byte();
    mesh.vertices[i] = (i > 0 && how % 8 == 0) ? mesh.vertices[how / 8 % i] : in.point3();
  }
  return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  const Mesh mesh = fuzzed_mesh(in);
  const auto axis = static_cast<clip::Axis>(in.byte() % 3);
  const int k = static_cast<int>(axis);
  std::vector<double> values;
  for (int i = 0; i < 4; ++i) {
    const std::uint8_t how = in.byte();
    const Vec3 u = mesh.vertices[how % mesh.vertices.size()];
    const Vec3 v = mesh.vertices[how / 16 % mesh.vertices.size()];
    if (how % 4 <= 1) {
      values.push_back(coord(u, k));
    } else if (how % 4 == 2) {
      values.push_back(coord(u, k) / 2 + coord(v, k) / 2);
    } else {
      values.push_back(in.coordinate());
    }
  }
  const auto one = clip::slice_mesh(mesh, values, {.axis = axis}, {.threads = 1});
  FUZZ_CHECK(one.ok());
  const auto two = clip::slice_mesh(mesh, values, {.axis = axis}, {.threads = 2});
  FUZZ_CHECK(two.ok());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const clip::Section& s = (*one)[i];
    FUZZ_CHECK(s.value == values[i]);
    FUZZ_CHECK(s.region == (*two)[i].region && s.triangles == (*two)[i].triangles);
    FUZZ_CHECK(test::is_valid_ogc(s.region));
    const std::vector<Ring> rings = s.region.all_rings();
    FUZZ_CHECK(rings.size() == s.triangles.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      FUZZ_CHECK(rings[r].size() == s.triangles[r].size());
      for (const std::int32_t t : s.triangles[r]) {
        FUZZ_CHECK(t >= 0 && static_cast<std::size_t>(t) < mesh.triangles.size());
        const Triangle3 tri = mesh.triangle(static_cast<std::size_t>(t));
        const double lo = std::min({coord(tri.a, k), coord(tri.b, k), coord(tri.c, k)});
        const double hi = std::max({coord(tri.a, k), coord(tri.b, k), coord(tri.c, k)});
        FUZZ_CHECK(lo <= s.value && s.value <= hi);
      }
    }
    const std::vector<double> alone{values[i]};
    const auto single = clip::slice_mesh(mesh, alone, {.axis = axis}, {.threads = 1});
    FUZZ_CHECK(single.ok() && (*single)[0].region == s.region);
  }
  const auto shadow = clip::shadow(mesh, {.axis = axis});
  FUZZ_CHECK(shadow.ok() && test::is_valid_ogc(*shadow));
  // Without its last triangle the mesh is open, unless that triangle repeats a corner by
  // position (its edges then come in pairs of opposite directions).
  const Triangle3 last = mesh.triangle(mesh.triangles.size() - 1);
  if (!(last.a == last.b) && !(last.b == last.c) && !(last.c == last.a)) {
    Mesh open = mesh;
    open.triangles.pop_back();
    const std::vector<double> first{values[0]};
    FUZZ_CHECK(!clip::slice_mesh(open, first).ok());
  }
  return 0;
}
