// Whole-process peer of `contain inside --polygon P.wkt --points PTS --threads 1`: GEOS reads the
// WKT, prepares it, and answers each point with GEOSPreparedContains_r: in or out, no "on" (a
// smaller task than contain's: telling the boundary apart with GEOSPreparedIntersects_r for every
// point not contained made the 10k-vertex star's run 14x slower, 12.5 s of CPU). The points are
// read by the fastest simple reader (peer_points.h). Kernel times on stderr.
//   geos_inside POLYGON.wkt POINTS.txt > answers.txt

#include <geos_c.h>

#include <cstdio>
#include <string>
#include <vector>

#include "bench/peers/peer_driver.h"
#include "bench/peers/peer_points.h"

int main(int argc, char** argv) {
  using namespace contain::bench;
  if (argc != 3) {
    std::fprintf(stderr, "usage: geos_inside POLYGON.wkt POINTS.txt\n");
    return 2;
  }
  GEOSContextHandle_t ctx = GEOS_init_r();
  const std::string wkt = read_whole_file(argv[1]);
  GEOSWKTReader* reader = GEOSWKTReader_create_r(ctx);
  GEOSGeometry* polygon = GEOSWKTReader_read_r(ctx, reader, wkt.c_str());
  if (polygon == nullptr) {
    std::fprintf(stderr, "%s: not WKT GEOS reads\n", argv[1]);
    return 3;
  }
  const std::vector<double> xy = read_numbers(argv[2]);
  const KernelClock clock;
  const GEOSPreparedGeometry* prepared = GEOSPrepare_r(ctx, polygon);
  std::vector<signed char> answers(xy.size() / 2);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    GEOSGeometry* point = GEOSGeom_createPointFromXY_r(ctx, xy[2 * i], xy[2 * i + 1]);
    answers[i] = GEOSPreparedContains_r(ctx, prepared, point) == 1 ? 1 : -1;
    GEOSGeom_destroy_r(ctx, point);
  }
  clock.report("prepare + query");
  write_answers(answers);
  GEOSPreparedGeom_destroy_r(ctx, prepared);
  GEOSGeom_destroy_r(ctx, polygon);
  GEOSWKTReader_destroy_r(ctx, reader);
  GEOS_finish_r(ctx);
  return 0;
}
