#include "errors.h"

#include <string>

namespace contain::python {
namespace {

const char* kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::usage:
      return "usage";
    case ErrorKind::io:
      return "io";
    case ErrorKind::parse:
      return "parse";
    case ErrorKind::invalid_value:
      return "invalid_value";
    case ErrorKind::degenerate:
      return "degenerate";
    case ErrorKind::unsupported:
      return "unsupported";
  }
  return "invalid_value";
}

// Set once at import; the classes live as long as the interpreter (the module holds them).
PyObject* contain_error = nullptr;
PyObject* contain_io_error = nullptr;

}  // namespace

void fail(ErrorKind kind, std::string message) {
  throw Failure{Error{.kind = kind, .message = std::move(message)}};
}

void register_errors(py::module_& module) {
  // Built with type() so that ContainIOError can derive from both ContainError and OSError, as
  // io.UnsupportedOperation derives from OSError and ValueError.
  const py::object type = py::module_::import("builtins").attr("type");
  py::dict error_body;
  error_body["__module__"] = "contain";
  error_body["__doc__"] =
      "An error reported by the contain library: bad input (a malformed file, NaN coordinates,\n"
      "an index out of range, an empty or degenerate shape) or an unsupported request.\n\n"
      "str(error) is the library's message, 'file:line: message' where a file and line apply.\n"
      "Attributes: kind ('usage', 'io', 'parse', 'invalid_value', 'degenerate', 'unsupported'),\n"
      "message (without the location), source (file name or '' ), line (1-based, 0: none).";
  const py::object error_class =
      type("ContainError", py::make_tuple(py::handle(PyExc_ValueError)), error_body);
  py::dict io_body;
  io_body["__module__"] = "contain";
  // OSError's own __str__ would print "[Errno None] None: <filename>"; keep the library's message.
  io_body["__str__"] = py::module_::import("builtins").attr("BaseException").attr("__str__");
  io_body["__doc__"] =
      "A file could not be opened or read (missing, a directory, unreadable): a ContainError\n"
      "and an OSError. `filename` names the file.";
  const py::object io_class =
      type("ContainIOError", py::make_tuple(error_class, py::handle(PyExc_OSError)), io_body);
  module.attr("ContainError") = error_class;
  module.attr("ContainIOError") = io_class;
  contain_error = error_class.ptr();
  contain_io_error = io_class.ptr();

  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const Failure& failure) {
      const Error& e = failure.error;
      const bool io = e.kind == ErrorKind::io;
      const py::handle cls = io ? contain_io_error : contain_error;
      // OSError(message) keeps str() equal to the message; filename is set as an attribute.
      py::object instance = cls(e.what());
      instance.attr("kind") = kind_name(e.kind);
      instance.attr("message") = e.message;
      instance.attr("source") = e.source;
      instance.attr("line") = e.line;
      if (io) instance.attr("filename") = e.source;
      PyErr_SetObject(cls.ptr(), instance.ptr());
    }
  });
}

void warn_deprecated(const std::string& old_name, const std::string& new_name) {
  const std::string text = old_name + " is deprecated: use " + new_name +
                           " (the name of the C++ function; docs/python.md, Renamed)";
  if (PyErr_WarnEx(PyExc_DeprecationWarning, text.c_str(), 1) != 0) throw py::error_already_set();
}

}  // namespace contain::python
