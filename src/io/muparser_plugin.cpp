// libcontain_muparser.so: muparser behind the C entry points of io/muparser_plugin.h, opened by
// contain::io on the first expression compiled.

#include <muParser.h>

#include <limits>
#include <memory>
#include <string>

#include "io/muparser_plugin.h"

namespace {

// One parser bound to its own x, y, z (muparser keeps pointers to them: never moved).
struct Evaluator {
  mu::Parser parser;
  double x = 0, y = 0, z = 0;
  std::string error;  // empty when the expression compiled
};

}  // namespace

extern "C" CONTAIN_MUPARSER_PLUGIN_EXPORT const char* contain_muparser_plugin_id() {
  return contain::io::detail::muparser_plugin_id;
}

extern "C" CONTAIN_MUPARSER_PLUGIN_EXPORT void* contain_muparser_compile(const char* expression) {
  try {
    auto e = std::make_unique<Evaluator>();
    try {
      e->parser.DefineVar("x", &e->x);
      e->parser.DefineVar("y", &e->y);
      e->parser.DefineVar("z", &e->z);
      e->parser.SetExpr(expression);
      static_cast<void>(e->parser.Eval());  // muparser checks the syntax on first evaluation
      if (e->parser.GetNumResults() != 1) {
        e->error = "expected one expression, got " + std::to_string(e->parser.GetNumResults());
      }
    } catch (const mu::Parser::exception_type& x) {
      e->error = x.GetMsg() + " (at position " + std::to_string(x.GetPos()) + " of \"" +
                 expression + "\")";
    }
    return e.release();
  } catch (...) {  // out of memory: nothing may cross the boundary
    return nullptr;
  }
}

extern "C" CONTAIN_MUPARSER_PLUGIN_EXPORT const char* contain_muparser_error(
    const void* evaluator) {
  const auto* e = static_cast<const Evaluator*>(evaluator);
  return e->error.empty() ? nullptr : e->error.c_str();
}

extern "C" CONTAIN_MUPARSER_PLUGIN_EXPORT double contain_muparser_evaluate(void* evaluator,
                                                                           double x, double y,
                                                                           double z) {
  auto* e = static_cast<Evaluator*>(evaluator);
  try {
    e->x = x;
    e->y = y;
    e->z = z;
    return e->parser.Eval();
  } catch (...) {  // NaN is `outside`
    return std::numeric_limits<double>::quiet_NaN();
  }
}

extern "C" CONTAIN_MUPARSER_PLUGIN_EXPORT void contain_muparser_release(void* evaluator) {
  delete static_cast<Evaluator*>(evaluator);
}
