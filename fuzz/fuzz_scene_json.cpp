// libFuzzer target: the scene JSON reader (io::parse_scene_json) on any text. A scene read has
// one id, mesh and transform per object, every mesh index in range and every transform finite;
// an error has a message.
#include <cmath>
#include <string_view>

#include "contain/io/scene_json.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // Mesh paths are relative to base_dir: a folder that does not exist keeps the fuzzer from
  // reading the machine's files.
  auto scene =
      io::parse_scene_json(text, {.source = "fuzz", .base_dir = "/nonexistent-contain-fuzz-dir"});
  if (!scene) {
    FUZZ_CHECK(!scene.error().message.empty());
    return 0;
  }
  FUZZ_CHECK(scene->ids.size() == scene->mesh_of.size());
  FUZZ_CHECK(scene->transforms.size() == scene->mesh_of.size());
  FUZZ_CHECK(scene->mesh_files.size() == scene->meshes.size());
  for (const std::int32_t m : scene->mesh_of)
    FUZZ_CHECK(m >= 0 && static_cast<std::size_t>(m) < scene->meshes.size());
  for (const Transform& t : scene->transforms)
    FUZZ_CHECK(std::isfinite(t.apply(Vec3{1, 1, 1}).x));
  return 0;
}
