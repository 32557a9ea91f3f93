#pragma once
/// \file
/// Errors as values: every place where user input enters the library returns `Result<T>`.

#include <cstdint>
#include <string>
#include <utility>
#include <variant>

namespace contain {

/// What kind of failure an `Error` reports; the CLI maps `usage` to exit code 2 and every other
/// kind to exit code 3.
enum class ErrorKind : std::uint8_t {
  usage,          ///< the caller asked for something meaningless (bad option value)
  io,             ///< a file could not be opened or read
  parse,          ///< a file or string is malformed
  invalid_value,  ///< a number is NaN or infinite, an index is out of range, a count is wrong
  degenerate,     ///< the shape is empty or degenerate where a proper one is required
  unsupported,    ///< valid input that this version does not handle (a WKT type, a PLY property)
};

/// A failure with a message a user can act on. `source` names the file (or "<stdin>", or the
/// argument) and `line` its 1-based line where one applies (0: none).
struct Error {
  ErrorKind kind = ErrorKind::invalid_value;
  std::string message;
  std::string source;
  std::int64_t line = 0;

  /// "source:line: message", leaving out what is unknown.
  [[nodiscard]] std::string what() const {
    std::string out;
    if (!source.empty()) {
      out += source;
      if (line > 0) out += ":" + std::to_string(line);
      out += ": ";
    }
    out += message;
    return out;
  }
};

/// Either a value or an `Error`. Deliberately small: `ok()`, `value()`, `error()`.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
  Result(Error error) : state_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool ok() const { return state_.index() == 0; }
  explicit operator bool() const { return ok(); }

  /// Precondition: ok().
  [[nodiscard]] T& value() & { return std::get<0>(state_); }
  [[nodiscard]] const T& value() const& { return std::get<0>(state_); }
  [[nodiscard]] T&& value() && { return std::get<0>(std::move(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

  /// Precondition: !ok().
  [[nodiscard]] const Error& error() const { return std::get<1>(state_); }

 private:
  std::variant<T, Error> state_;
};

/// `Result` for operations that produce nothing but can fail.
struct Ok {};
using Status = Result<Ok>;

}  // namespace contain
