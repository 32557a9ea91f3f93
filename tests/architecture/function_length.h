#pragma once
// The function-length check of tests/architecture (issue 23: no function in src/ over 120
// lines): finds function bodies by brace matching on the code of each file (comments, strings
// and preprocessor lines aside) and reports those longer than a limit, counted from the first
// line of the signature to the closing brace.

#include <string>
#include <vector>

#include "architecture/layering.h"

namespace contain::test {

/// One line per function of `files` longer than `max_lines` lines ("src/a.cpp:12: 130 lines:
/// void f(int x)"). A function is a brace block at namespace or class scope whose head (the
/// text since the previous `;`, `}` or `{` of that scope) ends in `)`, possibly followed by
/// `const`, `noexcept`, `override`, `final`, `mutable`, `&` or a trailing return type; lambdas
/// and local classes count as part of the function around them. Brace initializers (of a member
/// in a constructor's list, of an array) are not bodies.
[[nodiscard]] std::vector<std::string> check_function_lengths(const std::vector<SourceFile>& files,
                                                              int max_lines);

}  // namespace contain::test
