#include "io/json_tree.h"

#include <algorithm>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <unordered_set>
#include <utility>

#include "io/text_scan.h"

namespace contain::io::detail {

const JsonValue* JsonValue::member(std::string_view name) const {
  for (const auto& [key, value] : members) {
    if (key == name) return &value;
  }
  return nullptr;
}

namespace {

// A char iterator that publishes how far nlohmann's lexer has read.
class TrackingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  TrackingIterator() = default;
  TrackingIterator(const char* p, const char** cursor) : p_(p), cursor_(cursor) {}
  reference operator*() const { return *p_; }
  TrackingIterator& operator++() {
    ++p_;
    if (cursor_ != nullptr) *cursor_ = p_;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator old = *this;
    ++*this;
    return old;
  }
  friend bool operator==(const TrackingIterator& a, const TrackingIterator& b) {
    return a.p_ == b.p_;
  }

 private:
  const char* p_ = nullptr;
  const char** cursor_ = nullptr;
};

class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  TreeBuilder(const char* begin, const char** cursor, std::span<const std::string_view> keep_text)
      : begin_(begin), cursor_(cursor), keep_text_(keep_text) {}

  bool null() override { return add(JsonValue{}); }
  bool boolean(bool value) override {
    JsonValue v = make(JsonValue::Kind::boolean);
    v.number = value ? 1.0 : 0.0;  // read by ids: "v": true must not print false
    return add(std::move(v));
  }
  bool number_integer(number_integer_t v) override {
    return add_number(static_cast<double>(v), [&] { return std::to_string(v); });
  }
  bool number_unsigned(number_unsigned_t v) override {
    return add_number(static_cast<double>(v), [&] { return std::to_string(v); });
  }
  bool number_float(number_float_t, const string_t& text) override {
    // Re-read with from_chars: correctly rounded, and overflow is reported instead of infinity.
    const char* p = text.data();
    double v = 0.0;
    if (parse_double(p, text.data() + text.size(), v) != detail::NumberStatus::ok) {
      error_offset_ = offset();
      error_ = "the number " + text + " is not finite (too large for a double)";
      overflow_ = true;
      return false;
    }
    return add_number(v, [&] { return text; });
  }
  bool string(string_t& s) override {
    JsonValue v = make(JsonValue::Kind::string);
    v.text = std::move(s);
    return add(std::move(v));
  }
  bool binary(binary_t&) override { return add(JsonValue{}); }
  bool start_object(std::size_t) override {
    if (!can_open()) return false;
    stack_.push_back({make(JsonValue::Kind::object), {}});
    return true;
  }
  bool key(string_t& k) override {
    // JSON leaves it to the reader which of two equal names counts: a misspelt copy or a second
    // "coordinates" would silently win or lose, so a name given twice is an error.
    Open& open = stack_.back();
    if (open.value.members.size() >= kIndexedMembers && open.keys.empty()) {
      for (const JsonMember& m : open.value.members)
        open.keys.insert(m.key);
    }
    const bool repeated = open.keys.empty()
                              ? std::any_of(open.value.members.begin(), open.value.members.end(),
                                            [&](const JsonMember& m) { return m.key == k; })
                              : !open.keys.insert(k).second;
    if (repeated) {
      error_offset_ = offset() == 0 ? 0 : offset() - 1;
      error_ = "the member \"" + k + "\" is given twice in one object";
      return false;
    }
    open.key = std::move(k);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    if (!can_open()) return false;
    stack_.push_back({make(JsonValue::Kind::array), {}});
    return true;
  }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& ex) override {
    // Keep nlohmann's description, without its "[json.exception...] parse error at line L, column
    // C: " prefix (the line is ours to report).
    std::string message = ex.what();
    const std::size_t column = message.find("column");
    if (column != std::string::npos) {
      const std::size_t colon = message.find(": ", column);
      if (colon != std::string::npos) message = message.substr(colon + 2);
    } else if (const std::size_t bracket = message.find("] "); bracket != std::string::npos) {
      message = message.substr(bracket + 2);
    }
    // 406: a number too large for a double (nlohmann-json's out_of_range.406).
    overflow_ = ex.id == 406;
    error_ = (overflow_ ? "a number is too large for a double: " : "malformed JSON: ") + message;
    error_offset_ = position == 0 ? 0 : position - 1;
    return false;
  }

  std::optional<JsonValue> root;
  std::string error_;
  std::size_t error_offset_ = 0;
  bool overflow_ = false;

 private:
  struct Open {
    JsonValue value;
    std::string key;
    std::unordered_set<std::string> keys;  // the names so far, once an object has many
  };
  static constexpr std::size_t kIndexedMembers = 32;

  // The tree is freed recursively: bound its depth (GeoJSON needs 4 levels and a few wrappers).
  bool can_open() {
    if (stack_.size() < 256) return true;
    error_offset_ = offset();
    error_ = "the JSON is nested more than 256 levels deep";
    return false;
  }

  [[nodiscard]] std::size_t offset() const {
    return *cursor_ == nullptr ? 0 : static_cast<std::size_t>(*cursor_ - begin_);
  }
  [[nodiscard]] JsonValue make(JsonValue::Kind kind) const {
    JsonValue v;
    v.kind = kind;
    v.offset = offset() == 0 ? 0 : offset() - 1;
    return v;
  }
  // `text()` is the number as written; kept only for the members named in keep_text_ (ids and
  // properties), not for the millions of coordinates in arrays.
  template <class Text>
  bool add_number(double x, Text&& text) {
    JsonValue v = make(JsonValue::Kind::number);
    v.number = x;
    if (!stack_.empty() && stack_.back().value.kind == JsonValue::Kind::object &&
        std::find(keep_text_.begin(), keep_text_.end(), stack_.back().key) != keep_text_.end()) {
      v.text = text();
    }
    return add(std::move(v));
  }
  bool add(JsonValue v) {
    if (v.kind == JsonValue::Kind::null) v.offset = offset() == 0 ? 0 : offset() - 1;
    if (stack_.empty()) {
      root = std::move(v);
    } else if (stack_.back().value.kind == JsonValue::Kind::array) {
      stack_.back().value.items.push_back(std::move(v));
    } else {
      stack_.back().value.members.push_back({std::move(stack_.back().key), std::move(v)});
    }
    return true;
  }
  bool close() {
    JsonValue v = std::move(stack_.back().value);
    stack_.pop_back();
    if (stack_.empty()) {
      root = std::move(v);
      return true;
    }
    if (stack_.back().value.kind == JsonValue::Kind::array) {
      stack_.back().value.items.push_back(std::move(v));
    } else {
      stack_.back().value.members.push_back({std::move(stack_.back().key), std::move(v)});
    }
    return true;
  }

  const char* begin_;
  const char** cursor_;
  std::span<const std::string_view> keep_text_;
  std::vector<Open> stack_;
};

}  // namespace

