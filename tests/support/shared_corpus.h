#pragma once
/// \file
/// Finds `../shared` (test data with exact answers) beside the project. Tests that read it call
/// `CONTAIN_REQUIRE_SHARED()` first, which skips them with a message in a user's clone.

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

namespace contain::test {

/// The shared folder if it exists (it holds corpus/, spec/, tools/), else nothing.
[[nodiscard]] std::optional<std::filesystem::path> shared_dir();

}  // namespace contain::test

#define CONTAIN_REQUIRE_SHARED()                                                   \
  do {                                                                             \
    if (!::contain::test::shared_dir()) {                                          \
      GTEST_SKIP() << "../shared is absent (a user's clone): corpus test skipped"; \
    }                                                                              \
  } while (false)
