#include "check.h"

#include <cstdio>
#include <cstdlib>

namespace bsim {

void expectation_failed(const char* file, int line, const char* condition, const char* message) {
  std::fprintf(stderr, "%s:%d: internal error: %s (expected: %s)\n", file, line, message, condition);
  std::fflush(stderr);
  std::abort();
}

}  // namespace bsim
