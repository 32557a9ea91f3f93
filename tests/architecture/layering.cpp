#include "architecture/layering.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

namespace contain::test {
namespace {

std::string trim(std::string_view s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) return "";
  const auto end = s.find_last_not_of(" \t\r");
  return std::string(s.substr(begin, end - begin + 1));
}

std::vector<std::string> split(std::string_view s, std::string_view separator) {
  std::vector<std::string> parts;
  std::size_t at = 0;
  while (true) {
    const std::size_t next = s.find(separator, at);
    parts.push_back(trim(s.substr(at, next == std::string_view::npos ? next : next - at)));
    if (next == std::string_view::npos) break;
    at = next + separator.size();
  }
  return parts;
}

// Where a file lives: its domain, and whether it is a public header of the library.
struct Place {
  std::string domain;  // empty: not a checked file
  bool public_header = false;
};

Place place_of(std::string_view path) {
  const auto first = [](std::string_view rest) {
    return std::string(rest.substr(0, rest.find('/')));
  };
  if (path == "include/contain/contain.h") return {};
  if (path.starts_with("include/contain/")) {
    const std::string_view rest = path.substr(16);
    if (rest.find('/') == std::string_view::npos) return {};
    return {first(rest), path.ends_with(".h")};
  }
  if (path.starts_with("src/")) {
    const std::string_view rest = path.substr(4);
    if (rest.find('/') == std::string_view::npos) return {};
    return {first(rest), false};
  }
  if (path.starts_with("cli/")) return {"cli", false};
  if (path.starts_with("python/src/")) return {"python", false};
  if (path.starts_with("scenes/")) return {"scenes", false};
  return {};
}

}  // namespace

std::string code_only(std::string_view text) {
  std::string out(text);
  enum class State { code, line_comment, block_comment, string, character } state = State::code;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    switch (state) {
      case State::code:
        if (c == '/' && next == '/') {
          state = State::line_comment;
          out[i] = ' ';
        } else if (c == '/' && next == '*') {
          state = State::block_comment;
          out[i] = ' ';
        } else if (c == '"') {
          state = State::string;
        } else if (c == '\'') {
          state = State::character;
        }
        break;
      case State::line_comment:
        if (c == '\n') {
          state = State::code;
        } else {
          out[i] = ' ';
        }
        break;
      case State::block_comment:
        if (c == '*' && next == '/') {
          out[i] = out[i + 1] = ' ';
          ++i;
          state = State::code;
        } else if (c != '\n') {
          out[i] = ' ';
        }
        break;
      case State::string:
      case State::character:
        if (c == '\\') {
          out[i] = ' ';
          if (i + 1 < out.size()) out[++i] = ' ';
        } else if (c == (state == State::string ? '"' : '\'')) {
          state = State::code;
        } else if (c != '\n') {
          out[i] = ' ';
        }
        break;
    }
  }
  return out;
}

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string relation(const LayerOrder& order, std::string_view from, std::string_view to) {
  return order.level_of(to) == order.level_of(from) ? "a sibling layer" : "a higher layer";
}

}  // namespace

