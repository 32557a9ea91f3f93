#include "timings.h"

#include <cstdio>

namespace contain::cli {

void Timings::start() {
  enabled_ = true;
  phase_ = Phase::read;
  start_ = since_ = Clock::now();
  spent_.fill(Clock::duration::zero());
}

void Timings::enter(Phase phase) {
  if (!enabled_ || phase == phase_) return;
  const Clock::time_point now = Clock::now();
  spent_[static_cast<std::size_t>(phase_)] += now - since_;
  since_ = now;
  phase_ = phase;
}

void Timings::print() {
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  spent_[static_cast<std::size_t>(phase_)] += now - since_;
  since_ = now;
  const auto ms = [](Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
  };
  constexpr std::array<const char*, 4> names{"read", "prepare", "query", "write"};
  for (std::size_t k = 0; k < names.size(); ++k)
    std::fprintf(stderr, "contain: timings: %s %.3f ms\n", names[k], ms(spent_[k]));
  std::fprintf(stderr, "contain: timings: total %.3f ms\n", ms(now - start_));
}

Timings& timings() {
  static Timings clock;
  return clock;
}

void add_timings_option(CLI::App& app, bool& timings) {
  app.add_flag("--timings", timings,
               "print on stderr where the wall time went: 'contain: timings: PHASE MS ms' for "
               "read, prepare, query, write and total");
}

}  // namespace contain::cli
