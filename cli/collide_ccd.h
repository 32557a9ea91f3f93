#pragma once
// contain collide --ccd ... and contain collide A B --from-b/--to-b/--motions: continuous
// collision of primitives and of moving meshes (shared/spec/cli.md, "Continuous collision").

#include <string>

namespace contain::cli {

struct CcdCliOptions {
  std::string kind;     // --ccd: vertex-face | edge-edge
  std::string queries;  // --queries FILE
  std::string a, b;
  std::string transform_a, transform_b;
  std::string from_a, to_a, from_b, to_b, motions;
  bool json = false;
  int threads = 0;
  bool quiet = false;
  std::string out;
};

/// `--ccd KIND --queries FILE`: one line per query.
int run_ccd_queries(const CcdCliOptions& o);

/// True when any option of a moving mesh query is set (--from-X, --to-X, --motions).
[[nodiscard]] bool has_motion(const CcdCliOptions& o);

/// `A B --from-X/--to-X` or `--motions FILE`: one line per motion of B.
int run_moving_meshes(const CcdCliOptions& o);

}  // namespace contain::cli
