#include "slice_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "contain/io/svg.h"

namespace contain::cli {

namespace {

// A perceptually ordered ramp (viridis' ends and middle), linear between its stops.
std::string level_colour(double t) {
  static constexpr double stops[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  const auto mix = [&](int c) {
    return static_cast<int>(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", mix(0), mix(1), mix(2));
}

}  // namespace

std::string sections_svg(std::span<const clip::Section> sections, double lift,
                         const std::string& title) {
  std::vector<std::size_t> order(sections.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return sections[a].value < sections[b].value;
  });
  const double low = sections.empty() ? 0.0 : sections[order.front()].value;
  const double high = sections.empty() ? 0.0 : sections[order.back()].value;
  std::vector<std::vector<Ring>> drawn(sections.size());
  Box2 world;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const double shift = lift * (sections[i].value - low);
    drawn[i] = sections[i].region.all_rings();
    for (Ring& ring : drawn[i]) {
      for (Vec2& p : ring) {
        p = {p.x + shift, p.y + shift};
        world.expand(p);
      }
    }
  }
  io::SvgCanvas canvas(world, 800);
  canvas.title(title);
  for (const std::size_t i : order) {
    const double t = high > low ? (sections[i].value - low) / (high - low) : 0.0;
    const std::string colour = level_colour(t);
    canvas.region(drawn[i], {.fill = colour,
                             .stroke = colour,
                             .stroke_width = 0.75,
                             .fill_opacity = lift > 0 ? 0.8 : 0.35});
  }
  if (!sections.empty()) {
    canvas.legend(level_colour(0.0), fmt::format("{}", low));
    if (high > low) canvas.legend(level_colour(1.0), fmt::format("{}", high));
  }
  return canvas.str();
}

}  // namespace contain::cli
