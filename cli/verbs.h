#pragma once
// One function per verb; each adds its subcommand to the app and returns what runs it.

#include <vector>

#include "common.h"

namespace contain::cli {

Verb add_inside(CLI::App& app);
Verb add_bound(CLI::App& app);
Verb add_demo(CLI::App& app);
Verb add_clip(CLI::App& app);
Verb add_collide(CLI::App& app);
Verb add_distance(CLI::App& app);
Verb add_slice(CLI::App& app);
Verb add_index(CLI::App& app);

/// Every verb, in the order `contain --help` lists them.
std::vector<Verb> all_verbs(CLI::App& app);

/// The verbs that parsing `argv` can select: the one verb it names first, or all of them.
std::vector<Verb> verbs_for(CLI::App& app, int argc, char** argv);

}  // namespace contain::cli
