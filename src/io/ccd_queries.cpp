#include "contain/io/ccd_queries.h"

#include <cstring>
#include <iostream>

#include "contain/io/number_table.h"
#include "contain/predicates/exact_rational.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::make_error;

// The comma-separated fields of a row, blanks around them dropped.
std::vector<std::string_view> fields(std::string_view row) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = row.find(',', start);
    std::string_view f =
        row.substr(start, comma == std::string_view::npos ? row.npos : comma - start);
    while (!f.empty() && detail::is_blank(f.front()))
      f.remove_prefix(1);
    while (!f.empty() && detail::is_blank(f.back()))
      f.remove_suffix(1);
    out.push_back(f);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

bool is_integer(std::string_view s) {
  std::size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
  }
  return true;
}

Result<CcdQueries> parse_benchmark(std::string_view text, const std::string& source) {
  text = detail::skip_bom(text);
  CcdQueries out;
  CcdPoints query{};
  int row_in_query = 0;
  std::int64_t line = 0;
  std::int64_t first_line = 0;
  std::int8_t expected = -1;
  std::size_t pos = 0;
  while (pos < text.size()) {
    ++line;
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view row = text.substr(pos, eol - pos);
    pos = eol + 1;
    std::size_t first = 0;
    while (first < row.size() && detail::is_blank(row[first]))
      ++first;
    if (first == row.size() || row[first] == '#') continue;
    const std::vector<std::string_view> f = fields(row);
    if (f.size() != 7) {
      return make_error(ErrorKind::parse,
                        "expected 7 comma-separated integers (numerator and denominator of x, y "
                        "and z, then the expected answer), found " +
                            std::to_string(f.size()) + " fields",
                        source, line);
    }
    for (const std::string_view field : f) {
      if (!is_integer(field)) {
        return make_error(ErrorKind::parse,
                          "expected an integer, found '" + std::string(field.substr(0, 40)) + "'",
                          source, line);
      }
    }
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
      const std::optional<double> v = predicates::rational_to_double(f[2 * k], f[2 * k + 1]);
      if (!v) {
        return make_error(ErrorKind::invalid_value,
                          "the rational " + std::string(f[2 * k].substr(0, 40)) + "/" +
                              std::string(f[2 * k + 1].substr(0, 40)) +
                              " is not exactly a double (each coordinate must be one)",
                          source, line);
      }
      xyz[k] = *v;
    }
    if (row_in_query == 0) {
      first_line = line;
      expected = f[6] == "1" ? 1 : (f[6] == "0" ? 0 : -1);
    }
    query[static_cast<std::size_t>(row_in_query)] = {xyz[0], xyz[1], xyz[2]};
    if (++row_in_query == 8) {
      out.queries.push_back(query);
      out.lines.push_back(first_line);
      out.expected.push_back(expected);
      row_in_query = 0;
    }
  }
  if (row_in_query != 0) {
    return make_error(ErrorKind::invalid_value,
                      "the file ends inside a query: " + std::to_string(row_in_query) +
                          " of its 8 rows (a query is 8 rows: 4 points at t = 0, then at t = 1)",
                      source, line);
  }
  return out;
}

Result<CcdQueries> from_table(Result<NumberTable> table) {
  if (!table) return table.error();
  CcdQueries out;
  out.queries.resize(table->rows());
  for (std::size_t r = 0; r < table->rows(); ++r) {
    for (std::size_t i = 0; i < 8; ++i) {
      const double* v = &table->values[r * 24 + i * 3];
      out.queries[r][i] = {v[0], v[1], v[2]};
    }
  }
  out.lines = std::move(table->lines);
  out.expected.assign(out.queries.size(), -1);
  return out;
}

}  // namespace

Result<CcdQueries> parse_ccd_queries(std::string_view text, const std::string& source,
                                     CcdFileFormat format) {
  if (format == CcdFileFormat::benchmark) return parse_benchmark(text, source);
  return from_table(parse_number_table(text, source, {.columns = {24}}));
}

Result<CcdQueries> read_ccd_queries(const std::filesystem::path& path) {
  if (path == "-") return from_table(read_number_table(std::cin, "<stdin>", {.columns = {24}}));
  auto text = detail::read_file(path);
  if (!text) return text.error();
  const CcdFileFormat format =
      detail::lower_extension(path) == ".csv" ? CcdFileFormat::benchmark : CcdFileFormat::numbers;
  return parse_ccd_queries(*text, detail::source_name(path), format);
}

}  // namespace contain::io
