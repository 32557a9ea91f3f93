#pragma once
/// \file
/// A file in the temporary directory, removed when the object goes (tests of file readers).

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

namespace contain::test {

class TempFile {
 public:
  /// A new file named `<stem>-<pid>-<n><extension>` holding `bytes`.
  TempFile(std::string_view extension, std::string_view bytes) {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("contain-io-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
             std::string(extension));
    std::ofstream out(path_, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  /// A path that does not exist yet (for writers), with this extension.
  explicit TempFile(std::string_view extension) : TempFile(extension, "") {
    std::filesystem::remove(path_);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace contain::test
