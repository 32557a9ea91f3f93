// libFuzzer target: the WKB reader (io::parse_wkb) on any bytes, binary or hex: a region or an
// error, never a crash; a region read survives the WKB writer bit for bit.
#include "contain/io/wkb.h"
#include "region_reader_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto region =
      contain::io::parse_wkb(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  if (!region) {
    FUZZ_CHECK(!region.error().message.empty());
    return 0;
  }
  contain::fuzz::check_region(*region);
  auto back = contain::io::parse_wkb(contain::io::format_wkb(*region), "round trip");
  FUZZ_CHECK(back.ok());
  FUZZ_CHECK(back->all_rings() == region->all_rings());
  return 0;
}
