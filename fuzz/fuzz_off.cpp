// libFuzzer target: the OFF reader (io::parse_mesh with MeshFormat::off) on any bytes.
#include "mesh_reader_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return contain::fuzz::fuzz_mesh_reader(data, size, contain::io::MeshFormat::off);
}
