#pragma once
// What the whole-process point-query drivers of the peers share (geos_inside, embree_inside,
// cgal_inside): reading a point file and an OFF mesh as fast as plain C++ allows (the whole
// file in one read, std::from_chars), and writing one answer a line through one buffer. The
// peers get the fastest simple reader, so that the comparison is of the whole process, not of a
// slow reader.

#include <array>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace contain::bench {

[[nodiscard]] inline std::string read_whole_file(const char* path) {
  std::FILE* file = std::fopen(path, "rb");
  if (file == nullptr) {
    std::fprintf(stderr, "cannot open %s\n", path);
    std::exit(3);
  }
  std::string text;
  std::array<char, 1 << 16> buffer{};
  std::fseek(file, 0, SEEK_END);
  text.reserve(static_cast<std::size_t>(std::ftell(file)));
  std::fseek(file, 0, SEEK_SET);
  for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), file)) > 0;)
    text.append(buffer.data(), got);
  std::fclose(file);
  return text;
}

// Numbers separated by white space or commas; '#' starts a comment to the end of the line.
class NumberScanner {
 public:
  explicit NumberScanner(std::string_view text) : p_(text.data()), end_(p_ + text.size()) {}

  // The next number, false at the end; exits with status 3 on text that is not a number.
  bool next(double& value) {
    skip();
    if (p_ == end_) return false;
    if (*p_ == '+') ++p_;
    const auto [ptr, ec] = std::from_chars(p_, end_, value);
    if (ec != std::errc{}) {
      std::fprintf(stderr, "not a number at byte %td\n", p_ - start_);
      std::exit(3);
    }
    p_ = ptr;
    return true;
  }

  double need() {
    double value = 0.0;
    if (!next(value)) {
      std::fprintf(stderr, "the file ends early\n");
      std::exit(3);
    }
    return value;
  }

  // Skips a word ("OFF").
  void word() {
    skip();
    while (p_ != end_ && *p_ != ' ' && *p_ != '\n' && *p_ != '\t' && *p_ != '\r')
      ++p_;
  }

 private:
  void skip() {
    while (p_ != end_) {
      if (*p_ == '#') {
        while (p_ != end_ && *p_ != '\n')
          ++p_;
      } else if (*p_ == ' ' || *p_ == '\n' || *p_ == '\t' || *p_ == '\r' || *p_ == ',') {
        ++p_;
      } else {
        return;
      }
    }
  }

  const char* p_;
  const char* end_;
  const char* start_ = p_;
};

// Every number of a point file, flat (N a point).
[[nodiscard]] inline std::vector<double> read_numbers(const char* path) {
  const std::string text = read_whole_file(path);
  std::vector<double> out;
  NumberScanner scan(text);
  for (double v; scan.next(v);)
    out.push_back(v);
  return out;
}

struct OffMesh {
  std::vector<double> vertices;     // x y z a vertex
  std::vector<unsigned> triangles;  // 3 indices a triangle
};

// A triangle OFF file (the faces "3 a b c").
[[nodiscard]] inline OffMesh read_off(const char* path) {
  const std::string text = read_whole_file(path);
  NumberScanner scan(text);
  scan.word();
  OffMesh mesh;
  const auto nv = static_cast<std::size_t>(scan.need());
  const auto nf = static_cast<std::size_t>(scan.need());
  (void)scan.need();
  mesh.vertices.resize(3 * nv);
  for (double& v : mesh.vertices)
    v = scan.need();
  mesh.triangles.reserve(3 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    if (scan.need() != 3.0) {
      std::fprintf(stderr, "face %zu is not a triangle\n", f);
      std::exit(3);
    }
    for (int k = 0; k < 3; ++k)
      mesh.triangles.push_back(static_cast<unsigned>(scan.need()));
  }
  return mesh;
}

// "in", "on" or "out" a line (answer 1, 0, -1) through one buffer.
inline void write_answers(const std::vector<signed char>& answers) {
  std::string text;
  text.reserve(4 * answers.size());
  for (const signed char a : answers)
    text += a > 0 ? "in\n" : a == 0 ? "on\n" : "out\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
}

}  // namespace contain::bench
