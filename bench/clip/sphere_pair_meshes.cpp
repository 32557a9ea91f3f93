// The meshes of the solids benchmark (issue 25), written as OFF files for whole-process runs of
// contain and its peers (bench/peers/): the pair of Manifold's own boolean benchmark, a unit
// sphere and the same sphere shifted by half its radius on each axis, on five rungs of 2,048 to
// 524,288 triangles each.
//   sphere: a regular octahedron whose faces are cut into n x n triangles, every vertex pushed
//   out to the unit sphere (as Manifold::Sphere(1, 4n) builds it, so the triangle counts are the
//   same: 8 n^2 for n = 16, 32, 64, 128, 256). Vertices are keyed by their integer lattice point
//   on the octahedron |i| + |j| + |k| = n, so the faces share them: the mesh is closed, manifold
//   and outward (checked before writing; the program fails otherwise).
// Usage: sphere_pair_meshes OUT_DIR [--max-triangles N]
// Writes OUT_DIR/sphere_<T>.off and OUT_DIR/sphere_<T>_shifted.off for each rung of T <= N
// triangles (default: all five), and prints one line per file.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "contain/io/mesh_io.h"
#include "contain/shapes/mesh_closure.h"
#include "contain/shapes/mesh_validation.h"

using namespace contain;

namespace {

using Lattice = std::array<int, 3>;

class OctahedronSphere {
 public:
  explicit OctahedronSphere(int n) : n_(n) {}

  Mesh build() {
    for (int sx : {1, -1}) {
      for (int sy : {1, -1}) {
        for (int sz : {1, -1})
          add_face(sx, sy, sz);
      }
    }
    return Mesh{std::move(vertices_), std::move(triangles_)};
  }

 private:
  // One octant's face: lattice points (sx a, sy b, sz c) with a + b + c = n. The triangles of
  // the positive octant, listed (a, b, c) -> (a+1, b, c-1) -> (a, b+1, c-1), turn
  // counter-clockwise seen from outside; a mirror in an odd number of axes reverses them.
  void add_face(int sx, int sy, int sz) {
    const bool flip = sx * sy * sz < 0;
    const auto point = [&](int a, int b) { return vertex({sx * a, sy * b, sz * (n_ - a - b)}); };
    const auto add = [&](std::int32_t p, std::int32_t q, std::int32_t r) {
      triangles_.push_back(flip ? TriangleIndices{p, r, q} : TriangleIndices{p, q, r});
    };
    for (int a = 0; a < n_; ++a) {
      for (int b = 0; a + b < n_; ++b) {
        add(point(a, b), point(a + 1, b), point(a, b + 1));
        if (a + b + 1 < n_) add(point(a + 1, b), point(a + 1, b + 1), point(a, b + 1));
      }
    }
  }

  std::int32_t vertex(const Lattice& p) {
    const auto [it, added] = index_.try_emplace(p, static_cast<std::int32_t>(vertices_.size()));
    if (added) {
      const double x = p[0], y = p[1], z = p[2];
      const double norm = std::sqrt(x * x + y * y + z * z);
      vertices_.push_back({x / norm, y / norm, z / norm});
    }
    return it->second;
  }

  int n_;
  std::map<Lattice, std::int32_t> index_;
  std::vector<Vec3> vertices_;
  std::vector<TriangleIndices> triangles_;
};

Mesh shifted(Mesh mesh, double by) {
  for (Vec3& v : mesh.vertices)
    v = {v.x + by, v.y + by, v.z + by};
  return mesh;
}

bool write_checked(const Mesh& mesh, const std::filesystem::path& path) {
  const MeshReport report = validate_mesh(mesh);
  if (unmatched_edge(mesh) || !report.outward() || !report.manifold()) {
    std::fprintf(stderr, "sphere_pair_meshes: %s is not a closed outward manifold: %s\n",
                 path.c_str(), report.summary().c_str());
    return false;
  }
  if (const Status written = io::write_mesh(mesh, path); !written) {
    std::fprintf(stderr, "sphere_pair_meshes: %s\n", written.error().what().c_str());
    return false;
  }
  std::printf("%s: %zu triangles, %zu vertices, volume %.6f\n", path.c_str(), mesh.triangles.size(),
              mesh.vertices.size(), report.signed_volume);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  long max_triangles = 1L << 20;
  if (argc == 4 && std::string(argv[2]) == "--max-triangles") {
    max_triangles = std::strtol(argv[3], nullptr, 10);
  } else if (argc != 2) {
    std::fprintf(stderr, "usage: sphere_pair_meshes OUT_DIR [--max-triangles N]\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (error) {
    std::fprintf(stderr, "sphere_pair_meshes: cannot create %s: %s\n", out.c_str(),
                 error.message().c_str());
    return 3;
  }
  for (int n : {16, 32, 64, 128, 256}) {
    const long triangles = 8L * n * n;
    if (triangles > max_triangles) break;
    const Mesh sphere = OctahedronSphere(n).build();
    const std::string stem = "sphere_" + std::to_string(triangles);
    if (!write_checked(sphere, out / (stem + ".off")) ||
        !write_checked(shifted(sphere, 0.5), out / (stem + "_shifted.off"))) {
      return 1;
    }
  }
  return 0;
}
