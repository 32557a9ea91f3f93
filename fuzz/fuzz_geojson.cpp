// libFuzzer target: the GeoJSON reader (io::parse_geojson) on any text.
#include "region_reader_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto region = contain::io::parse_geojson(
      std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  if (!region) {
    FUZZ_CHECK(!region.error().message.empty());
    return 0;
  }
  contain::fuzz::check_region(*region);
  return 0;
}
