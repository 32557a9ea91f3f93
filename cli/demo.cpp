// contain demo: every capability on built-in scenes (no files needed), with a short report,
// timings, and pictures and meshes written into a folder.

#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "common.h"
#include "demo_scenes.h"
#include "verbs.h"

namespace contain::cli {
namespace demo {
namespace {
std::vector<std::string> written;  // names of the files this run wrote, for the closing line
}  // namespace

Counts count(std::span<const Location> locations) {
  Counts c;
  for (Location l : locations) {
    if (l == Location::inside) ++c.inside;
    if (l == Location::boundary) ++c.boundary;
    if (l == Location::outside) ++c.outside;
  }
  return c;
}

void location_legend(io::SvgCanvas& canvas) {
  const io::LocationColours colours;
  canvas.legend(colours.inside, "in");
  canvas.legend(colours.boundary, "on (exact)");
  canvas.legend(colours.outside, "out");
}

void record(const std::string& name) {
  written.push_back(name);
}

Status save(const Context& context, const std::string& name, std::string_view text) {
  const Status status = write_output(text, (context.dir / name).string());
  if (status) record(name);
  return status;
}

}  // namespace demo

namespace {

struct DemoOptions {
  std::string out_dir = "contain-demo";
  int threads = 0;
};

int run_demo(const DemoOptions& o) {
  const demo::Context context{o.out_dir, o.threads};
  std::error_code ec;
  std::filesystem::create_directories(context.dir, ec);
  if (ec) return report({ErrorKind::io, "cannot create the folder: " + ec.message(), o.out_dir});
  fmt::print("contain demo: built-in scenes, exact answers\n\n");
  using Scene = Status (*)(const demo::Context&);
  const Scene scenes[] = {demo::polygon_scene,
                          demo::csg_scene,
                          demo::mesh_scene,
                          demo::collide_scene,
                          demo::ccd_scene,
                          demo::segment_scene,
                          demo::sutherland_hodgman_scene,
                          demo::boolean_scene,
                          demo::mesh_clip_scene,
                          demo::solid_scene,
                          demo::bound_scene,
                          demo::distance_slice_scene,
                          demo::clearance_scene,
                          demo::slice_scene};
  for (Scene scene : scenes) {
    const Status status = scene(context);
    if (!status) return report(status.error());
  }
  fmt::print("\nwrote {} files to {}/:\n", demo::written.size(), context.dir.string());
  for (const std::string& name : demo::written)
    fmt::print("  {}\n", name);
  return exit_ok;
}

}  // namespace

Verb add_demo(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "demo",
      "Runs every capability on built-in scenes; prints a report and writes pictures and meshes");
  cmd->add_option("--out-dir", o->out_dir,
                  "folder for the SVG pictures and OBJ/PLY meshes (created; default contain-demo)")
      ->option_text("DIR");
  add_threads_option(*cmd, o->threads);
  cmd->footer("Example:\n  contain demo --out-dir /tmp/demo && ls /tmp/demo");
  return {cmd, [o]() { return run_demo(*o); }};
}

}  // namespace contain::cli
