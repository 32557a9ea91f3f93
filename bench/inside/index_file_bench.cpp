// Saved MeshIndex: building the index against loading it from its file (memory mapped, every
// field checked), on the 100k-triangle torus scenes::torus(1, 0.4, 500, 100) or a mesh file
// given as the first argument; the loaded index must answer every point as the built one.
// Best of 5 runs of each step, one thread. Plain main: one run prints the table.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "contain/inside/index_file.h"
#include "contain/inside/mesh_index.h"
#include "contain/io/index_io.h"
#include "contain/io/mesh_io.h"
#include "scenes/scenes.h"

namespace {

template <class F>
double best_seconds(F&& f, int runs = 5) {
  double best = 1e300;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace contain;
  Mesh mesh;
  std::string name = "scenes::torus(1, 0.4, 500, 100)";
  if (argc > 1) {
    auto file = io::read_mesh(argv[1]);
    if (!file) {
      std::fprintf(stderr, "%s\n", file.error().what().c_str());
      return 3;
    }
    mesh = std::move(file->mesh);
    name = argv[1];
  } else {
    mesh = scenes::torus(1.0, 0.4, 500, 100);
  }
  const std::string path = argc > 2 ? argv[2] : "/tmp/contain_index_file_bench.cidx";
  inside::MeshIndex built;
  const double build = best_seconds([&] { built = inside::MeshIndex(mesh); });
  std::vector<std::byte> bytes;
  const double format = best_seconds([&] { bytes = inside::format_index(built); });
  if (!io::write_index(bytes, path)) return 3;
  const double fingerprint = best_seconds([&] { (void)inside::fingerprint(mesh); });
  inside::MeshIndex loaded;
  const double load = best_seconds([&] { loaded = std::move(io::read_mesh_index(path).value()); });
  const double check = best_seconds([&] { (void)inside::parse_index_header(bytes); });

  Box3 box = built.bounds();
  const std::vector<Vec3> points = scenes::uniform_points(box, 1000000, 1);
  std::vector<Location> a(points.size()), b(points.size());
  built.locate(points, a, {.threads = 1});
  loaded.locate(points, b, {.threads = 1});
  const auto mismatches = std::inner_product(a.begin(), a.end(), b.begin(), std::size_t{0},
                                             std::plus<>(), std::not_equal_to<>());
  std::printf("mesh %s: %zu triangles; index file %zu bytes (%s)\n", name.c_str(),
              mesh.triangles.size(), bytes.size(), path.c_str());
  std::printf("step (1 thread, best of 5)                      seconds\n");
  std::printf("build MeshIndex                                 %.4f\n", build);
  std::printf("format_index (to bytes)                         %.4f\n", format);
  std::printf("read_mesh_index (mmap, checks, arrays)          %.4f\n", load);
  std::printf("  of which parse_index_header (both checksums)  %.4f\n", check);
  std::printf("fingerprint of the mesh (--mesh with --index)   %.4f\n", fingerprint);
  std::printf("build / load                                    %.1fx\n", build / load);
  std::printf("1e6 uniform points: %zu answers differ between built and loaded\n", mismatches);
  return mismatches == 0 ? 0 : 1;
}
