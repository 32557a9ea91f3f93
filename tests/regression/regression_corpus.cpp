#include "regression/regression_corpus.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/run.h"

namespace contain::test {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

// An argument naming a file of the folder becomes its path; so does the value of `--opt=FILE`.
std::string resolve(const std::filesystem::path& dir, const std::string& arg) {
  if (!arg.empty() && arg.front() != '-' && std::filesystem::is_regular_file(dir / arg)) {
    return (dir / arg).string();
  }
  return arg;
}

}  // namespace

std::optional<std::string> RegressionCase::option(const std::string& flag) const {
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (run[i] == flag && i + 1 < run.size()) return run[i + 1];
    if (run[i].rfind(flag + "=", 0) == 0) return run[i].substr(flag.size() + 1);
  }
  return std::nullopt;
}

std::filesystem::path regression_dir(const std::string& domain) {
  return std::filesystem::path(CONTAIN_SOURCE_DIR) / "tests" / "data" / domain;
}

std::vector<RegressionCase> read_regression_cases(const std::string& domain) {
  const std::filesystem::path dir = regression_dir(domain);
  std::ifstream in(dir / "cases.txt");
  std::vector<RegressionCase> cases;
  if (!in) {
    ADD_FAILURE() << "cannot read " << (dir / "cases.txt");
    return cases;
  }
  std::optional<RegressionCase> open;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line.front() == '#') continue;
    const std::size_t space = line.find(' ');
    const std::string key = line.substr(0, space);
    const std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
    auto words = [&rest] {
      std::vector<std::string> out;
      std::istringstream ws(rest);
      for (std::string w; ws >> w;)
        out.push_back(w);
      return out;
    };
    const std::string where = "cases.txt:" + std::to_string(number) + ": ";
    if (key == "case") {
      if (open) ADD_FAILURE() << where << "case " << open->name << " has no 'end'";
      open = RegressionCase{.name = rest, .line = number};
      continue;
    }
    if (!open) {
      ADD_FAILURE() << where << "'" << key << "' outside a case";
      continue;
    }
    if (key == "run" || key == "lib") {
      std::vector<std::string> args = words();
      for (std::string& a : args) {
        const std::size_t eq = a.find('=');
        if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
          a = a.substr(0, eq + 1) + resolve(dir, a.substr(eq + 1));
        } else {
          a = resolve(dir, a);
        }
      }
      (key == "run" ? open->run : open->lib) = std::move(args);
    } else if (key == "exit") {
      open->exit_code = std::stoi(rest);
    } else if (key == "out") {
      open->out.push_back(rest);
    } else if (key == "err") {
      open->err.push_back(rest);
    } else if (key == "end") {
      if (open->run.empty() == open->lib.empty()) {
        ADD_FAILURE() << where << "case " << open->name << " needs exactly one of 'run' and 'lib'";
      }
      cases.push_back(std::move(*open));
      open.reset();
    } else {
      ADD_FAILURE() << where << "unknown key '" << key << "'";
    }
  }
  if (open) ADD_FAILURE() << "cases.txt: case " << open->name << " has no 'end'";
  return cases;
}

void expect_cli_gives_recorded_answer(const RegressionCase& c) {
  SCOPED_TRACE("case " + c.name + " (cases.txt:" + std::to_string(c.line) + ")");
  const CliRun r = run_contain(c.run);
  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  EXPECT_EQ(split_lines(r.out), c.out);
  for (const std::string& fragment : c.err) {
    EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr lacks '" << fragment << "':\n"
                                                       << r.err;
  }
}

void expect_every_file_has_a_case(const std::string& domain,
                                  const std::vector<RegressionCase>& cases) {
  std::set<std::string> named;
  for (const RegressionCase& c : cases) {
    bool any = false;
    for (const auto* args : {&c.run, &c.lib}) {
      for (const std::string& a : *args) {
        const std::string value = a.substr(a.rfind("--", 0) == 0 ? a.find('=') + 1 : 0);
        const std::filesystem::path p(value);
        if (p.is_absolute() && std::filesystem::is_regular_file(p)) {
          named.insert(p.filename().string());
          any = true;
        }
      }
    }
    EXPECT_TRUE(any) << "case " << c.name << " names no file of tests/data/" << domain;
  }
  for (const auto& entry : std::filesystem::directory_iterator(regression_dir(domain))) {
    const std::string name = entry.path().filename().string();
    if (name == "README.md" || name == "cases.txt") continue;
    EXPECT_TRUE(named.count(name))
        << "tests/data/" << domain << "/" << name << " is named by no case of cases.txt";
  }
}

}  // namespace contain::test
