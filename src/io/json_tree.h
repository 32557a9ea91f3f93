#pragma once
// A JSON document as a small tree whose values remember where they were read, for readers that
// must name the line of every semantic error (GeoJSON). nlohmann-json's DOM keeps no positions,
// so the text goes through its SAX parser.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/result.h"

namespace contain::io::detail {

// Each value remembers the byte offset where the parser stood when it was read (the end of its
// first token): enough to name the line of every semantic error. `text` holds a string's text,
// and for a number the text as written when it is the value of a member named in `keep_text`.
struct JsonMember;

struct JsonValue {
  enum class Kind : std::uint8_t { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  double number = 0.0;
  std::string text;
  std::vector<JsonValue> items;
  std::vector<JsonMember> members;
  std::size_t offset = 0;

  [[nodiscard]] const JsonValue* member(std::string_view name) const;
};

// A named struct rather than std::pair<std::string, JsonValue>, and member() out of the
// class: clang with libstdc++ rejects the pair of a still incomplete JsonValue.
struct JsonMember {
  std::string key;
  JsonValue value;
};

/// "null", "a boolean", "a number", ... for messages.
[[nodiscard]] const char* kind_name(JsonValue::Kind kind);

/// Parses `text` (BOM already skipped) into a tree. Errors name `source` and the line:
/// ErrorKind::parse for malformed JSON (nlohmann-json's description), an empty input or nesting
/// deeper than 256 levels; ErrorKind::invalid_value for a number too large for a double.
/// Numbers are correctly rounded (std::from_chars); those that are the value of a member named
/// in `keep_text` also keep their text as written.
[[nodiscard]] Result<JsonValue> parse_json_tree(std::string_view text, const std::string& source,
                                                std::span<const std::string_view> keep_text = {});

}  // namespace contain::io::detail
