// Stage 4 of slicing: planes in increasing order, the triangles they cross, and each section
// from its two curves.

#include <algorithm>

#include "clip/slice/stages.h"
#include "contain/clip/polygon_boolean.h"

namespace contain::clip::slice {

Section section_at(const SweepMesh& mesh, std::span<const std::int32_t> active, double c,
                   SweepScratch& scratch) {
  PlaneCurves& curves = scratch.curves;
  crossing_segments(mesh, active, c, scratch.memo, curves);
  Section out;
  out.value = c;
  if (!curves.touches) {
    // No vertex on the plane: both sides have the same curve, whose positive winding numbers
    // are the section (rule slice-two-sides).
    std::vector<std::vector<std::int32_t>> under;
    std::vector<Ring> above = chain_rings(curves.above, &under, scratch.chain);
    if (simple_section(above, under, curves.above.size(), out)) return out;
    out.region = polygon_boolean(above, {}, {.op = Op::union_, .fill = Fill::positive});
    out.triangles = edge_triangles(out.region, curves.above);
    return out;
  }
  const std::vector<Ring> above = chain_rings(curves.above, nullptr, scratch.chain);
  const std::vector<Ring> below = chain_rings(curves.below, nullptr, scratch.chain);
  out.region = polygon_boolean(above, below, {.op = Op::intersection, .fill = Fill::positive});
  std::vector<CrossingSegment>& both = scratch.both;
  both.assign(curves.above.begin(), curves.above.end());
  both.insert(both.end(), curves.below.begin(), curves.below.end());
  out.triangles = edge_triangles(out.region, both);
  return out;
}

void sweep(const SweepMesh& mesh, std::span<const double> values,
           std::span<const std::size_t> order, std::size_t begin, std::size_t end,
           std::span<Section> out) {
  SweepScratch scratch;
  std::vector<std::int32_t>& active = scratch.active;
  std::size_t next = 0;  // the first triangle of by_low not yet active
  for (std::size_t i = begin; i < end; ++i) {
    const double c = values[order[i]];
    for (; next < mesh.by_low.size() && mesh.low[static_cast<std::size_t>(mesh.by_low[next])] <= c;
         ++next) {
      active.push_back(mesh.by_low[next]);
    }
    // The planes increase: a triangle wholly below this one stays out of every later one. The
    // order of `active` then depends on where this thread's run of planes began, but no answer
    // depends on it (chain_rings, edge_triangles).
    std::erase_if(active,
                  [&](std::int32_t t) { return mesh.high[static_cast<std::size_t>(t)] < c; });
    out[order[i]] = section_at(mesh, active, c, scratch);
  }
}

}  // namespace contain::clip::slice
