// Manifold's Project (the shadow of a solid) as its users call it, as a whole process for the
// slicing benchmark (issue 26): read an OFF file, project it along an axis, print the shadow's
// area and contour count.
// Usage: manifold_project MESH.off [--axis x|y|z]      (default z)
// Project returns overlapping outlines; the shadow is their union through CrossSection, as
// Manifold's README says to use it. One thread. On stderr, the kernel times: building
// Manifold's solid, Project, and the CrossSection union; reading and printing are outside them.

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string_view>

#include <manifold/cross_section.h>

#include "bench/peers/manifold_mesh.h"
#include "bench/peers/peer_driver.h"

using namespace contain;
using namespace contain::bench;

int main(int argc, char** argv) {
  const std::optional<SliceArgs> args = parse_slice_args(argc, argv);
  if (!args || std::find(argv, argv + argc, std::string_view("--planes")) != argv + argc) {
    std::fprintf(stderr, "usage: manifold_project MESH.off [--axis x|y|z]\n");
    return 2;
  }
  const std::optional<manifold::Manifold> solid = load_solid(args->mesh, args->axis);
  if (!solid) return 3;

  const KernelClock project_clock;
  const manifold::Polygons outlines = solid->Project();
  project_clock.report("project");
  const KernelClock union_clock;
  const manifold::CrossSection shadow(outlines);
  const double area = shadow.Area();
  union_clock.report("union");

  std::printf("%zu outlines, shadow %zu contours, area %.17g\n", outlines.size(),
              shadow.NumContour(), area);
  return 0;
}
