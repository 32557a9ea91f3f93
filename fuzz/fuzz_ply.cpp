// libFuzzer target: the PLY reader, ASCII and both binary encodings (from the header).
#include "mesh_reader_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return contain::fuzz::fuzz_mesh_reader(data, size, contain::io::MeshFormat::ply_ascii);
}
