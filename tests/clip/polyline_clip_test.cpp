#include "contain/clip/polyline_clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "contain/inside/point_in_polygon.h"

namespace contain::clip {
namespace {

Ring box_ring(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

double length(const std::vector<Polyline>& paths) {
  double sum = 0;
  for (const Polyline& p : paths) {
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      sum += contain::length(p[i + 1] - p[i]);
  }
  return sum;
}

TEST(PolylineClip, LineThroughASquareSplitsIntoInsideAndOutsideParts) {
  const std::vector<Ring> square{box_ring(0, 0, 2, 2)};
  const std::vector<Polyline> line{{{-1, 1}, {3, 1}}};
  const auto in = clip_polylines(line, square, {.keep = PolylinePart::inside});
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0], (Polyline{{0, 1}, {2, 1}}));
  const auto out = clip_polylines(line, square, {.keep = PolylinePart::outside});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], (Polyline{{-1, 1}, {0, 1}}));
  EXPECT_EQ(out[1], (Polyline{{2, 1}, {3, 1}}));
}

TEST(PolylineClip, PathWhollyInsideIsReturnedBitForBit) {
  const std::vector<Ring> square{box_ring(0, 0, 1, 1)};
  const std::vector<Polyline> path{{{0.1, 0.1}, {0.3, 0.7}, {0.9, 0.2}, {0.15, 0.95}}};
  EXPECT_EQ(clip_polylines(path, square), path);
  EXPECT_TRUE(clip_polylines(path, square, {.keep = PolylinePart::outside}).empty());
}

TEST(PolylineClip, PieceAlongTheBoundaryBelongsToTheInsidePart) {
  const std::vector<Ring> square{box_ring(0, 0, 2, 2)};
  const std::vector<Polyline> path{{{-1, 0}, {3, 0}}};
  const auto in = clip_polylines(path, square);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0], (Polyline{{0, 0}, {2, 0}}));
  EXPECT_EQ(clip_polylines(path, square, {.keep = PolylinePart::outside}).size(), 2u);
}

TEST(PolylineClip, HolesAndFillRulesDecideTheInside) {
  Ring hole = box_ring(1, 1, 2, 2);
  const std::vector<Ring> region{box_ring(0, 0, 3, 3), hole};
  const std::vector<Polyline> path{{{-1, 1.5}, {4, 1.5}}};
  // Even-odd: the hole is outside; nonzero with both counter-clockwise: it is filled.
  EXPECT_EQ(clip_polylines(path, region, {.fill = Fill::even_odd}).size(), 2u);
  EXPECT_EQ(clip_polylines(path, region, {.fill = Fill::nonzero}).size(), 1u);
}

TEST(PolylineClip, InsideAndOutsidePartsTileEveryPath) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Ring star;
  for (int i = 0; i < 40; ++i) {
    const double t = 2 * M_PI * i / 40, r = 0.3 + 0.6 * (u(rng) + 1) / 2;
    star.push_back({r * std::cos(t), r * std::sin(t)});
  }
  const std::vector<Ring> region{star};
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Polyline> paths(1);
    for (int i = 0; i < 15; ++i)
      paths[0].push_back({u(rng), u(rng)});
    const auto in = clip_polylines(paths, region, {.keep = PolylinePart::inside});
    const auto out = clip_polylines(paths, region, {.keep = PolylinePart::outside});
    EXPECT_NEAR(length(in) + length(out), length(paths), 1e-12);
    for (const Polyline& p : in) {
      // Inner vertices lie in the region (the ends are rounded crossing points).
      for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        EXPECT_NE(inside::point_in_polygon(region, p[i]), Location::outside);
      }
    }
    for (const Polyline& p : out) {
      for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        EXPECT_EQ(inside::point_in_polygon(region, p[i]), Location::outside);
      }
    }
  }
}

}  // namespace
}  // namespace contain::clip
