#include "support/shared_corpus.h"

namespace contain::test {

std::optional<std::filesystem::path> shared_dir() {
  std::filesystem::path dir = std::filesystem::path(CONTAIN_SHARED_DIR);
  std::error_code ec;
  if (std::filesystem::is_directory(dir / "corpus", ec)) return std::filesystem::canonical(dir, ec);
  return std::nullopt;
}

}  // namespace contain::test
