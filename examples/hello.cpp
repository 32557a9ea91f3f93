// The short tour of contain's public API: exact point containment in 2D and 3D and bounding
// volumes. Built and run by the test suite, so it stays true.

#include <contain/contain.h>

#include <cstdio>
#include <vector>

int main() {
  using namespace contain;

  // A square with a square hole; points on an edge are on the boundary, exactly.
  auto square =
      Polygon::from_rings({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}});
  if (!square) {
    std::fprintf(stderr, "%s\n", square.error().what().c_str());
    return 1;
  }
  std::printf("(0.5, 0.5) is %s\n",
              to_string(inside::point_in_polygon(*square, {0.5, 0.5})).data());  // in
  std::printf("(4, 2)     is %s\n",
              to_string(inside::point_in_polygon(*square, {4, 2})).data());  // on

  // Many queries against one region: prepare it once, then locate in parallel.
  const inside::PolygonIndex index(*square, {.fill = Fill::even_odd});
  const std::vector<Vec2> points{{2, 2}, {0.5, 3.5}, {1, 2}, {9, 9}};
  std::vector<Location> where(points.size());
  index.locate(points, where, {.threads = 0});
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::printf("(%g, %g) is %s\n", points[i].x, points[i].y, to_string(where[i]).data());
  }

  // Solids: a unit ball united with a box, minus a half-space; regularised set operations.
  const Csg tree = Csg::difference(
      Csg::unite({Csg::leaf(Sphere{{0, 0, 0}, 1}), Csg::leaf(Box3{{0, -1, -1}, {2, 1, 1}})}),
      Csg::leaf(Plane{0, 0, 1, -0.5}));  // removes z >= 0.5
  auto solid = inside::CsgSolid::prepare(tree);
  if (!solid) return 1;
  std::printf("(1.5, 0, 0) is %s, (0, 0, 0.5) is %s\n",
              to_string(solid->locate({1.5, 0, 0})).data(),   // in
              to_string(solid->locate({0, 0, 0.5})).data());  // on

  // Bounding volumes: the minimal enclosing sphere contains every point, exactly checked.
  const std::vector<Vec3> cloud{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0, 0.5}};
  auto ball = bound::bounding_sphere(cloud);
  if (!ball) return 1;
  std::printf("minimal sphere: center (%g, %g, %g), radius %g\n", ball->center.x, ball->center.y,
              ball->center.z, ball->radius);
  return 0;
}
