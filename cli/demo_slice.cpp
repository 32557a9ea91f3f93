// The slicing scene of `contain demo`: the layers of a solid made of overlapping parts (a torus
// with a bar through its tube, in one mesh) as stacked sections, and its shadows.

#include <fmt/format.h>

#include <vector>

#include "contain/clip/slice_mesh.h"
#include "contain/io/svg.h"
#include "demo_scenes.h"
#include "scenes/scenes.h"
#include "slice_svg.h"

namespace contain::cli::demo {

namespace {

// The torus of the 3D scenes and a bar crossing its tube in one mesh: overlapping parts, which
// the sections count once (winding numbers, Fill::positive).
Mesh torus_and_bar() {
  Mesh mesh = scenes::torus(2.0, 0.6, 96, 48);
  const Mesh bar = scenes::box_mesh({{1.0, -0.3, -0.9}, {3.2, 0.3, 0.9}});
  const auto base = static_cast<std::int32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), bar.vertices.begin(), bar.vertices.end());
  for (TriangleIndices t : bar.triangles)
    mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return mesh;
}

}  // namespace

Status slice_scene(const Context& context) {
  const Mesh solid = torus_and_bar();
  std::vector<double> values;
  for (int k = 0; k <= 36; ++k)
    values.push_back((k - 18) / 20.0);  // through the bar's bottom and top faces (z = -0.9, 0.9)
  const Stopwatch clock;
  auto sections =
      clip::slice_mesh(solid, values, {.axis = clip::Axis::z}, {.threads = context.threads});
  if (!sections) return sections.error();
  const double slice_ms = clock.ms();
  std::size_t rings = 0;
  for (const clip::Section& s : *sections)
    rings += s.region.all_rings().size();
  const clip::Section& middle = (*sections)[18];
  fmt::print(
      "slicing           {} layers of a torus and a bar ({} triangles, overlapping parts counted "
      "once) in {:.1f} ms: {} rings; at z = {:.2g} {} polygon(s), the bar's faces at z = +-0.9 "
      "give {} and {} polygon(s)\n",
      values.size(), solid.triangles.size(), slice_ms, rings, middle.value,
      middle.region.polygons.size(), sections->front().region.polygons.size(),
      sections->back().region.polygons.size());
  Status saved =
      save(context, "slice-layers.svg",
           sections_svg(*sections, 0.35, "contain slice: 37 layers of a torus and a bar, stacked"));
  if (!saved) return saved;
  auto top = clip::shadow(solid, {.axis = clip::Axis::z});
  auto side = clip::shadow(solid, {.axis = clip::Axis::x});
  if (!top) return top.error();
  if (!side) return side.error();
  const std::vector<Ring> a = top->all_rings();
  std::vector<Ring> b = side->all_rings();
  for (Ring& ring : b) {
    for (Vec2& p : ring)
      p = {p.x + 6.5, p.y};  // beside the first: (y, z) of the view along x
  }
  std::vector<Ring> all = a;
  all.insert(all.end(), b.begin(), b.end());
  io::SvgCanvas canvas(bounding_box(all), 800);
  canvas.title("contain slice --shadow: from above (left) and along x (right)");
  canvas.region(a, {.fill = "#4c8dc9", .stroke = "#1f3b5c", .stroke_width = 1.0});
  canvas.region(b, {.fill = "#e3a34b", .stroke = "#7a4d10", .stroke_width = 1.0});
  fmt::print(
      "shadow            from above: {} polygon(s) with {} ring(s); along x: {} polygon(s)\n",
      top->polygons.size(), a.size(), side->polygons.size());
  return save(context, "slice-shadow.svg", canvas.str());
}

}  // namespace contain::cli::demo
