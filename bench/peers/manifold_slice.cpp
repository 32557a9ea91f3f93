// Manifold's Slice as its users call it, as a whole process for the slicing benchmark (issue
// 26): read an OFF file, cut it by N evenly spaced planes perpendicular to an axis (the middles
// of N equal layers of its extent, as every driver and contain), print each plane's region.
// Usage: manifold_slice MESH.off [--planes N] [--axis x|y|z]      (defaults: 100, z)
// Prints per plane: the value, the number of contours and the area of the region (the contours
// through CrossSection, Manifold's positive fill rule). One thread. On stderr, the kernel times:
// building Manifold's solid from the mesh, and the N Slice calls (raw contours); the regions'
// CrossSection and areas, reading and printing are outside them.

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include <manifold/cross_section.h>

#include "bench/peers/manifold_mesh.h"
#include "bench/peers/peer_driver.h"

using namespace contain;
using namespace contain::bench;

int main(int argc, char** argv) {
  const std::optional<SliceArgs> args = parse_slice_args(argc, argv);
  if (!args) {
    std::fprintf(stderr, "usage: manifold_slice MESH.off [--planes N] [--axis x|y|z]\n");
    return 2;
  }
  const std::optional<manifold::Manifold> solid = load_solid(args->mesh, args->axis);
  if (!solid) return 3;

  const manifold::Box box = solid->BoundingBox();
  const std::vector<double> values = plane_values(box.min.z, box.max.z, args->planes);
  std::vector<manifold::Polygons> sections;
  sections.reserve(values.size());
  const KernelClock slice_clock;
  for (double value : values)
    sections.push_back(solid->Slice(value));
  slice_clock.report("slice");

  for (std::size_t i = 0; i < values.size(); ++i) {
    const manifold::CrossSection region(sections[i]);
    std::printf("%.17g %zu %.17g\n", values[i], region.NumContour(), region.Area());
  }
  return 0;
}
