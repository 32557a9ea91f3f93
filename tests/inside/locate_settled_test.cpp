// locate_settled of PolygonIndex and MeshIndex (the answer for a whole box, used for points read
// from their first digits): where it answers, every point of the box is located so by the
// ordinary locate (corners, centre, the point the box was made around), on random and
// degenerate points (vertices, edges, grid lines); a box touching a grid line is never settled
// inside the bounds; and it does answer for most small boxes (the test is not vacuous).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "contain/inside/grid_axis.h"
#include "contain/inside/index_file.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/polygon_index.h"
#include "inside/mesh_test_meshes.h"
#include "inside/polygon_random.h"

namespace contain::inside {
namespace {

// Boxes around p: the point itself, tiny boxes on each side, one as wide as a cell, and one
// whose low x corner is the nearest grid line (touching it).
std::vector<Box2> boxes_around(Vec2 p, std::span<const double> grid_x, double cell) {
  std::vector<Box2> boxes{{p, p}};
  for (const double w : {1e-12, 1e-8, 1e-3, cell}) {
    boxes.push_back({p, {p.x + w, p.y + w}});
    boxes.push_back({{p.x - w, p.y - w}, p});
  }
  const auto line = std::lower_bound(grid_x.begin(), grid_x.end(), p.x);
  if (line != grid_x.end()) boxes.push_back({{*line, p.y}, {*line + 1e-9, p.y + 1e-9}});
  return boxes;
}

// Where the index settles the box, the ordinary locate agrees at its corners and centre.
int expect_settled_agrees(const PolygonIndex& index, const Box2& box) {
  const std::optional<Location> settled = index.locate_settled(box);
  if (!settled) return 0;
  const std::array<Vec2, 5> probes{
      box.min, box.max, Vec2{box.min.x, box.max.y}, Vec2{box.max.x, box.min.y},
      box.min + 0.5 * (box.max - box.min)};  // the centre, in the box even when subnormal
  for (const Vec2& q : probes) {
    EXPECT_EQ(index.locate(q), *settled) << q.x << " " << q.y;
  }
  return 1;
}

TEST(LocateSettled, PolygonAnswersOnlyWhereEveryPointOfTheBoxLocatesSo) {
  std::mt19937_64 rng(27);
  for (int round = 0; round < 40; ++round) {
    const std::vector<Ring> rings =
        round % 2 == 0 ? test::random_integer_rings(rng, 3, 12, 8)
                       : std::vector<Ring>{test::random_star(rng, 20 + round, 0.0, 0.0, 1.0)};
    const PolygonIndex index(std::span<const Ring>(rings), {.min_cells = 64});
    const Box2 b = index.bounds();
    const double cell = (b.max.x - b.min.x) / static_cast<double>(index.grid_x().size());
    std::vector<Vec2> points = test::points_near_rings(rng, rings, 3);
    std::uniform_real_distribution<double> ux(b.min.x - 0.1, b.max.x + 0.1),
        uy(b.min.y - 0.1, b.max.y + 0.1);
    int tiny = 0;  // random points whose tiny box is settled
    for (int k = 0; k < 300; ++k) {
      const Vec2 p{ux(rng), uy(rng)};
      tiny += index.locate_settled({p, {p.x + 1e-8, p.y + 1e-8}}) ? 1 : 0;
      points.push_back(p);
    }
    for (const double x : index.grid_x())  // on the grid lines
      points.push_back({x, uy(rng)});
    int settled = 0;
    for (const Vec2& p : points) {
      for (const Box2& box : boxes_around(p, index.grid_x(), cell)) {
        settled += expect_settled_agrees(index, box);
      }
    }
    EXPECT_GT(settled, 0);
    if (round % 2 == 1) {  // a star: most random points are far from its edges
      EXPECT_GT(tiny, 100);
    }
  }
}

// Boxes in the cells that edges cross: settled only where every point of the box locates so
// (corners, centre and points drawn inside it), whatever the fill rule, around vertices, points
// on edges and near them, and on integer rings whose vertices share heights with the boxes'
// sides; and a tiny box off the edges is settled there too (the test is not vacuous: without
// the edge-cell proof no tiny box in an edge cell is).
TEST(LocateSettled, PolygonBoxesInEdgeCellsAnswerOnlyWhereEveryPointLocatesSo) {
  std::mt19937_64 rng(1027);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int round = 0; round < 24; ++round) {
    const std::vector<Ring> rings =
        round % 3 == 0 ? test::random_integer_rings(rng, 3, 12, 8)
                       : std::vector<Ring>{test::random_star(rng, 20 + round, 0.0, 0.0, 1.0)};
    const Fill fill = std::array{Fill::even_odd, Fill::nonzero, Fill::positive}[round % 3];
    // A coarse grid: every edge cell holds several edges and side edges.
    const PolygonIndex index(std::span<const Ring>(rings), {.fill = fill, .min_cells = 16});
    std::vector<Vec2> points = test::points_near_rings(rng, rings, 8);
    for (const Ring& ring : rings)
      points.insert(points.end(), ring.begin(), ring.end());
    for (const Vec2& p : std::vector<Vec2>(points)) {  // and just off each of them
      points.push_back({p.x + 1e-9, p.y - 1e-9});
      points.push_back({p.x - 1e-6, p.y + 1e-6});
    }
    for (const Vec2& p : points) {
      for (const double w : {0.0, 1e-12, 1e-8, 1e-4, 0.05}) {
        for (const Box2& box : {Box2{p, {p.x + w, p.y + w}}, Box2{{p.x - w, p.y - w}, p},
                                Box2{{p.x - w, p.y}, {p.x, p.y + 2 * w}},
                                Box2{{p.x - w, p.y - w}, {p.x + w, p.y + w}}}) {
          if (expect_settled_agrees(index, box) == 0) continue;
          for (int k = 0; k < 4; ++k) {
            const Vec2 q{std::min(box.max.x, box.min.x + unit(rng) * (box.max.x - box.min.x)),
                         std::min(box.max.y, box.min.y + unit(rng) * (box.max.y - box.min.y))};
            EXPECT_EQ(index.locate(q), index.locate_settled(box)) << q.x << " " << q.y;
          }
        }
      }
    }
    if (round % 3 != 0) {  // a star: random tiny boxes settle, edge cells or not
      const Box2 b = index.bounds();
      int tiny = 0;
      for (int k = 0; k < 1000; ++k) {
        const Vec2 p{b.min.x + unit(rng) * (b.max.x - b.min.x),
                     b.min.y + unit(rng) * (b.max.y - b.min.y)};
        tiny += index.locate_settled({p, {p.x + 1e-8, p.y + 1e-8}}) ? 1 : 0;
      }
      EXPECT_GT(tiny, 950);
    }
  }
}

TEST(LocateSettled, PolygonBoxTouchingAnInnerGridLineIsNotSettled) {
  std::mt19937_64 rng(5);
  const std::vector<Ring> rings{test::random_star(rng, 30, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  const std::span<const double> xs = index.grid_x(), ys = index.grid_y();
  for (std::size_t i = 1; i + 1 < xs.size(); ++i) {
    for (std::size_t j = 1; j + 1 < ys.size(); j += 7) {
      const double y = 0.5 * ys[j] + 0.5 * ys[j + 1];
      EXPECT_FALSE(index.locate_settled({{xs[i], y}, {xs[i] + 1e-9, y}}));
      EXPECT_FALSE(index.locate_settled({{xs[i] - 1e-9, y}, {xs[i], y}}));
    }
  }
  // Beyond the bounds, even touching them: outside.
  const Box2 b = index.bounds();
  EXPECT_EQ(index.locate_settled({{b.max.x + 1.0, 0.0}, {b.max.x + 2.0, 0.0}}), Location::outside);
  // An empty region settles every box as outside, as it locates every point.
  EXPECT_EQ(PolygonIndex().locate_settled({{0, 0}, {1, 1}}), Location::outside);
}

// Without a grid (few queries) the one cell holds every edge: a box is settled by its walk where
// no edge meets the box, never around a vertex.
TEST(LocateSettled, PolygonWithoutGridSettlesBoxesOffTheEdgesByItsOneCell) {
  std::mt19937_64 rng(8);
  const std::vector<Ring> rings{test::random_star(rng, 30, 0.0, 0.0, 1.0)};
  const PolygonIndex index(std::span<const Ring>(rings), {.queries = 1});
  ASSERT_EQ(index.stats().cells, 1u);
  EXPECT_EQ(index.locate_settled({{0, 0}, {1e-9, 1e-9}}), Location::inside);  // the star's centre
  EXPECT_EQ(expect_settled_agrees(index, {{0, 0}, {1e-9, 1e-9}}), 1);
  EXPECT_EQ(index.locate_settled({{5, 5}, {6, 6}}), Location::outside);
  for (const Vec2& v : rings[0]) {
    EXPECT_FALSE(index.locate_settled({{v.x - 1e-9, v.y - 1e-9}, {v.x + 1e-9, v.y + 1e-9}}));
  }
}

// An edge wholly left of a box adds nothing to the walk of any of its points, even with an end at
// the box's heights: the box is settled (it was not while such ends refused the box first).
TEST(LocateSettled, PolygonEdgeLeftOfTheBoxWithAnEndAtItsHeightsDoesNotUnsettleIt) {
  // A pentagon with a vertex in the middle of its left side (at height 2) and its rightmost
  // vertex (the one cell's right side) above the boxes' heights.
  const std::vector<Ring> rings{{{0, 0}, {4, 0}, {6, 3}, {4, 4}, {0, 4}, {0, 2}}};
  const PolygonIndex index(std::span<const Ring>(rings), {.queries = 1});
  ASSERT_EQ(index.stats().cells, 1u);
  EXPECT_EQ(index.locate_settled({{3, 1.9}, {3.5, 2.1}}), Location::inside);
  EXPECT_EQ(expect_settled_agrees(index, {{3, 1.9}, {3.5, 2.1}}), 1);
  // A box across the left side holds points in and out: no answer.
  EXPECT_FALSE(index.locate_settled({{-0.5, 1.9}, {0.5, 2.1}}));
}

// Whether `box` lies strictly inside a cell of the index's grid whose middle half the index does
// not settle: then an edge cell, since a cell no edge touches settles every box strictly inside
// it (the floating-point guess of a cell is not wrong a quarter of a cell from its lines).
bool in_edge_cell(const PolygonIndex& index, const Box2& box) {
  const std::span<const double> gx = index.grid_x(), gy = index.grid_y();
  const auto ix = std::upper_bound(gx.begin(), gx.end(), box.min.x);
  const auto iy = std::upper_bound(gy.begin(), gy.end(), box.min.y);
  if (ix == gx.begin() || ix == gx.end() || iy == gy.begin() || iy == gy.end()) return false;
  const double x0 = *(ix - 1), x1 = *ix, y0 = *(iy - 1), y1 = *iy;
  if (!(x0 < box.min.x && box.max.x < x1 && y0 < box.min.y && box.max.y < y1)) return false;
  const Vec2 quarter{0.25 * (x1 - x0), 0.25 * (y1 - y0)};
  return !index.locate_settled(
      {{x0 + quarter.x, y0 + quarter.y}, {x1 - quarter.x, y1 - quarter.y}});
}

// An index saved and loaded settles every box as the index it was saved from: the records
// locate_settled reads (edge cells found by their rank in the packed states, a cell's first edge
// beside its record) are rebuilt on loading, for cells of one edge (the fine grid) and of
// several (the coarse one). Boxes settled inside edge cells are counted: the records were read.
TEST(LocateSettled, PolygonLoadedFromItsFileSettlesBoxesAsTheIndexSaved) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(-1.1, 1.1);
  const std::vector<Ring> rings{test::random_star(rng, 100, 0.0, 0.0, 1.0)};
  for (const std::size_t min_cells : {std::size_t{16}, std::size_t{1} << 16}) {
    const PolygonIndex built(std::span<const Ring>(rings), {.min_cells = min_cells});
    const auto loaded = parse_polygon_index(format_index(built, 0));
    ASSERT_TRUE(loaded);
    int settled = 0, settled_in_edge_cells = 0;
    for (int k = 0; k < 20000; ++k) {
      const Vec2 p{unit(rng), unit(rng)};
      for (const double w : {0.0, 1e-8, 1e-3}) {
        const Box2 box{p, {p.x + w, p.y + w}};
        ASSERT_EQ(loaded->locate_settled(box), built.locate_settled(box)) << p.x << " " << p.y;
        if (expect_settled_agrees(*loaded, box) == 0) continue;
        ++settled;
        settled_in_edge_cells += in_edge_cell(*loaded, box) ? 1 : 0;
      }
    }
    EXPECT_GT(settled, 50000);
    EXPECT_GT(settled_in_edge_cells, 500);  // 1,437 and 16,918 when written
  }
}

int expect_settled_agrees(const MeshIndex& index, const Box3& box) {
  const std::optional<Location> settled = index.locate_settled(box);
  if (!settled) return 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 q{(corner & 1) != 0 ? box.max.x : box.min.x,
                 (corner & 2) != 0 ? box.max.y : box.min.y,
                 (corner & 4) != 0 ? box.max.z : box.min.z};
    EXPECT_EQ(index.locate(q), *settled) << q.x << " " << q.y << " " << q.z;
  }
  const Vec3 centre = box.min + 0.5 * (box.max - box.min);  // in the box, even when subnormal
  EXPECT_EQ(index.locate(centre), *settled);
  return 1;
}

TEST(LocateSettled, MeshAnswersOnlyWhereEveryPointOfTheBoxLocatesSo) {
  std::mt19937_64 rng(3);
  const std::vector<Mesh> meshes{test::grid_cube(0.0, 4.0, 4), test::octahedron(2.0),
                                 test::l_prism(), test::scaled(test::l_prism(), 0.25)};
  for (const Mesh& mesh : meshes) {
    const MeshIndex index(mesh);
    const Box3 b = index.bounds();
    std::uniform_real_distribution<double> ux(b.min.x - 0.5, b.max.x + 0.5),
        uy(b.min.y - 0.5, b.max.y + 0.5), uz(b.min.z - 0.5, b.max.z + 0.5);
    std::uniform_int_distribution<int> lattice(-2, 18);
    std::vector<Vec3> points;
    for (int k = 0; k < 2000; ++k)
      points.push_back({ux(rng), uy(rng), uz(rng)});
    for (int k = 0; k < 2000; ++k) {  // on vertices, faces and grid planes: quarter lattice
      points.push_back({0.25 * lattice(rng), 0.25 * lattice(rng), 0.25 * lattice(rng)});
    }
    for (const Vec3& v : mesh.vertices)
      points.push_back(v);
    int settled = 0, tiny = 0;
    for (const Vec3& p : points) {
      for (const double w : {0.0, 1e-9, 1e-3, 0.3}) {
        settled += expect_settled_agrees(index, {p, p + Vec3{w, w, w}});
        settled += expect_settled_agrees(index, {p - Vec3{w, w, w}, p});
      }
      tiny += index.locate_settled({p, p + Vec3{1e-8, 1e-8, 1e-8}}) ? 1 : 0;
    }
    EXPECT_GT(settled, 0);
    EXPECT_GT(tiny, 1000);
  }
}

TEST(LocateSettled, MeshBoxTouchingAGridPlaneOrWithoutGridIsNotSettledInsideTheBounds) {
  const Mesh cube = test::grid_cube(0.0, 4.0, 2);
  const MeshIndex index(cube);
  const Box3 b = index.bounds();
  const Vec3 mid = 0.5 * b.min + 0.5 * b.max;
  EXPECT_FALSE(index.locate_settled({{b.min.x, mid.y, mid.z}, {b.min.x + 1e-9, mid.y, mid.z}}));
  // Every inner plane across x, touched from either side (the index's axis: its bounds cut
  // into its cell count, as the index builds it), at a y and z inside a cell.
  const MeshIndex::Stats stats = index.stats();
  ASSERT_GT(stats.nx, 1);
  const GridAxis xs(b.min.x, b.max.x, stats.nx);
  const GridAxis ys(b.min.y, b.max.y, stats.ny), zs(b.min.z, b.max.z, stats.nz);
  int settled_between = 0;  // the same boxes moved off the plane: settled in empty cells
  for (int j = 0; j < stats.ny; j += 3) {
    const double y = 0.5 * ys.line(j) + 0.5 * ys.line(j + 1);
    const double z = 0.5 * zs.line(j % stats.nz) + 0.5 * zs.line(j % stats.nz + 1);
    for (int i = 1; i < stats.nx; ++i) {
      const double x = xs.line(i);
      EXPECT_FALSE(index.locate_settled({{x, y, z}, {x + 1e-9, y, z}})) << i << " " << j;
      EXPECT_FALSE(index.locate_settled({{x - 1e-9, y, z}, {x, y, z}})) << i << " " << j;
      const double between = 0.5 * xs.line(i - 1) + 0.5 * x;
      settled_between += index.locate_settled({{between, y, z}, {between + 1e-9, y, z}}) ? 1 : 0;
    }
  }
  EXPECT_GT(settled_between, 10);
  EXPECT_EQ(index.locate_settled({{-2, -2, -2}, {-1, -1, -1}}), Location::outside);
  const MeshIndex few(cube, {.queries = 1});
  EXPECT_FALSE(few.locate_settled({mid, mid}));
  EXPECT_EQ(few.locate_settled({{5, 5, 5}, {6, 6, 6}}), Location::outside);
}

}  // namespace
}  // namespace contain::inside
