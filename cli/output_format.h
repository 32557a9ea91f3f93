#pragma once
// The text format of a region result: `--format` reconciled with `--out`'s extension, so that a
// file named .svg or .geojson never silently holds WKT (issue 24 found that trap in --tiles; the
// same rule holds wherever a verb writes regions).

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <string_view>

#include "contain/core/result.h"

namespace contain::cli {

/// The region format an output path's extension names: "wkt" (.wkt), "geojson" (.geojson,
/// .json) or "svg" (.svg); none for any other extension (.txt, none).
[[nodiscard]] std::optional<std::string> region_format_named_by(const std::string& path);

/// The format to write: `--format` when given (lower case), else the one `--out`'s extension
/// names, else "wkt". A `--format` that `--out`'s extension contradicts is a usage error naming
/// both (`verb` opens the message).
[[nodiscard]] Result<std::string> region_output_format(const CLI::Option& format_option,
                                                       const std::string& format,
                                                       const std::string& out,
                                                       std::string_view verb);

}  // namespace contain::cli
