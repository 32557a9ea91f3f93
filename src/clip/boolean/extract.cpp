// The result region of the arrangement (rule clip-rings in docs/robustness.md): a half-edge is a
// boundary of the result when the face on its left is kept and the one on its right is not.
// Boundary chains take at each vertex the first boundary half-edge clockwise from the reverse of
// the arriving one (the tightest turn, which keeps two kept sectors meeting at a vertex apart); a
// chain that revisits a vertex is split there, so every ring is simple; rings copy the inner
// points of their runs. Counter-clockwise rings are shells, clockwise ones holes, and a hole
// joins the shell whose kept faces are connected to its own across non-boundary edges.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "clip/boolean/arrangement.h"
#include "clip/boolean/graph_helpers.h"
#include "contain/core/union_find.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::detail {

using graph::kNone;
using graph::lex_less;

struct Arrangement::Loop {
  Ring ring;
  std::uint32_t region;
  bool shell;
  std::uint32_t key;  // earliest input segment starting at one of its points, else kNone
};

MultiPolygon Arrangement::extract(const std::function<bool(int, int)>& keep) const {
  const std::size_t nf = face_a_.size();
  std::vector<char> in(nf);
  for (std::size_t f = 0; f < nf; ++f)
    in[f] = keep(face_a_[f], face_b_[f]) ? 1 : 0;
  const std::vector<std::uint32_t> region = regions(in);
  std::vector<Loop> loops = trace_rings(in, region);
  return assemble(loops, nf);
}

std::vector<std::uint32_t> Arrangement::regions(const std::vector<char>& in) const {
  // Regions: kept faces connected across kept-kept edges (and a component's outer face with
  // the face of the component around it).
  const std::size_t nf = in.size();
  const std::size_t nh = face_.size();
  UnionFind<std::uint32_t> region(nf);
  for (const auto& [f, g] : face_links_) {
    if (in[f]) region.unite(static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(g));
  }
  for (std::size_t h = 0; h < nh; h += 2) {
    if (in[face_[h]] && in[face_[h + 1]]) {
      region.unite(static_cast<std::uint32_t>(face_[h]), static_cast<std::uint32_t>(face_[h + 1]));
    }
  }
  std::vector<std::uint32_t> root(nf);
  for (std::size_t f = 0; f < nf; ++f)
    root[f] = region.find(static_cast<std::uint32_t>(f));
  return root;
}

Arrangement::Loop Arrangement::make_loop(std::span<const std::int32_t> hs,
                                         const std::vector<std::uint32_t>& region) const {
  const std::vector<std::uint32_t>& first = noded_.first;
  Loop loop;
  loop.region = region[static_cast<std::size_t>(face_[hs[0]])];
  Ring& ring = loop.ring;
  std::uint32_t key = kNone;
  std::size_t k = 0;
  for (const std::int32_t h : hs) {
    const std::uint32_t t = tail(h);
    if (origin_[t] < key) {
      key = origin_[t];
      k = ring.size();
    }
    const Edge& e = edge_[h >> 1];
    const std::size_t before = ring.size();
    append_points(h, ring);
    if (e.i0 == kPlain) continue;
    // Points inside a run are joints, each the start of the segment after the one that ends
    // there: the earliest is the end of the segment holding i0, first in the run's direction.
    if (ring.size() == before + 1) continue;
    const auto seg = static_cast<std::uint32_t>(std::upper_bound(first.begin(), first.end(), e.i0) -
                                                first.begin());
    if (seg < key) {
      key = seg;
      k = (h & 1) ? ring.size() - 1 : before + 1;
    }
  }
  // The lowest point is convex: its turn gives the orientation.
  const std::size_t n = ring.size();
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (lex_less(ring[i], ring[m])) m = i;
  }
  loop.shell =
      predicates::orient2d(ring[(m + n - 1) % n], ring[m], ring[(m + 1) % n]) == Sign::positive;
  loop.key = key;
  if (key == kNone) k = m;
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(k), ring.end());
  return loop;
}

std::vector<Arrangement::Loop> Arrangement::trace_rings(
    const std::vector<char>& in, const std::vector<std::uint32_t>& region) const {
  const std::size_t nh = face_.size();
  auto boundary = [&](std::int32_t h) { return in[face_[h]] && !in[face_[h ^ 1]]; };
  std::vector<Loop> loops;
  std::vector<char> used(nh, 0);
  std::vector<std::int32_t> stack;
  std::vector<std::int32_t> mark(vertex_.size(), -1);
  for (std::size_t h0 = 0; h0 < nh; ++h0) {
    const auto start = static_cast<std::int32_t>(h0);
    if (used[h0] || !boundary(start)) continue;
    stack.clear();
    std::int32_t h = start;
    do {
      used[h] = 1;
      const std::uint32_t x = tail(h);
      if (mark[x] >= 0) {
        const auto from = static_cast<std::size_t>(mark[x]);
        loops.push_back(make_loop(std::span<const std::int32_t>(stack).subspan(from), region));
        for (std::size_t i = from; i < stack.size(); ++i)
          mark[tail(stack[i])] = -1;
        stack.resize(from);
      }
      mark[x] = static_cast<std::int32_t>(stack.size());
      stack.push_back(h);
      // Next boundary half-edge: the first clockwise from the reverse of h.
      const std::uint32_t v = head(h);
      const std::uint32_t b = out_first_[v], deg = out_first_[v + 1] - b;
      std::uint32_t p = pos_[h ^ 1];
      std::int32_t g = -1;
      for (std::uint32_t i = 0; i < deg; ++i) {
        p = p == 0 ? deg - 1 : p - 1;
        if (boundary(out_[b + p])) {
          g = out_[b + p];
          break;
        }
      }
      h = g;
    } while (h != start && h >= 0);
    loops.push_back(make_loop(stack, region));
    for (std::int32_t s : stack)
      mark[tail(s)] = -1;
  }
  return loops;
}

MultiPolygon Arrangement::assemble(std::vector<Loop>& loops, std::size_t faces) {
  // Polygons: one shell per region, its holes after it.
  std::vector<std::int32_t> shell_of(faces, -1);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (loops[i].shell) shell_of[loops[i].region] = static_cast<std::int32_t>(i);
  }
  std::vector<std::size_t> order(loops.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // By the earliest input vertex, then the first point: ties keep the order found.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) {
    if (loops[l].key != loops[r].key) return loops[l].key < loops[r].key;
    return lex_less(loops[l].ring.front(), loops[r].ring.front());
  });
  MultiPolygon out;
  std::vector<std::int32_t> polygon_of(loops.size(), -1);
  for (std::size_t i : order) {
    if (!loops[i].shell) continue;
    polygon_of[i] = static_cast<std::int32_t>(out.polygons.size());
    out.polygons.push_back(Polygon{{std::move(loops[i].ring)}});
  }
  for (std::size_t i : order) {
    if (loops[i].shell) continue;
    const std::int32_t s = shell_of[loops[i].region];
    if (s < 0) continue;  // cannot happen for a bounded kept region
    out.polygons[polygon_of[s]].rings.push_back(std::move(loops[i].ring));
  }
  return out;
}

}  // namespace contain::clip::detail
