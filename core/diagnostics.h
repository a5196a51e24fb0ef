#pragma once
// User errors and warnings as values: `path:line:col: error: message`.
#include <string>
#include <string_view>
#include <vector>

#include "source_loc.h"

namespace bsim {

enum class Severity { error, warning };

struct Diagnostic {
  Severity severity = Severity::error;
  SourceLoc loc;
  std::string message;
};

/// "PATH:LINE:COL: error: MESSAGE" (or "PATH: error: MESSAGE" without a location).
std::string format_diagnostic(const Diagnostic& d, std::string_view path);

bool has_errors(const std::vector<Diagnostic>& diagnostics);

}  // namespace bsim
