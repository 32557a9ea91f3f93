// libFuzzer target: the CCD query readers (io::parse_ccd_queries) on any text. The first byte
// picks the format (the benchmark's CSV or 24 numbers a line); every query read has its line,
// lines increase, and every coordinate is finite; an error names a line within the text.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "contain/io/ccd_queries.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  if (size == 0) return 0;
  const auto format = data[0] % 2 == 0 ? io::CcdFileFormat::benchmark : io::CcdFileFormat::numbers;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  auto read = io::parse_ccd_queries(text, "fuzz", format);
  if (!read) {
    FUZZ_CHECK(!read.error().message.empty());
    const auto lines = 1 + std::count(text.begin(), text.end(), '\n');
    FUZZ_CHECK(read.error().line <= lines);
    return 0;
  }
  FUZZ_CHECK(read->queries.size() == read->lines.size());
  FUZZ_CHECK(read->queries.size() == read->expected.size());
  for (std::size_t i = 0; i < read->queries.size(); ++i) {
    FUZZ_CHECK(read->lines[i] >= 1 && (i == 0 || read->lines[i] > read->lines[i - 1]));
    for (const Vec3& p : read->queries[i])
      FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }
  return 0;
}
