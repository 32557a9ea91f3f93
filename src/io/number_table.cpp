#include "contain/io/number_table.h"

#include <algorithm>
#include <cstring>
#include <iostream>

#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::is_blank;
using detail::make_error;
using detail::NumberStatus;
using detail::skip_blanks;

std::string describe_counts(const std::vector<int>& allowed) {
  std::string out;
  for (std::size_t i = 0; i < allowed.size(); ++i) {
    if (i > 0) out += (i + 1 == allowed.size()) ? " or " : ", ";
    out += std::to_string(allowed[i]);
  }
  return out;
}

}  // namespace

Result<NumberTable> parse_number_table(std::string_view text, const std::string& source,
                                       const NumberTableOptions& options) {
  // A byte order mark is one only at the start of the whole text.
  if (options.lines_before == 0) text = detail::skip_bom(text);
  NumberTable table;
  const char* p = text.data();
  const char* const end = p + text.size();
  std::int64_t line = options.lines_before;
  int columns = options.first_row_columns;
  std::int64_t first_row_line = options.first_row_line;
  std::vector<double> row;
  // Room for every line: counting them is a fast pass, and capacity that stays unused is never
  // touched (no page faults); growing instead copied the values once or twice.
  const auto line_count = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  table.values.reserve(3 * line_count);
  table.lines.reserve(line_count);
  while (p != end) {
    ++line;
    const char* eol =
        static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (eol == nullptr) eol = end;
    row.clear();
    skip_blanks(p, eol);
    if (p != eol && *p != '#') {
      const char* at_number = p;
      while (true) {
        double value = 0.0;
        const char* at = p;
        at_number = p;
        switch (detail::parse_double(p, eol, value)) {
          case NumberStatus::ok:
            break;
          case NumberStatus::not_a_number:
            return make_error(ErrorKind::parse,
                              "expected a number, found " + detail::quote_token(at, eol), source,
                              line);
          case NumberStatus::not_finite:
            return make_error(ErrorKind::invalid_value,
                              "the number " + std::string(at, p) +
                                  " is not finite (NaN, infinite or too large for a double)",
                              source, line);
        }
        row.push_back(value);
        const char* after = p;
        skip_blanks(p, eol);
        if (p == eol || *p == '#') break;
        if (*p == ',') {
          ++p;
          skip_blanks(p, eol);
          if (p == eol || *p == '#' || *p == ',') {
            return make_error(
                ErrorKind::parse,
                "expected a number after the comma, found " + detail::quote_token(p, eol), source,
                line);
          }
        } else if (p == after) {
          return make_error(ErrorKind::parse,
                            "unexpected text " + detail::quote_token(after, eol) +
                                " after the number " + std::string(at_number, after),
                            source, line);
        }
      }
      const int count = static_cast<int>(row.size());
      if (columns == 0) {
        if (!options.columns.empty() && std::find(options.columns.begin(), options.columns.end(),
                                                  count) == options.columns.end()) {
          return make_error(ErrorKind::invalid_value,
                            "found " + std::to_string(count) + " numbers on the line, expected " +
                                describe_counts(options.columns),
                            source, line);
        }
        columns = count;
        first_row_line = line;
      } else if (count != columns) {
        return make_error(ErrorKind::invalid_value,
                          "found " + std::to_string(count) + " numbers on the line, but line " +
                              std::to_string(first_row_line) + " has " + std::to_string(columns) +
                              " (every line must have as many)",
                          source, line);
      }
      table.columns = columns;
      table.values.insert(table.values.end(), row.begin(), row.end());
      table.lines.push_back(line);
    }
    p = (eol == end) ? end : eol + 1;
  }
  return table;
}

Result<NumberTable> read_number_table(const std::filesystem::path& path,
                                      const NumberTableOptions& options) {
  if (path == "-") return read_number_table(std::cin, "<stdin>", options);
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_number_table(*text, detail::source_name(path), options);
}

Result<NumberTable> read_number_table(std::istream& in, const std::string& source,
                                      const NumberTableOptions& options) {
  auto text = detail::read_stream(in, source);
  if (!text) return text.error();
  return parse_number_table(*text, source, options);
}

}  // namespace contain::io
