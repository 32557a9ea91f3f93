#pragma once
// The scenes of `contain demo`: each runs one capability on built-in geometry, prints a few
// report lines and writes its pictures (and 3D results) into the demo folder.

#include <chrono>
#include <filesystem>
#include <span>
#include <string>

#include "contain/core/location.h"
#include "contain/core/result.h"
#include "contain/io/svg.h"
#include "contain/values/transform.h"

namespace contain::cli::demo {

struct Context {
  std::filesystem::path dir;
  int threads = 0;
};

class Stopwatch {
 public:
  [[nodiscard]] double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct Counts {
  std::size_t inside = 0, boundary = 0, outside = 0;
};
[[nodiscard]] Counts count(std::span<const Location> locations);

/// The in / on / out legend every containment picture carries.
void location_legend(io::SvgCanvas& canvas);

/// A translation by t.
[[nodiscard]] inline Transform shift(Vec3 t) {
  Transform transform;
  transform.t = t;
  return transform;
}

/// Remembers a file the demo wrote, for the closing list.
void record(const std::string& name);

/// Writes `text` to `name` in the demo folder and records it.
[[nodiscard]] Status save(const Context& context, const std::string& name, std::string_view text);

Status polygon_scene(const Context& context);
Status segment_scene(const Context& context);
Status sutherland_hodgman_scene(const Context& context);
Status boolean_scene(const Context& context);
Status csg_scene(const Context& context);
Status mesh_scene(const Context& context);
Status collide_scene(const Context& context);
Status ccd_scene(const Context& context);
Status mesh_clip_scene(const Context& context);
Status solid_scene(const Context& context);
Status bound_scene(const Context& context);
Status distance_slice_scene(const Context& context);
Status clearance_scene(const Context& context);
Status slice_scene(const Context& context);

}  // namespace contain::cli::demo
