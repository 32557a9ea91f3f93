#pragma once
// The layering check of tests/architecture: reads the includes and, in public headers, the
// namespace-qualified names of every file of the library, the CLI and the Python module, and
// reports each use of a higher (or sibling) layer and each include of another domain's private
// header. The layer order is read from docs/architecture.md, where it is written once.

#include <string>
#include <string_view>
#include <vector>

namespace contain::test {

/// The layers, lowest first; each level holds one or more sibling domains, which may not use
/// each other.
struct LayerOrder {
  std::vector<std::vector<std::string>> levels;

  /// The level of a domain, or -1 if it is not in the order.
  [[nodiscard]] int level_of(std::string_view domain) const;
};

/// Parses "core -> values -> bvh, bound -> ..." (levels separated by "->", siblings by ",").
[[nodiscard]] LayerOrder parse_layer_order(std::string_view line);

/// The order from a document: the first line after the marker "<!-- layer-order -->" that is
/// not a code fence. Empty levels when the marker is missing.
[[nodiscard]] LayerOrder layer_order_from_doc(std::string_view doc);

/// One file of the tree: its path relative to the project root and its text.
struct SourceFile {
  std::string path;
  std::string text;
};

/// `text` with comments and string and character literals blanked out (same length, newlines
/// kept), so that names and braces in them are not taken for code.
[[nodiscard]] std::string code_only(std::string_view text);

/// Every violation in `files`, one readable line each ("src/clip/a.cpp:12: includes ..."):
/// - a file in include/contain/<d>/, src/<d>/, cli/, python/src/ or scenes/ whose domain is not
///   in the order;
/// - an include of a public header ("contain/<d>/...") of a higher or sibling layer;
/// - an include of another domain's private header ("<d>/..." of src/<d>/);
/// - in a public header of include/contain/<d>/, a name qualified by the namespace of a higher or
///   sibling layer (`shapes::Polygon` in a predicates header), comments and strings aside.
/// include/contain/contain.h, the umbrella of the library, is exempt.
[[nodiscard]] std::vector<std::string> check_layering(const LayerOrder& order,
                                                      const std::vector<SourceFile>& files);

/// The library target of each src/<d>/CMakeLists.txt may link only lower layers: each
/// "contain_<x>" after DEPS must be of a lower level than <d>. `lists` holds those files (path
/// src/<d>/CMakeLists.txt).
[[nodiscard]] std::vector<std::string> check_link_order(const LayerOrder& order,
                                                        const std::vector<SourceFile>& lists);

}  // namespace contain::test