int LayerOrder::level_of(std::string_view domain) const {
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (std::find(levels[i].begin(), levels[i].end(), domain) != levels[i].end()) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

LayerOrder parse_layer_order(std::string_view line) {
  LayerOrder order;
  for (const std::string& level : split(line, "->")) {
    std::vector<std::string> domains;
    for (const std::string& domain : split(level, ",")) {
      if (!domain.empty()) domains.push_back(domain);
    }
    if (!domains.empty()) order.levels.push_back(std::move(domains));
  }
  return order;
}

LayerOrder layer_order_from_doc(std::string_view doc) {
  const std::string_view marker = "<!-- layer-order -->";
  const std::size_t at = doc.find(marker);
  if (at == std::string_view::npos) return {};
  std::istringstream lines{std::string(doc.substr(at + marker.size()))};
  std::string line;
  while (std::getline(lines, line)) {
    const std::string text = trim(line);
    if (text.empty() || text.starts_with("```")) continue;
    return parse_layer_order(text);
  }
  return {};
}

std::vector<std::string> check_layering(const LayerOrder& order,
                                        const std::vector<SourceFile>& files) {
  std::vector<std::string> problems;
  const std::regex include_line(R"re(^\s*#\s*include\s*["<]([^">]+)[">])re");
  const std::regex include_directive(R"(^\s*#\s*include)");
  const std::regex qualified(R"re(\b([a-z_]+)::)re");
  for (const SourceFile& file : files) {
    const Place here = place_of(file.path);
    if (here.domain.empty()) continue;
    const int level = order.level_of(here.domain);
    if (level < 0) {
      problems.push_back(file.path + ": the folder '" + here.domain +
                         "' is not in the layer order (docs/architecture.md)");
      continue;
    }
    const std::vector<std::string> original = lines_of(file.text);
    const std::vector<std::string> code = lines_of(code_only(file.text));
    for (std::size_t k = 0; k < code.size(); ++k) {
      const std::string& line = code[k];
      const std::string where = file.path + ":" + std::to_string(k + 1) + ": ";
      std::smatch m;
      // An include outside comments; its path (a string literal, blanked in `code`) is read from
      // the original line.
      if (std::regex_search(line, include_directive)) {
        if (!std::regex_search(original[k], m, include_line)) continue;
        const std::string target = m[1];
        if (target.starts_with("contain/")) {
          const std::string rest = target.substr(8);
          const auto slash = rest.find('/');
          if (slash == std::string::npos) continue;  // the umbrella contain/contain.h
          const std::string domain = rest.substr(0, slash);
          const int other = order.level_of(domain);
          if (domain != here.domain && (other < 0 || other >= level)) {
            problems.push_back(where + "includes " + target + ", a header of " +
                               (other < 0 ? std::string("a folder not in the layer order")
                                          : relation(order, here.domain, domain)) +
                               " (" + domain + ") in " + here.domain);
          }
        } else if (const auto slash = target.find('/'); slash != std::string::npos) {
          const std::string domain = target.substr(0, slash);
          const int other = order.level_of(domain);
          if (other < 0 || domain == here.domain) continue;  // not a domain of the tree
          if (domain == "scenes") {  // scenes/ is its own public include directory
            if (other >= level) {
              problems.push_back(where + "includes " + target + ", a header of " +
                                 relation(order, here.domain, domain) + " (" + domain + ") in " +
                                 here.domain);
            }
            continue;
          }
          problems.push_back(where + "includes " + target + ", a private header of " + domain +
                             " (src/" + domain + "/), in " + here.domain +
                             ": give it a public header in the right layer");
        }
        continue;
      }
      if (!here.public_header) continue;
      for (auto it = std::sregex_iterator(line.begin(), line.end(), qualified);
           it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1];
        if (name == here.domain) continue;
        const int other = order.level_of(name);
        if (other >= level) {
          problems.push_back(where + "names " + name + "::, a namespace of " +
                             relation(order, here.domain, name) + ", in a public header of " +
                             here.domain);
        }
      }
    }
  }
  return problems;
}

std::vector<std::string> check_link_order(const LayerOrder& order,
                                          const std::vector<SourceFile>& lists) {
  std::vector<std::string> problems;
  const std::regex library(R"(\bcontain_([a-z_]+)\b)");
  for (const SourceFile& list : lists) {
    const Place here = place_of(list.path);
    const int level = order.level_of(here.domain);
    if (level < 0) {
      problems.push_back(list.path + ": the folder '" + here.domain +
                         "' is not in the layer order (docs/architecture.md)");
      continue;
    }
    const std::string code = list.text;
    const std::size_t deps = code.find("DEPS");
    if (deps == std::string::npos) continue;
    const std::string tail = code.substr(deps, code.find(')', deps) - deps);
    for (auto it = std::sregex_iterator(tail.begin(), tail.end(), library);
         it != std::sregex_iterator(); ++it) {
      const std::string domain = (*it)[1];
      const int other = order.level_of(domain);
      if (other >= level || other < 0) {
        problems.push_back(
            list.path + ": links contain_" + domain + ", " +
            (other < 0 ? std::string("not a layer") : relation(order, here.domain, domain)) +
            " of " + here.domain);
      }
    }
  }
  return problems;
}

}  // namespace contain::test
