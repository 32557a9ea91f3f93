#include "architecture/function_length.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <string_view>

// Outline: blank comments, strings and preprocessor lines (code_only, then `#` lines); walk the
// brace blocks of each scope; recurse into namespaces, classes and `extern` blocks; a block whose
// head ends like a signature is a function body, measured and not entered; any other block (an
// initializer) is skipped and its scope's head goes on.

namespace contain::test {
namespace {

// Preprocessor lines (and their continuations) blanked, newlines kept.
std::string without_preprocessor(std::string code) {
  bool directive = false;
  std::size_t line = 0;
  for (std::size_t i = 0; i <= code.size(); ++i) {
    if (i < code.size() && code[i] != '\n') continue;
    const std::string_view text = std::string_view(code).substr(line, i - line);
    const std::size_t first = text.find_first_not_of(" \t");
    directive = directive || (first != std::string_view::npos && text[first] == '#');
    if (directive) std::fill(code.begin() + line, code.begin() + i, ' ');
    directive = directive && text.ends_with('\\');
    line = i + 1;
  }
  return code;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
    s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
    s.remove_suffix(1);
  return s;
}

bool has_word(std::string_view head, std::string_view word) {
  for (std::size_t at = head.find(word); at != std::string_view::npos;
       at = head.find(word, at + 1)) {
    const auto is_name = [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    const bool before = at == 0 || !is_name(head[at - 1]);
    const bool after = at + word.size() == head.size() || !is_name(head[at + word.size()]);
    if (before && after) return true;
  }
  return false;
}

// The head ends like a function's signature: `)` after trailing qualifiers and return type.
bool ends_like_signature(std::string_view head) {
  const std::size_t close = head.rfind(')');
  if (close == std::string_view::npos) return false;
  std::string_view tail = head.substr(close + 1);
  if (const std::size_t arrow = tail.find("->"); arrow != std::string_view::npos)
    tail = tail.substr(0, arrow);
  constexpr std::array<std::string_view, 6> kQualifiers = {"const", "noexcept", "override",
                                                           "final", "mutable",  "&"};
  for (tail = trimmed(tail); !tail.empty(); tail = trimmed(tail)) {
    const auto q = std::find_if(kQualifiers.begin(), kQualifiers.end(),
                                [&](std::string_view w) { return tail.starts_with(w); });
    if (q == kQualifiers.end()) return false;
    tail.remove_prefix(q->size());
  }
  return true;
}

bool is_scope(std::string_view head) {
  if (head.find('(') != std::string_view::npos) return false;
  return has_word(head, "namespace") || has_word(head, "class") || has_word(head, "struct") ||
         has_word(head, "union") || has_word(head, "enum") || has_word(head, "extern");
}

struct Scanner {
  const SourceFile& file;
  const std::string& code;
  int max_lines;
  std::vector<std::string>& problems;

  std::size_t matching_brace(std::size_t open, std::size_t end) const {
    int depth = 0;
    for (std::size_t j = open; j < end; ++j) {
      if (code[j] == '{') ++depth;
      if (code[j] == '}' && --depth == 0) return j;
    }
    return end;
  }

  int line_of(std::size_t at) const {
    return 1 + static_cast<int>(std::count(code.begin(), code.begin() + at, '\n'));
  }

  void scope(std::size_t begin, std::size_t end) {
    std::size_t head_start = begin;
    for (std::size_t i = begin; i < end; ++i) {
      if (code[i] == ';' || code[i] == '}') head_start = i + 1;
      if (code[i] != '{') continue;
      const std::size_t close = matching_brace(i, end);
      const std::string_view head =
          trimmed(std::string_view(code).substr(head_start, i - head_start));
      if (is_scope(head)) {
        scope(i + 1, close);
      } else if (ends_like_signature(head) && !head.ends_with('=')) {
        measure(head, close);
      } else {
        i = close;  // an initializer: the scope's head goes on past it
        continue;
      }
      i = close;
      head_start = close + 1;
    }
  }

  void measure(std::string_view head, std::size_t close) {
    const std::size_t start = static_cast<std::size_t>(head.data() - code.data());
    const int first = line_of(start), lines = line_of(close) - first + 1;
    if (lines <= max_lines) return;
    std::string signature(head.substr(0, std::min<std::size_t>(head.size(), 80)));
    std::replace(signature.begin(), signature.end(), '\n', ' ');
    problems.push_back(file.path + ":" + std::to_string(first) + ": " + std::to_string(lines) +
                       " lines (at most " + std::to_string(max_lines) + "): " + signature);
  }
};

}  // namespace

std::vector<std::string> check_function_lengths(const std::vector<SourceFile>& files,
                                                int max_lines) {
  std::vector<std::string> problems;
  for (const SourceFile& file : files) {
    const std::string code = without_preprocessor(code_only(file.text));
    Scanner{file, code, max_lines, problems}.scope(0, code.size());
  }
  return problems;
}

}  // namespace contain::test
