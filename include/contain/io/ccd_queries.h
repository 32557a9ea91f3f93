#pragma once
/// \file
/// Files of continuous collision queries (`contain collide --ccd`, shared/spec/cli.md): the CSV
/// format of the CCD benchmark of Wang et al. (2021), with exact rational coordinates, or one
/// query a line as 24 numbers.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <array>

#include "contain/core/result.h"
#include "contain/values/vec.h"

namespace contain::io {

/// Eight points of a query in the benchmark's order (four at t = 0, then the same four at t = 1;
/// the same layout as `collide::CcdQuery`).
using CcdPoints = std::array<Vec3, 8>;

/// Queries in file order, each with the 1-based line where it starts and, for the benchmark
/// format, the value of the last column of its first row (the benchmark's expected answer:
/// 1 contact, 0 none; -1 in the 24-number format).
struct CcdQueries {
  std::vector<CcdPoints> queries;
  std::vector<std::int64_t> lines;
  std::vector<std::int8_t> expected;
};

/// Which layout a query file has.
enum class CcdFileFormat : std::uint8_t {
  benchmark,  ///< 8 rows a query, 7 integer columns: num, den of x, y, z, then one ignored
  numbers,    ///< one query a line: 24 numbers (x y z of the 8 points in CcdQuery order)
};

/// Parses queries. Benchmark format: each row holds 7 comma-separated integers of any length;
/// every rational num / den must be exactly a double (read exactly, never rounded); blank lines
/// and `#` lines are skipped. Errors name the line: ErrorKind::parse for a row that is not 7
/// integers, ErrorKind::invalid_value for a rational that is not exactly a double (or a zero
/// denominator) and for a file whose row count is not a multiple of 8. Numbers format: the rules
/// of `parse_number_table` with 24 columns. An empty file gives no queries.
[[nodiscard]] Result<CcdQueries> parse_ccd_queries(std::string_view text, const std::string& source,
                                                   CcdFileFormat format);

/// Reads a query file: the benchmark format when the extension is `.csv` (any case), else the
/// numbers format. "-" reads standard input in the numbers format.
[[nodiscard]] Result<CcdQueries> read_ccd_queries(const std::filesystem::path& path);

}  // namespace contain::io
