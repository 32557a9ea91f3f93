// The solid scene of `contain demo`: a bracket built by CSG (plate, wall and rib united, bolt
// holes and a fillet block subtracted), evaluated by the exact mesh booleans into one mesh,
// written as OBJ and drawn.

#include <fmt/format.h>

#include "contain/clip/csg_to_mesh.h"
#include "contain/io/mesh_io.h"
#include "contain/shapes/mesh_closure.h"
#include "demo_scenes.h"
#include "scenes/scenes.h"

namespace contain::cli::demo {

Status solid_scene(const Context& context) {
  const Stopwatch clock;
  auto bracket = clip::csg_to_mesh(scenes::bracket_csg());
  const double ms = clock.ms();
  if (!bracket) return bracket.error();
  const Mesh& mesh = bracket->mesh;
  fmt::print(
      "solid booleans     CSG bracket (plate + wall + rib - 2 bolt holes - fillet block): {} "
      "triangles in {:.1f} ms, volume {:.6g}, {} shell(s), {} vertices moved, {}\n",
      mesh.triangles.size(), ms, bracket->volume, bracket->shells, bracket->moved,
      unmatched_edge(mesh) ? "NOT closed" : "closed");
  if (Status s = io::write_mesh(mesh, context.dir / "solid-bracket.obj"); !s) return s;
  record("solid-bracket.obj");
  const io::View3 view{.azimuth_deg = 60.0, .elevation_deg = 40.0};  // from the front, above
  io::SvgCanvas canvas(io::projected_bounds(mesh.vertices, view), 800);
  canvas.title("contain clip --csg: bracket, exact mesh booleans");
  canvas.mesh(mesh, view);
  return save(context, "solid-bracket.svg", canvas.str());
}

}  // namespace contain::cli::demo
