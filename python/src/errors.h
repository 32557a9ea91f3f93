#pragma once
/// \file
/// Library errors as Python exceptions: `contain.ContainError` (a ValueError) and, for files
/// that cannot be opened or read, `contain.ContainIOError` (a ContainError and an OSError).

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "contain/core/result.h"

namespace contain::python {

namespace py = pybind11;

/// Thrown by the bindings, translated to ContainError / ContainIOError carrying the library's
/// message ("file:line: message") and the attributes kind, source, line, message.
struct Failure {
  Error error;
};

/// Creates the two exception classes in `module` and registers the translator of `Failure`.
void register_errors(py::module_& module);

/// The value of `result`, or throws `Failure` with its error.
template <class T>
[[nodiscard]] T take(Result<T>&& result) {
  if (!result.ok()) throw Failure{result.error()};
  return std::move(result).value();
}

/// Throws `Failure` of kind `kind` with `message`.
[[noreturn]] void fail(ErrorKind kind, std::string message);

/// Issues a DeprecationWarning "`old_name` is deprecated: use `new_name`" pointing at the
/// caller's line (an error when warnings are errors: error_already_set).
void warn_deprecated(const std::string& old_name, const std::string& new_name);

}  // namespace contain::python
