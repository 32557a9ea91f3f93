// The contain command: parses the verb and its options, then hands over to the verb.

#include <CLI/CLI.hpp>

#include <iostream>
#include <new>
#include <vector>

#include "common.h"
#include "timings.h"
#include "verbs.h"

int main(int argc, char** argv) {
  using namespace contain::cli;
  CLI::App app{
      "contain: exact point containment, collision detection and clipping in 2D and 3D.\n"
      "Answers are exact on the given doubles: 'on' means exactly on the boundary.",
      "contain"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", "contain 0.1.0");
  app.footer(
      "Exit status: 0 success, 2 usage error, 3 bad input (the message names the file "
      "and line).\nRun 'contain VERB --help' for a verb's options and examples.");
  std::vector<Verb> verbs = verbs_for(app, argc, argv);
  bool show_timings = false;
  for (const Verb& verb : verbs) {
    if (verb.app->get_name() == "demo") continue;
    add_timings_option(*verb.app, show_timings);
    // Where the flag is written after a verb's own subcommand (`contain index build ...
    // --timings`), that subcommand parses it: it needs the flag too.
    for (CLI::App* sub : verb.app->get_subcommands({}))
      add_timings_option(*sub, show_timings);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_usage;
  }
  try {
    for (const Verb& verb : verbs) {
      if (!verb.app->parsed()) continue;
      if (show_timings) timings().start();
      const int status = verb.run();
      timings().print();
      return status;
    }
  } catch (const std::bad_alloc&) {
    std::cerr << "contain: the input needs more memory than this machine has\n";
    return exit_bad_input;
  }
  return exit_usage;
}
