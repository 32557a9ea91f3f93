// Built with the flags of the installed contain.pc only (no CMake), as a Makefile user would.
#include <contain/contain.h>

int main() {
  const contain::Sign s = contain::predicates::orient2d({0, 0}, {1, 0}, {0.5, 0});
  return s == contain::Sign::zero ? 0 : 1;
}
