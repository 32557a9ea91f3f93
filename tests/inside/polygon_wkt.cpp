#include "inside/polygon_wkt.h"

#include <cctype>
#include <charconv>

namespace contain::test {

namespace {

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool eat(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  bool eat_word(std::string_view word) {
    skip_space();
    if (text_.size() - pos_ < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i) {
      if (std::toupper(static_cast<unsigned char>(text_[pos_ + i])) != word[i]) return false;
    }
    pos_ += word.size();
    return true;
  }
  std::optional<double> number() {
    skip_space();
    const char* begin = text_.data() + pos_;
    if (pos_ < text_.size() && text_[pos_] == '+') ++begin;
    double value = 0.0;
    const auto [end, ec] = std::from_chars(begin, text_.data() + text_.size(), value);
    if (ec != std::errc()) return std::nullopt;
    pos_ = static_cast<std::size_t>(end - text_.data());
    return value;
  }
  bool at_end() {
    skip_space();
    return pos_ == text_.size();
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

std::optional<Ring> ring(Scanner& s) {
  if (!s.eat('(')) return std::nullopt;
  Ring out;
  do {
    const auto x = s.number();
    const auto y = s.number();
    if (!x || !y) return std::nullopt;
    out.push_back({*x, *y});
  } while (s.eat(','));
  if (!s.eat(')')) return std::nullopt;
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

std::optional<Polygon> polygon(Scanner& s) {
  if (s.eat_word("EMPTY")) return Polygon{};
  if (!s.eat('(')) return std::nullopt;
  Polygon out;
  do {
    auto r = ring(s);
    if (!r) return std::nullopt;
    out.rings.push_back(std::move(*r));
  } while (s.eat(','));
  if (!s.eat(')')) return std::nullopt;
  return out;
}

}  // namespace

std::optional<MultiPolygon> parse_polygon_wkt(std::string_view text) {
  Scanner s(text);
  MultiPolygon out;
  if (s.eat_word("MULTIPOLYGON")) {
    if (!s.eat_word("EMPTY")) {
      if (!s.eat('(')) return std::nullopt;
      do {
        auto p = polygon(s);
        if (!p) return std::nullopt;
        out.polygons.push_back(std::move(*p));
      } while (s.eat(','));
      if (!s.eat(')')) return std::nullopt;
    }
  } else if (s.eat_word("POLYGON")) {
    auto p = polygon(s);
    if (!p) return std::nullopt;
    out.polygons.push_back(std::move(*p));
  } else {
    return std::nullopt;
  }
  if (!s.at_end()) return std::nullopt;
  return out;
}

}  // namespace contain::test
