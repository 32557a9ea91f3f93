#pragma once
/// \file
/// Text tables of numbers, one row a line: the common format of point files (2 or 3 numbers),
/// segment files (4 or 6), pose files (12) and list-valued command-line arguments.

#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/result.h"

namespace contain::io {

/// What a table may hold.
struct NumberTableOptions {
  /// The numbers a row may hold (e.g. {2, 3}); every row must hold as many as the first row.
  /// Empty: any positive count, still the same on every row.
  std::vector<int> columns;
  /// For text that continues a table (a reader parsing a long file piece by piece): the lines of
  /// the table before this text (the text's first line is line `lines_before + 1` in the rows and
  /// errors), and the line and count of the table's first row among them (0: no row yet), so that
  /// a row with another count is named against it as in one pass over the whole file.
  std::int64_t lines_before = 0;
  std::int64_t first_row_line = 0;
  int first_row_columns = 0;
};

/// Rows of numbers read from text, flat: row r is `values[r * columns .. r * columns + columns)`
/// and came from the 1-based line `lines[r]`.
struct NumberTable {
  std::vector<double> values;
  int columns = 0;  ///< 0 when there are no rows
  std::vector<std::int64_t> lines;

  [[nodiscard]] std::size_t rows() const { return lines.size(); }
};

/// Parses a table from text. A row is a line of numbers separated by white space or by one comma
/// (with optional white space around it); blank lines and lines whose first non-blank character is
/// `#` are skipped, and a `#` after the numbers starts a comment. Numbers are decimal
/// (std::from_chars general format, an optional leading '+'), correctly rounded. A UTF-8 byte order
/// mark and CR LF line ends are accepted.
///
/// Errors (with `source` and the line): ErrorKind::parse for text that is not a number, a missing
/// number between commas, a trailing comma; ErrorKind::invalid_value for NaN, infinities and
/// numbers that overflow (1e400); ErrorKind::invalid_value for a row whose count is not allowed or
/// differs from the first row's (the message names both counts). Empty text gives an empty table.
/// Linear time; about the speed of std::from_chars.
[[nodiscard]] Result<NumberTable> parse_number_table(std::string_view text,
                                                     const std::string& source,
                                                     const NumberTableOptions& options = {});

/// Reads a table from a file; the path "-" reads standard input (named "<stdin>" in errors).
/// A missing or unreadable file is ErrorKind::io.
[[nodiscard]] Result<NumberTable> read_number_table(const std::filesystem::path& path,
                                                    const NumberTableOptions& options = {});

/// Reads a table from a stream to its end; `source` names it in errors.
[[nodiscard]] Result<NumberTable> read_number_table(std::istream& in, const std::string& source,
                                                    const NumberTableOptions& options = {});

}  // namespace contain::io
