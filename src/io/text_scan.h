#pragma once
/// \file
/// Private helpers shared by the readers and writers of contain::io: whole-file reading, number
/// parsing with std::from_chars (correctly rounded, NaN/Inf rejected), shortest round-trip
/// formatting as std::to_chars writes it, and errors that name the source and line.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "contain/core/result.h"
#include "io/shortest_double.h"

namespace contain::io::detail {

/// The name of a file in messages: its path as given.
[[nodiscard]] std::string source_name(const std::filesystem::path& path);

/// The name of a GDAL source in messages: as given, but a connection string's password shown
/// as `***` in every form libpq takes: `password=...` (quoted or not, also as a URI query
/// parameter) and the user information of a URI (`postgresql://user:secret@host`).
[[nodiscard]] std::string connection_name(const std::string& source);

/// `message` (a driver's words, which may quote the source) with every password of `source`
/// hidden, as connection_name hides it.
[[nodiscard]] std::string hide_secrets(const std::string& message, const std::string& source);

/// The whole content of a file (binary-safe). Errors: ErrorKind::io naming the path (missing,
/// a directory, unreadable).
[[nodiscard]] Result<std::string> read_file(const std::filesystem::path& path);

/// A file, or standard input for the path "-", read a block at a time: a long file costs the
/// block in memory, not its size. Opening gives read_file's errors.
class BlockInput {
 public:
  [[nodiscard]] static Result<BlockInput> open(const std::filesystem::path& path);
  BlockInput(BlockInput&& other) noexcept;
  BlockInput& operator=(BlockInput&& other) = delete;
  BlockInput(const BlockInput&) = delete;
  BlockInput& operator=(const BlockInput&) = delete;
  ~BlockInput();

  /// Reads up to `bytes` bytes into `to`; the count read, 0 at the end. ErrorKind::io when
  /// reading fails.
  [[nodiscard]] Result<std::size_t> read(char* to, std::size_t bytes);
  /// The name in messages: the path, or "<stdin>".
  [[nodiscard]] const std::string& source() const { return source_; }
  /// The file's size in bytes when known (a regular file), else 0.
  [[nodiscard]] std::uintmax_t size() const { return size_; }
  /// The open file, for MappedText::map.
  [[nodiscard]] std::FILE* file() const { return file_; }

 private:
  BlockInput(std::FILE* file, std::string source, std::uintmax_t size)
      : file_(file), source_(std::move(source)), size_(size) {}
  std::FILE* file_;
  std::string source_;
  std::uintmax_t size_;
};

/// A regular file's bytes mapped into memory read-only, in place of read() into a buffer: the
/// kernel's copy of every byte is saved, but each page's first touch is a fault (dearer than the
/// copy on the project's virtual machine), so the point reader maps only when asked
/// (io::ChunkedReading::map). Pages are made present a window ahead of the reader (`reach`) and
/// dropped from the mapping behind it (`release`), so a file of gigabytes holds a few windows of
/// memory, as the read() blocks do (the page cache keeps them either way). A file cut shorter while
/// it is mapped ends the process by SIGBUS, as for every program that maps its input; bytes
/// appended after the mapping are not read.
class MappedText {
 public:
  /// The open file `file` (its whole size, `size` bytes, 1 or more) mapped; nothing when it
  /// cannot be (not a regular file, a platform without mmap, a failed call): then read() it.
  [[nodiscard]] static std::optional<MappedText> map(std::FILE* file, std::uintmax_t size);
  MappedText(MappedText&& other) noexcept;
  MappedText& operator=(MappedText&& other) = delete;
  MappedText(const MappedText&) = delete;
  MappedText& operator=(const MappedText&) = delete;
  ~MappedText();

  /// The file's bytes.
  [[nodiscard]] std::string_view text() const { return {data_, size_}; }
  /// Makes the bytes before `to` present in memory, a window at a time ahead of it. False when
  /// the system says those pages cannot be read (the file shortened since it was mapped, or a
  /// read error): touching them would end the process (SIGBUS), so the reader stops first.
  [[nodiscard]] bool reach(std::size_t to);
  /// Drops the pages wholly before `from` from the mapping (their text is no longer used).
  void release(std::size_t from);

 private:
  MappedText(const char* data, std::size_t size) : data_(data), size_(size) {}
  const char* data_;
  std::size_t size_;
  std::size_t present_ = 0;   // bytes made present
  std::size_t released_ = 0;  // bytes dropped
};

/// The whole content of a stream; ErrorKind::io when the stream fails before its end.
[[nodiscard]] Result<std::string> read_stream(std::istream& in, const std::string& source);

/// Writes `bytes` to `path`, replacing it; ErrorKind::io when that fails.
[[nodiscard]] Status write_file(const std::filesystem::path& path, std::string_view bytes);

/// An Error with every field set.
[[nodiscard]] Error make_error(ErrorKind kind, std::string message, const std::string& source,
                               std::int64_t line = 0);

/// What `parse_double` found.
enum class NumberStatus : std::uint8_t {
  ok,
  not_a_number,  ///< no number starts here (nothing consumed)
  not_finite,    ///< "nan", "inf", "infinity" or a value that overflows to infinity
};

/// Parses one decimal number at `p` (an optional '+' or '-', then std::from_chars' general
/// format), advancing `p` past it on success and on `not_finite`. Correctly rounded: underflow
/// gives the correctly rounded subnormal or zero. Does not check what follows the number.
[[nodiscard]] NumberStatus parse_double(const char*& p, const char* end, double& out);

/// Parses an optionally signed decimal integer at `p`; false (nothing consumed) when none starts
/// here or it does not fit in int64.
[[nodiscard]] bool parse_int64(const char*& p, const char* end, std::int64_t& out);

/// Room for the shortest form of a double (at most 24 characters: sign, 17 digits, point,
/// "e-308") and the scratch of its writer (io/shortest_double.h).
inline constexpr auto kMaxDoubleChars = static_cast<std::size_t>(kShortestDoubleRoom);

/// Shortest decimal that reads back as exactly `value`, the bytes of std::to_chars, written at
/// `at` (room for kMaxDoubleChars): the end of what was written.
char* write_double(char* at, double value);

/// Shortest decimal that reads back as exactly `value` (std::to_chars), appended to `out`.
void append_double(std::string& out, double value);

/// A number as a layer's id, the same whichever reader met it (GeoJSON text, a GDAL field): a
/// whole number of magnitude below 2^63 in plain digits ("3.0", "3e0" and the integer 3 all
/// give "3"), any other the shortest decimal that reads back as the same double.
[[nodiscard]] std::string number_id(double value);

/// A short quote of the text at `p` for messages: `'abc'`, or "the end of the line/file".
[[nodiscard]] std::string quote_token(const char* p, const char* end);

/// The 1-based line of byte `offset` in `text`.
[[nodiscard]] std::int64_t line_of_offset(std::string_view text, std::size_t offset);

/// Drops a UTF-8 byte order mark.
[[nodiscard]] std::string_view skip_bom(std::string_view text);

/// Lower-case ASCII copy of an extension (".OBJ" -> ".obj").
[[nodiscard]] std::string lower_extension(const std::filesystem::path& path);

[[nodiscard]] constexpr bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
[[nodiscard]] constexpr bool is_space(char c) {
  return is_blank(c) || c == '\n';
}

/// Advances `p` over blanks (not newlines).
inline void skip_blanks(const char*& p, const char* end) {
  while (p != end && is_blank(*p))
    ++p;
}

}  // namespace contain::io::detail
