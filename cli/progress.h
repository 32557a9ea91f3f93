#pragma once
// Progress on stderr for long batch runs: shown only when stderr is a terminal, the run has
// taken over a second, and --quiet was not given (the contract's general rules).

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string_view>

namespace contain::cli {

class Progress {
 public:
  /// `what` names the items ("points", "poses"); `enabled` is false for --quiet or when stderr
  /// is not a terminal.
  Progress(std::string_view what, std::size_t total, bool enabled)
      : what_(what), total_(total), enabled_(enabled) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() {
    if (shown_) std::fputs("\r\033[K", stderr);  // leave the terminal line clean
  }

  /// Reports that `done` items are finished.
  void update(std::size_t done) {
    if (!enabled_ || total_ == 0) return;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    if (elapsed < std::chrono::seconds(1)) return;
    shown_ = true;
    std::fprintf(stderr, "\rcontain: %3zu%% (%zu of %zu %.*s)", done * 100 / total_, done, total_,
                 static_cast<int>(what_.size()), what_.data());
    std::fflush(stderr);
  }

  /// Reports progress by share (0 to 1) when the total is not known in items: `done` items so far.
  void update_share(double share, std::size_t done) {
    if (!enabled_) return;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    if (elapsed < std::chrono::seconds(1)) return;
    shown_ = true;
    std::fprintf(stderr, "\rcontain: %3d%% (%zu %.*s)", static_cast<int>(100 * share), done,
                 static_cast<int>(what_.size()), what_.data());
    std::fflush(stderr);
  }

  /// Runs `body(begin, end)` over [0, total) in chunks of about 1% (at least `min_chunk` items),
  /// with an update after each: the library's batch calls stay whole within a chunk.
  template <class Body>
  void run(Body&& body, std::size_t min_chunk = 4096) {
    const std::size_t chunk = enabled_ ? std::max<std::size_t>(min_chunk, total_ / 100) : total_;
    for (std::size_t begin = 0; begin < total_; begin += chunk) {
      const std::size_t end = std::min(total_, begin + chunk);
      body(begin, end);
      update(end);
    }
  }

 private:
  std::string_view what_;
  std::size_t total_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace contain::cli
