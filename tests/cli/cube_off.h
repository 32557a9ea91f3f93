#pragma once
// A closed, outward-oriented cube [0, size]^3 as OFF text, for the end-to-end tests of solids.

#include <string>

namespace contain::test {

inline std::string cube_off(double size) {
  std::string out = "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i) {
    out += std::to_string((i & 1) ? size : 0.0) + " " + std::to_string((i & 2) ? size : 0.0) + " " +
           std::to_string((i & 4) ? size : 0.0) + "\n";
  }
  out +=
      "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n"
      "3 1 3 7\n3 1 7 5\n";
  return out;
}

}  // namespace contain::test
