#pragma once
// The batch form shared by RegionLayer and SolidScene: points in fixed blocks, blocks handed to
// worker threads as they free up, each block's holders gathered on its own, then laid end to
// end in block order. The blocks do not depend on the thread count, so neither do the answers
// nor their order.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <span>
#include <thread>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/core/parallel.h"
#include "contain/core/sort_few.h"
#include "contain/inside/holders.h"

namespace contain::inside::detail {

// `append(point, out)` appends the holders of one point to `out`, shape numbers ascending.
template <class Point, class Append>
HolderTable holder_table(std::span<const Point> points, const BatchOptions& options,
                         Append&& append) {
  constexpr std::size_t kBlock = std::size_t{1} << 13;
  const std::size_t n = points.size();
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  HolderTable table;
  table.offsets.assign(n + 1, 0);
  std::vector<std::vector<Holder>> found(blocks);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t b = next.fetch_add(1); b < blocks; b = next.fetch_add(1)) {
      const std::size_t begin = b * kBlock, end = std::min(n, begin + kBlock);
      std::vector<Holder>& out = found[b];
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t before = out.size();
        append(points[i], out);
        table.offsets[i + 1] = out.size() - before;
      }
    }
  };
  const int threads = std::min<int>(thread_count(options, n), static_cast<int>(blocks));
  if (threads <= 1) {
    work();
  } else {
    std::vector<std::thread> workers;
    workers.reserve(static_cast<std::size_t>(threads) - 1);
    for (int t = 1; t < threads; ++t)
      workers.emplace_back(work);
    work();
    for (std::thread& w : workers)
      w.join();
  }
  for (std::size_t i = 0; i < n; ++i)
    table.offsets[i + 1] += table.offsets[i];
  table.holders.resize(table.offsets[n]);
  for (std::size_t b = 0; b < blocks; ++b) {
    std::copy(found[b].begin(), found[b].end(),
              table.holders.begin() + static_cast<std::ptrdiff_t>(table.offsets[b * kBlock]));
    std::vector<Holder>().swap(found[b]);
  }
  return table;
}

// Appends the holders of `point` to `out`: the items of `tree` in leaves whose boxes
// `meets(box)` accepts are asked `indexes[item].locate(point)`; shape numbers ascending.
template <class Indexes, class Point, class Meets>
void append_holders(const bvh::Bvh& tree, const Indexes& indexes, Point point, Meets&& meets,
                    std::vector<Holder>& out) {
  const std::size_t first = out.size();
  (void)tree.traverse([&](const bvh::Node& node, std::int32_t) { return meets(node.box); },
                      [&](std::int32_t k) {
                        const Location where = indexes[static_cast<std::size_t>(k)].locate(point);
                        if (where != Location::outside) out.push_back({k, where});
                        return bvh::Visit::proceed;
                      });
  // A traversal finds a point's holders in tree order: by shape number (usually a few).
  sort_few(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), 32,
           [](const Holder& a, const Holder& b) { return a.shape < b.shape; });
}

}  // namespace contain::inside::detail
