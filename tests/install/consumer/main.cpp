// Uses the installed headers and libraries the way a user's program would.
#include <contain/contain.h>
#include <contain/io/wkt.h>

#include <cstdio>

int main() {
  auto region = contain::io::parse_wkt("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "inline");
  if (!region) return 1;
  const contain::inside::PolygonIndex index(*region);
  const contain::Location where = index.locate({2, 1});
  std::printf("%s\n", contain::to_string(where).data());
  return where == contain::Location::boundary ? 0 : 1;
}
