#pragma once
// What the whole-process peer drivers of bench/peers/ share: their kernel clock (printed on
// stderr, so that a run gives both the whole-process and the kernel figure), the boolean
// operation and slicing options of their command lines, and the planes of a slice run.

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace contain::bench {

// Wall and thread CPU time from construction: the peers run on one thread, and the machine is
// shared, so both are printed (the CPU time does not count time the core was lent to others).
class KernelClock {
 public:
  KernelClock() : wall_(now(CLOCK_MONOTONIC)), cpu_(now(CLOCK_THREAD_CPUTIME_ID)) {}

  // "kernel <what>: W ms wall, C ms cpu" on stderr.
  void report(const char* what) const {
    std::fprintf(stderr, "kernel %s: %.3f ms wall, %.3f ms cpu\n", what,
                 now(CLOCK_MONOTONIC) - wall_, now(CLOCK_THREAD_CPUTIME_ID) - cpu_);
  }

 private:
  static double now(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
  }

  double wall_;
  double cpu_;
};

enum class BooleanOp { union_, intersection, difference };

[[nodiscard]] inline std::optional<BooleanOp> boolean_op_named(std::string_view name) {
  if (name == "union") return BooleanOp::union_;
  if (name == "intersection") return BooleanOp::intersection;
  if (name == "difference") return BooleanOp::difference;
  return std::nullopt;
}

// `A.off B.off --op union|intersection|difference OUT.off`.
struct BooleanArgs {
  std::string a;
  std::string b;
  BooleanOp op = BooleanOp::union_;
  std::string out;
};

[[nodiscard]] inline std::optional<BooleanArgs> parse_boolean_args(int argc, char** argv) {
  if (argc != 6 || std::string_view(argv[3]) != "--op") return std::nullopt;
  const std::optional<BooleanOp> op = boolean_op_named(argv[4]);
  if (!op) return std::nullopt;
  return BooleanArgs{argv[1], argv[2], *op, argv[5]};
}

// `MESH.off [--planes N] [--axis x|y|z]` (defaults: 100 planes, z); axis as 0, 1, 2.
struct SliceArgs {
  std::string mesh;
  int planes = 100;
  int axis = 2;
};

[[nodiscard]] inline std::optional<SliceArgs> parse_slice_args(int argc, char** argv) {
  if (argc < 2 || argc % 2 != 0) return std::nullopt;
  SliceArgs args{argv[1]};
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string_view option = argv[i];
    const std::string_view value = argv[i + 1];
    if (option == "--planes") {
      args.planes = std::atoi(argv[i + 1]);
      if (args.planes <= 0) return std::nullopt;
    } else if (option == "--axis" && value.size() == 1 && value[0] >= 'x' && value[0] <= 'z') {
      args.axis = value[0] - 'x';
    } else {
      return std::nullopt;
    }
  }
  return args;
}

// `count` planes evenly spaced strictly inside [lo, hi]: the middles of `count` equal layers, so
// no plane passes through the extreme vertices (every driver and contain cut at the same values).
[[nodiscard]] inline std::vector<double> plane_values(double lo, double hi, int count) {
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i)
    values.push_back(lo + (hi - lo) * (i + 0.5) / count);
  return values;
}

}  // namespace contain::bench