const char* kind_name(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::null:
      return "null";
    case JsonValue::Kind::boolean:
      return "a boolean";
    case JsonValue::Kind::number:
      return "a number";
    case JsonValue::Kind::string:
      return "a string";
    case JsonValue::Kind::array:
      return "an array";
    case JsonValue::Kind::object:
      return "an object";
  }
  return "a value";
}

Result<JsonValue> parse_json_tree(std::string_view text, const std::string& source,
                                  std::span<const std::string_view> keep_text) {
  const char* cursor = nullptr;
  TreeBuilder builder(text.data(), &cursor, keep_text);
  const char* begin = text.data();
  const char* end = begin + text.size();
  bool ok = false;
  try {
    ok = nlohmann::json::sax_parse(TrackingIterator(begin, &cursor), TrackingIterator(end, nullptr),
                                   &builder);
  } catch (const std::exception& ex) {  // allocation failure and the like: still an Error
    return make_error(ErrorKind::parse, std::string("cannot read the JSON: ") + ex.what(), source);
  }
  if (!ok || !builder.root) {
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
      return make_error(ErrorKind::parse, "the input is empty: expected a JSON object", source, 1);
    }
    const ErrorKind kind = builder.overflow_ ? ErrorKind::invalid_value : ErrorKind::parse;
    return make_error(kind, builder.error_, source, line_of_offset(text, builder.error_offset_));
  }
  return std::move(*builder.root);
}

}  // namespace contain::io::detail
