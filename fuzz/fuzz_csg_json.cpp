// libFuzzer target: the CSG JSON reader (io::parse_csg_json) on any text; a tree read is
// prepared and queried at a few points, and a point's answer for A and for complement(A) are
// each other's mirror (in <-> out, on stays on).
#include <string_view>

#include "contain/inside/csg.h"
#include "contain/io/csg_json.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // Mesh leaves name files relative to base_dir: a folder that does not exist keeps the fuzzer
  // from reading the machine's files.
  auto tree =
      io::parse_csg_json(text, {.source = "fuzz", .base_dir = "/nonexistent-contain-fuzz-dir"});
  if (!tree) {
    FUZZ_CHECK(!tree.error().message.empty());
    return 0;
  }
  auto solid = inside::CsgSolid::prepare(*tree);
  if (!solid) return 0;
  auto complement = inside::CsgSolid::prepare(Csg::complement(*tree));
  FUZZ_CHECK(complement.ok());
  for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0.5, -0.25, 2}, Vec3{-3, 7, 1e-300}}) {
    const Location a = solid->locate(p);
    const Location b = complement->locate(p);
    FUZZ_CHECK((a == Location::boundary) == (b == Location::boundary));
    FUZZ_CHECK(a == Location::boundary || a != b);
  }
  return 0;
}
