// libFuzzer target: point in polyhedron on closed meshes of fixed topology (octahedron, cube,
// two tetrahedra) whose vertices are fuzzed: flat, folded, self-intersecting, with coincident
// vertices and zero-area triangles, at 2^±1000 scales. Claims checked:
// - MeshIndex on a coarse, the default and a fine grid gives the same answer everywhere (the
//   perturbed +x ray rule does not depend on the grid), and so does point_in_mesh;
// - a vertex of the mesh is `boundary` (open meshes) or answered alike on every grid (closed
//   meshes: the solid of their winding number may hold it inside or leave it out);
// - batch answers equal one-by-one answers.
#include <array>
#include <vector>

#include "contain/inside/mesh_index.h"
#include "contain/inside/point_in_mesh.h"
#include "fuzz_meshes.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

using fuzz::kCube;
using fuzz::kOctahedron;
using fuzz::kTwoTetrahedra;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  Mesh mesh;
  switch (in.byte() % 3) {
    case 0:
      mesh.triangles.assign(kOctahedron.begin(), kOctahedron.end());
      mesh.vertices.resize(6);
      break;
    case 1:
      mesh.triangles.assign(kCube.begin(), kCube.end());
      mesh.vertices.resize(8);
      break;
    default:
      mesh.triangles.assign(kTwoTetrahedra.begin(), kTwoTetrahedra.end());
      mesh.vertices.resize(8);
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const std::uint8_t how = in.byte();
    mesh.vertices[i] = (i > 0 && how % 8 == 0) ? mesh.vertices[how / 8 % i] : in.point3();
  }
  if (in.byte() % 8 == 0) mesh.triangles.pop_back();  // open: the winding number regime

  std::vector<Vec3> points;
  for (int k = 0; k < 6; ++k) {
    const std::uint8_t how = in.byte();
    const Vec3 u = mesh.vertices[how % mesh.vertices.size()];
    const Vec3 v = mesh.vertices[how / 16 % mesh.vertices.size()];
    if (how % 4 == 0) {
      points.push_back(u);
    } else if (how % 4 == 1) {
      points.push_back({u.x / 2 + v.x / 2, u.y / 2 + v.y / 2, u.z / 2 + v.z / 2});
    } else {
      points.push_back(in.point3());
    }
  }

  // Grids capped: the answers do not depend on them, and a fine grid under a few huge, thin
  // triangles costs seconds per input in this build.
  const inside::MeshIndex index(mesh, {.min_cells = 64, .max_cells = 1 << 12});
  const inside::MeshIndex coarse(mesh, {.cells_per_triangle = 0.1, .min_cells = 1, .max_cells = 8});
  const inside::MeshIndex fine(mesh,
                               {.cells_per_triangle = 512, .min_cells = 1, .max_cells = 1 << 12});
  FUZZ_CHECK(coarse.regime() == index.regime() && fine.regime() == index.regime());
  std::vector<Location> batch(points.size());
  index.locate(points, batch, {.threads = 1});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    const Location answer = index.locate(p);
    FUZZ_CHECK(batch[i] == answer);
    if (index.regime() == inside::MeshRegime::closed_exact) {
      FUZZ_CHECK(coarse.locate(p) == answer);
      FUZZ_CHECK(fine.locate(p) == answer);
    } else {
      FUZZ_CHECK((coarse.locate(p) == Location::boundary) == (answer == Location::boundary));
    }
  }
  for (const Vec3& v : mesh.vertices) {
    // A vertex lies on the surface. A closed mesh answers the solid of its winding number, which
    // may hold a vertex inside (a part buried in another) or not at all (parts that enclose no
    // volume): there the three grids agree at it; any other mesh gives `on`.
    const Location at = index.locate(v);
    if (index.regime() == inside::MeshRegime::closed_exact) {
      FUZZ_CHECK(coarse.locate(v) == at && fine.locate(v) == at);
    } else {
      FUZZ_CHECK(at == Location::boundary);
    }
  }
  FUZZ_CHECK(inside::point_in_mesh(mesh, points[0], {.max_cells = 1 << 12}) ==
             index.locate(points[0]));
  return 0;
}
