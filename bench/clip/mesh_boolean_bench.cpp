// contain's mesh boolean as a whole process for the solids benchmark (issue 25), beside the peer
// drivers of ../peers: read two OFF files, A op B, write OFF.
// Usage: mesh_boolean_bench A.off B.off --op union|intersection|difference OUT.off
// On stderr, the kernel time of `clip::mesh_boolean` alone (wall and thread CPU: the machine is
// shared); reading and writing OFF (contain::io, as the peers' runs) are outside it.

#include <array>
#include <cstdio>
#include <optional>

#include "bench/peers/peer_driver.h"
#include "contain/clip/mesh_boolean.h"
#include "contain/io/mesh_io.h"

using namespace contain;
using namespace contain::bench;

namespace {

clip::Op op_of(BooleanOp op) {
  switch (op) {
    case BooleanOp::union_:
      return clip::Op::union_;
    case BooleanOp::intersection:
      return clip::Op::intersection;
    case BooleanOp::difference:
      return clip::Op::difference;
  }
  return clip::Op::union_;
}

std::optional<Mesh> read(const char* path) {
  Result<io::MeshFile> file = io::read_mesh(path);
  if (!file) {
    std::fprintf(stderr, "%s\n", file.error().what().c_str());
    return std::nullopt;
  }
  return std::move(file->mesh);
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<BooleanArgs> args = parse_boolean_args(argc, argv);
  if (!args) {
    std::fprintf(
        stderr,
        "usage: mesh_boolean_bench A.off B.off --op union|intersection|difference OUT.off\n");
    return 2;
  }
  std::optional<Mesh> a = read(args->a.c_str());
  std::optional<Mesh> b = read(args->b.c_str());
  if (!a || !b) return 3;
  const std::array<Mesh, 2> inputs{std::move(*a), std::move(*b)};

  const KernelClock clock;
  Result<clip::MeshBooleanResult> result = clip::mesh_boolean(inputs, {op_of(args->op)});
  clock.report("boolean");
  if (!result) {
    std::fprintf(stderr, "mesh_boolean_bench: %s\n", result.error().what().c_str());
    return 1;
  }
  if (const Status written = io::write_mesh(result->mesh, args->out); !written) {
    std::fprintf(stderr, "%s\n", written.error().what().c_str());
    return 3;
  }
  std::printf("%zu triangles, volume %.9g, %zu shells, %zu moved\n", result->mesh.triangles.size(),
              result->volume, result->shells, result->moved);
  return 0;
}
