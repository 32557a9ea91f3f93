// Stage 4 of slicing: planes in increasing order, the triangles they cross, and each section
// from its two curves.

#include <algorithm>

#include "clip/slice/stages.h"
#include "contain/clip/polygon_boolean.h"

namespace contain::clip::slice {

namespace {

// The section of a plane through no vertex, from its one curve (rule slice-two-sides: both
// sides have it), whose positive winding numbers are the section.
Section one_curve_section(std::vector<Ring> rings, std::vector<std::vector<std::int32_t>> under,
                          std::span<const CrossingSegment> segments, double c) {
  Section out;
  out.value = c;
  if (simple_section(rings, under, segments.size(), out)) return out;
  if (nested_section(rings, under, segments.size(), out)) return out;
  out.region = polygon_boolean(rings, {}, {.op = Op::union_, .fill = Fill::positive});
  out.triangles = edge_triangles(out.region, segments);
  return out;
}

}  // namespace

Section section_at(const SweepMesh& mesh, std::span<const std::int32_t> active, double c,
                   SweepScratch& scratch) {
  PlaneCurves& curves = scratch.curves;
  ChainScratch& chain = scratch.chain;
  if (walk_curve(mesh, active, c, scratch.walk, curves.above, chain.cycles)) {
    chain.walk.resize(curves.above.size());
    for (std::size_t i = 0; i < chain.walk.size(); ++i)
      chain.walk[i] = static_cast<std::int32_t>(i);
    std::vector<Ring> rings;
    std::vector<std::vector<std::int32_t>> under;
    write_cycles(curves.above, chain.walk, chain.cycles, rings, &under, chain.rotated);
    return one_curve_section(std::move(rings), std::move(under), curves.above, c);
  }
  crossing_segments(mesh, active, c, scratch.memo, curves);
  if (!curves.touches) {
    std::vector<std::vector<std::int32_t>> under;
    std::vector<Ring> rings = chain_rings(curves.above, &under, chain);
    return one_curve_section(std::move(rings), std::move(under), curves.above, c);
  }
  Section out;
  out.value = c;
  const std::vector<Ring> above = chain_rings(curves.above, nullptr, chain);
  const std::vector<Ring> below = chain_rings(curves.below, nullptr, chain);
  out.region = polygon_boolean(above, below, {.op = Op::intersection, .fill = Fill::positive});
  std::vector<CrossingSegment>& both = scratch.both;
  both.assign(curves.above.begin(), curves.above.end());
  both.insert(both.end(), curves.below.begin(), curves.below.end());
  out.triangles = edge_triangles(out.region, both);
  return out;
}

void carry_active(const SweepMesh& mesh, const SweepStarts& starts, std::span<const double> sorted,
                  std::size_t from, std::size_t to, std::vector<std::size_t>& positions) {
  if (to >= sorted.size()) {
    positions.clear();
    return;
  }
  const double c = sorted[to];
  const auto reaches = [&](std::size_t p) {
    return mesh.high(static_cast<std::size_t>(starts.triangles[p])) >= c;
  };
  std::erase_if(positions, [&](std::size_t p) { return !reaches(p); });
  for (std::size_t p = starts.start[from]; p < starts.start[to]; ++p) {
    if (reaches(p)) positions.push_back(p);
  }
}

void sweep(const SweepMesh& mesh, const SweepStarts& starts, std::span<const double> sorted,
           std::span<const std::size_t> order, std::size_t begin, std::size_t end,
           std::size_t first, std::span<const std::size_t> carried, std::span<Section> out) {
  SweepScratch scratch;
  std::vector<std::int32_t>& active = scratch.active;
  const auto entering = [&](std::size_t i) {
    return std::span<const std::int32_t>(starts.triangles)
        .subspan(starts.start[i], starts.start[i + 1] - starts.start[i]);
  };
  // A run of planes starting past the first takes the triangles that reached an earlier plane
  // and still reach this one, in the order a scan of them all would give.
  // Each active triangle's top beside it, read from the mesh once, when it enters.
  std::vector<double>& high = scratch.active_high;
  const auto enter = [&](std::int32_t t) {
    active.push_back(t);
    high.push_back(mesh.high(static_cast<std::size_t>(t)));
  };
  active.reserve(carried.size());
  high.reserve(carried.size());
  for (const std::size_t p : carried)
    enter(starts.triangles[p]);
  for (std::size_t i = begin; i < end; ++i) {
    const double c = sorted[i];
    for (const std::int32_t t : entering(i))
      enter(t);
    // The planes increase: a triangle wholly below this one stays out of every later one. The
    // order of `active` then depends on where this thread's run of planes began, but no answer
    // depends on it (walk_curve, chain_rings, edge_triangles).
    std::size_t kept = 0;
    for (std::size_t k = 0; k < active.size(); ++k) {
      if (high[k] < c) continue;
      active[kept] = active[k];
      high[kept] = high[k];
      ++kept;
    }
    active.resize(kept);
    high.resize(kept);
    if (order[i] < first || order[i] - first >= out.size()) continue;
    out[order[i] - first] = section_at(mesh, active, c, scratch);
  }
}

}  // namespace contain::clip::slice
