#pragma once
// Pictures of sections: every section of a stack in one SVG, one colour a level (contain slice
// --format svg, and the demo's layers).

#include <span>
#include <string>

#include "contain/clip/slice_mesh.h"

namespace contain::cli {

/// The sections drawn over each other in the plane's coordinates, the lowest level first, each
/// filled in its level's colour (blue for the lowest value to yellow for the highest). With
/// `lift` > 0 each section is shifted up and right by lift x (value - lowest value), a stack
/// seen obliquely. `title` is the caption.
[[nodiscard]] std::string sections_svg(std::span<const clip::Section> sections, double lift,
                                       const std::string& title);

}  // namespace contain::cli
