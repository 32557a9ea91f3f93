#include "output_format.h"

#include <cctype>
#include <filesystem>

#include "contain/io/region_io.h"

namespace contain::cli {
namespace {

std::string lower(std::string text) {
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::optional<std::string> region_format_named_by(const std::string& path) {
  if (path.empty() || path == "-") return std::nullopt;
  if (lower(std::filesystem::path(path).extension().string()) == ".svg") return "svg";
  const auto format = io::region_format(path);
  if (!format) return std::nullopt;
  return *format == io::RegionFormat::geojson ? "geojson" : "wkt";
}

Result<std::string> region_output_format(const CLI::Option& format_option,
                                         const std::string& format, const std::string& out,
                                         std::string_view verb) {
  const std::optional<std::string> named = region_format_named_by(out);
  if (format_option.count() == 0) return named.value_or(lower(format));
  const std::string given = lower(format);
  if (named && *named != given) {
    return Error{ErrorKind::usage,
                 std::string(verb) + ": --format " + given + " but --out " + out + " names " +
                     *named + "; give one of them (the extension alone chooses the format)"};
  }
  return given;
}

}  // namespace contain::cli
