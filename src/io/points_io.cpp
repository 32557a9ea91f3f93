#include "contain/io/points_io.h"

#include <utility>

#include "contain/io/number_table.h"

namespace contain::io {
namespace {

Result<Points2> to_points2(Result<NumberTable> table) {
  if (!table) return table.error();
  Points2 out;
  out.points.reserve(table->rows());
  const std::vector<double>& v = table->values;
  for (std::size_t i = 0; i < table->rows(); ++i)
    out.points.push_back({v[2 * i], v[2 * i + 1]});
  out.lines = std::move(table->lines);
  return out;
}

Result<Points3> to_points3(Result<NumberTable> table) {
  if (!table) return table.error();
  Points3 out;
  out.points.reserve(table->rows());
  const std::vector<double>& v = table->values;
  for (std::size_t i = 0; i < table->rows(); ++i) {
    out.points.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
  }
  out.lines = std::move(table->lines);
  return out;
}

const NumberTableOptions kTwo{.columns = {2}};
const NumberTableOptions kThree{.columns = {3}};

}  // namespace

Result<Points2> parse_points2(std::string_view text, const std::string& source) {
  return to_points2(parse_number_table(text, source, kTwo));
}
Result<Points3> parse_points3(std::string_view text, const std::string& source) {
  return to_points3(parse_number_table(text, source, kThree));
}
Result<Points2> read_points2(const std::filesystem::path& path) {
  return to_points2(read_number_table(path, kTwo));
}
Result<Points3> read_points3(const std::filesystem::path& path) {
  return to_points3(read_number_table(path, kThree));
}
Result<Points2> read_points2(std::istream& in, const std::string& source) {
  return to_points2(read_number_table(in, source, kTwo));
}
Result<Points3> read_points3(std::istream& in, const std::string& source) {
  return to_points3(read_number_table(in, source, kThree));
}

}  // namespace contain::io
