#pragma once
/// \file
/// Batch work over all cores with std::thread: the library core needs no thread pool library.

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <span>
#include <thread>
#include <utility>
#include <vector>

namespace contain {

/// How a batch call spreads its work. `threads == 0` means every hardware thread.
struct BatchOptions {
  int threads = 0;
};

/// The number of threads a batch of `count` items uses: never more than the items (in chunks of
/// at least `min_chunk`), never fewer than one.
[[nodiscard]] inline int thread_count(const BatchOptions& options, std::size_t count,
                                      std::size_t min_chunk = 4096) {
  int wanted =
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  wanted = std::max(wanted, 1);
  const std::size_t by_size = std::max<std::size_t>(1, count / std::max<std::size_t>(1, min_chunk));
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(wanted), by_size));
}

/// Calls `body(begin, end)` on disjoint contiguous ranges covering [0, count), on up to
/// `thread_count` threads. Each range is processed by one thread, so results written per index
/// are deterministic whatever the thread count. `body` must not throw.
template <class Body>
void parallel_for(std::size_t count, const BatchOptions& options, std::size_t min_chunk,
                  Body&& body) {
  const int threads = thread_count(options, count, min_chunk);
  if (threads <= 1) {
    body(std::size_t{0}, count);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(static_cast<std::size_t>(threads) - 1);
  const std::size_t chunk =
      (count + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
  for (int t = 1; t < threads; ++t) {
    const std::size_t begin = std::min(count, chunk * static_cast<std::size_t>(t));
    const std::size_t end = std::min(count, begin + chunk);
    workers.emplace_back([&body, begin, end] { body(begin, end); });
  }
  body(std::size_t{0}, std::min(count, chunk));
  for (std::thread& w : workers)
    w.join();
}

/// parallel_for in chunks of at least 4096 items (cheap items: thread start-up stays small).
template <class Body>
void parallel_for(std::size_t count, const BatchOptions& options, Body&& body) {
  parallel_for(count, options, std::size_t{4096}, std::forward<Body>(body));
}

/// The one size rule of batch calls `f(inputs, out, ..., BatchOptions)` (docs/architecture.md,
/// "Naming", rule 3): `out` has the inputs' size, and a different size is a programming error,
/// asserted. A build without assertions answers the common prefix, so that nothing is written
/// past `out` either way. Returns the number of items to answer.
[[nodiscard]] inline std::size_t batch_size(std::size_t inputs, std::size_t out) {
  assert(inputs == out && "a batch call's out span must have its inputs' size");
  return std::min(inputs, out);
}

/// `out[i] = answer(inputs[i])` for every i (`batch_size`'s rule), in ranges of at least
/// `min_chunk` items on up to `thread_count` threads: each answer is the same whatever the thread
/// count. The loop of every batch call whose items need no shared state. `answer` must not throw.
template <class In, class Out, class Answer>
void batch_map(std::span<In> inputs, std::span<Out> out, const BatchOptions& options,
               std::size_t min_chunk, Answer&& answer) {
  parallel_for(batch_size(inputs.size(), out.size()), options, min_chunk,
               [&](std::size_t begin, std::size_t end) {
                 for (std::size_t i = begin; i < end; ++i)
                   out[i] = answer(inputs[i]);
               });
}

}  // namespace contain
