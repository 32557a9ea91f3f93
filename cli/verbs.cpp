#include "verbs.h"

namespace contain::cli {

std::vector<Verb> all_verbs(CLI::App& app) {
  return {add_inside(app),   add_bound(app), add_clip(app),  add_collide(app),
          add_distance(app), add_slice(app), add_index(app), add_demo(app)};
}

}  // namespace contain::cli
