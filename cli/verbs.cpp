#include "verbs.h"

#include <array>
#include <string_view>

namespace contain::cli {
namespace {

struct NamedVerb {
  std::string_view name;  // the name its function gives its subcommand
  Verb (*add)(CLI::App&);
};

// In the order `contain --help` lists them.
constexpr std::array<NamedVerb, 8> kVerbs{{{"inside", add_inside},
                                           {"bound", add_bound},
                                           {"clip", add_clip},
                                           {"collide", add_collide},
                                           {"distance", add_distance},
                                           {"slice", add_slice},
                                           {"index", add_index},
                                           {"demo", add_demo}}};

const NamedVerb* verb_named(std::string_view name) {
  for (const NamedVerb& v : kVerbs) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

}  // namespace

std::vector<Verb> all_verbs(CLI::App& app) {
  std::vector<Verb> verbs;
  verbs.reserve(kVerbs.size());
  for (const NamedVerb& v : kVerbs)
    verbs.push_back(v.add(app));
  return verbs;
}

std::vector<Verb> verbs_for(CLI::App& app, int argc, char** argv) {
  // Building every verb's options is a third of a millisecond, a few per cent of a small boolean.
  // When the first argument is exactly a verb's name and no later one names another verb, the
  // parse can only select that verb: its options, help and errors are its own, whichever others
  // exist. Anything else (top-level help, a misspelt or missing verb) sees every verb.
  const NamedVerb* named = argc >= 2 ? verb_named(argv[1]) : nullptr;
  for (int i = 2; named != nullptr && i < argc; ++i) {
    if (const NamedVerb* other = verb_named(argv[i]); other != nullptr && other != named)
      named = nullptr;
  }
  if (named == nullptr) return all_verbs(app);
  std::vector<Verb> verbs;
  verbs.push_back(named->add(app));
  return verbs;
}

}  // namespace contain::cli
