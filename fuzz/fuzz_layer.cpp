// libFuzzer target: the layer readers (io::parse_geojson_layer, io::parse_wkt_layer) on any
// text, and the layer prepared from what they read. A layer read has one id per region and
// regions as the region readers give them; RegionLayer answers every region exactly as that
// region alone (PolygonIndex under the same fill rule), one point at a time and in a batch.
#include <span>
#include <vector>

#include "contain/inside/polygon_index.h"
#include "contain/inside/region_layer.h"
#include "contain/io/layer_io.h"
#include "region_reader_fuzz.h"

namespace {

using namespace contain;

// Small layers only: every region is also prepared alone, as the reference.
constexpr std::size_t kMaxRings = 32;

void check_layer(const io::Layer& layer) {
  FUZZ_CHECK(layer.ids.size() == layer.regions.size());
  std::size_t rings = 0;
  for (const MultiPolygon& region : layer.regions)
    rings += region.all_rings().size();
  if (rings > kMaxRings) return;
  for (const MultiPolygon& region : layer.regions)
    fuzz::check_region(region);

  const inside::RegionLayer index(layer.regions);
  FUZZ_CHECK(index.size() == layer.regions.size());
  std::vector<inside::PolygonIndex> alone;
  for (const MultiPolygon& region : layer.regions)
    alone.emplace_back(region);

  // Queries: every ring's first vertex (on that region's boundary, maybe inside another) and
  // the midpoint of its first edge.
  std::vector<Vec2> points;
  for (const MultiPolygon& region : layer.regions) {
    for (const Ring& ring : region.all_rings()) {
      points.push_back(ring[0]);
      points.push_back({ring[0].x / 2 + ring[1].x / 2, ring[0].y / 2 + ring[1].y / 2});
    }
  }
  const inside::HolderTable table = index.locate(std::span<const Vec2>(points));
  FUZZ_CHECK(table.points() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<inside::Holder> expected;
    for (std::size_t r = 0; r < alone.size(); ++r) {
      const Location where = alone[r].locate(points[i]);
      if (where != Location::outside) expected.push_back({static_cast<std::int32_t>(r), where});
    }
    const std::vector<inside::Holder> one = index.locate(points[i]);
    FUZZ_CHECK(one == expected);
    const auto row = table.of(i);
    FUZZ_CHECK(std::vector<inside::Holder>(row.begin(), row.end()) == expected);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const bool json : {true, false}) {
    auto layer = json ? io::parse_geojson_layer(text, "fuzz") : io::parse_wkt_layer(text, "fuzz");
    if (!layer) {
      FUZZ_CHECK(!layer.error().message.empty());
      continue;
    }
    check_layer(*layer);
  }
  return 0;
}
