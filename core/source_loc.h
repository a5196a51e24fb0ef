#pragma once
// Where a token came from, kept on every parsed entity so errors found after simulation still
// point at the line and column the user typed.
#include <string>

namespace bsim {

struct SourceLoc {
  int line = 0;    ///< 1-based; 0 means "no location" (built-in defaults)
  int column = 0;  ///< 1-based, in bytes
  bool known() const { return line > 0; }
};

}  // namespace bsim
