#include "muparser_function.h"

#include <muParser.h>

#include <limits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace contain::io::detail {
namespace {

// One parser bound to its own x, y, z (muparser keeps pointers to them: never moved).
struct Evaluator {
  mu::Parser parser;
  double x = 0, y = 0, z = 0;

  explicit Evaluator(const std::string& expression) {
    parser.DefineVar("x", &x);
    parser.DefineVar("y", &y);
    parser.DefineVar("z", &z);
    parser.SetExpr(expression);
  }
};

// muparser parsers are not safe to share between threads (evaluation writes a stack in the
// parser); a pool hands each concurrent caller its own. The pool grows to the number of
// threads that ever evaluate at once and is shared by copies of the function.
struct Pool {
  std::string expression;
  std::mutex mutex;
  std::vector<std::unique_ptr<Evaluator>> idle;

  std::unique_ptr<Evaluator> take() {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!idle.empty()) {
        std::unique_ptr<Evaluator> e = std::move(idle.back());
        idle.pop_back();
        return e;
      }
    }
    return std::make_unique<Evaluator>(expression);
  }
  void give_back(std::unique_ptr<Evaluator> e) {
    const std::lock_guard<std::mutex> lock(mutex);
    idle.push_back(std::move(e));
  }
};

}  // namespace

Result<ImplicitFunction> compile_expression(const std::string& expression) {
  auto pool = std::make_shared<Pool>();
  pool->expression = expression;
  try {
    auto first = std::make_unique<Evaluator>(expression);
    static_cast<void>(first->parser.Eval());  // muparser checks the syntax on first evaluation
    if (first->parser.GetNumResults() != 1) {
      return Error{ErrorKind::parse,
                   "expected one expression, got " + std::to_string(first->parser.GetNumResults())};
    }
    pool->idle.push_back(std::move(first));
  } catch (const mu::Parser::exception_type& e) {
    return Error{ErrorKind::parse, e.GetMsg() + " (at position " + std::to_string(e.GetPos()) +
                                       " of \"" + expression + "\")"};
  }
  return ImplicitFunction([pool](Vec3 p) {
    std::unique_ptr<Evaluator> e;
    double value = std::numeric_limits<double>::quiet_NaN();
    try {
      e = pool->take();
      e->x = p.x;
      e->y = p.y;
      e->z = p.z;
      value = e->parser.Eval();
    } catch (...) {  // nothing may cross the library boundary; NaN is `outside`
      value = std::numeric_limits<double>::quiet_NaN();
    }
    try {
      if (e) pool->give_back(std::move(e));
    } catch (...) {  // out of memory: the evaluator is dropped, the pool makes another later
    }
    return value;
  });
}

}  // namespace contain::io::detail
