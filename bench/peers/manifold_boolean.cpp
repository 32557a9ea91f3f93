// Manifold's boolean of two solids as its users call it, as a whole process for the solids
// benchmark (issue 25): read two OFF files, A op B, write OFF.
// Usage: manifold_boolean A.off B.off --op union|intersection|difference OUT.off
// One thread (Manifold built with MANIFOLD_PAR=OFF). On stderr, the kernel times: building
// Manifold's half-edge solids from the two meshes, the boolean itself (Manifold's booleans are
// lazy: forced by NumTri()), and exporting the result as a MeshGL64; reading and writing OFF
// (contain::io, as contain's own runs) are outside them.

#include <cstdio>
#include <optional>

#include "bench/peers/manifold_mesh.h"
#include "bench/peers/peer_driver.h"

using namespace contain;
using namespace contain::bench;

namespace {

manifold::Manifold apply(const manifold::Manifold& a, const manifold::Manifold& b, BooleanOp op) {
  switch (op) {
    case BooleanOp::union_:
      return a + b;
    case BooleanOp::intersection:
      return a ^ b;
    case BooleanOp::difference:
      return a - b;
  }
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<BooleanArgs> args = parse_boolean_args(argc, argv);
  if (!args) {
    std::fprintf(
        stderr, "usage: manifold_boolean A.off B.off --op union|intersection|difference OUT.off\n");
    return 2;
  }
  const std::optional<Mesh> mesh_a = read_off(args->a);
  const std::optional<Mesh> mesh_b = read_off(args->b);
  if (!mesh_a || !mesh_b) return 3;

  const KernelClock build_clock;
  const std::optional<manifold::Manifold> a = build_manifold(*mesh_a, args->a);
  const std::optional<manifold::Manifold> b = build_manifold(*mesh_b, args->b);
  if (!a || !b) return 3;
  build_clock.report("build");

  const KernelClock boolean_clock;
  const manifold::Manifold result = apply(*a, *b, args->op);
  const std::size_t triangles = result.NumTri();
  boolean_clock.report("boolean");

  const KernelClock export_clock;
  const manifold::MeshGL64 out = result.GetMeshGL64();
  export_clock.report("export");
  if (result.Status() != manifold::Manifold::Error::NoError) {
    std::fprintf(stderr, "manifold_boolean: Manifold::Error %d\n",
                 static_cast<int>(result.Status()));
    return 1;
  }
  if (const Status written = io::write_mesh(from_manifold(out), args->out); !written) {
    std::fprintf(stderr, "%s\n", written.error().what().c_str());
    return 3;
  }
  std::printf("%zu triangles, volume %.9g\n", triangles, result.Volume());
  return 0;
}
