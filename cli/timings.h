#pragma once
// --timings: where a verb's wall time went, printed on stderr after it ran (docs/scale.md,
// "Where the time goes"). The verb says which phase it enters; every moment from the verb's start
// to its end counts in exactly one phase, so the phases add up to the total.

#include <CLI/CLI.hpp>

#include <array>
#include <chrono>
#include <cstdint>

namespace contain::cli {

enum class Phase : std::uint8_t {
  read,     // reading and parsing the inputs
  prepare,  // building indexes, checking the inputs (a mesh's self-crossing check)
  query,    // answering
  write,    // formatting and writing the answers
};

class Timings {
 public:
  /// Starts the clock in Phase::read; until then `enter` does nothing (no --timings).
  void start();
  /// From now on, time counts in `phase`.
  void enter(Phase phase);
  /// "contain: timings: PHASE MS ms" for read, prepare, query, write and total, on stderr.
  void print();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_ = false;
  Phase phase_ = Phase::read;
  Clock::time_point start_{};
  Clock::time_point since_{};
  std::array<Clock::duration, 4> spent_{};
};

/// The process's one clock.
[[nodiscard]] Timings& timings();

/// Shorthand: `timings().enter(phase)`.
inline void enter_phase(Phase phase) {
  timings().enter(phase);
}

/// `--timings` on a verb.
void add_timings_option(CLI::App& app, bool& timings);

}  // namespace contain::cli
