#include "diagnostics.h"

#include <algorithm>

namespace bsim {

std::string format_diagnostic(const Diagnostic& d, std::string_view path) {
  std::string out(path);
  if (d.loc.known()) {
    out.append(":").append(std::to_string(d.loc.line));
    out.append(":").append(std::to_string(d.loc.column));
  }
  out.append(d.severity == Severity::error ? ": error: " : ": warning: ");
  out.append(d.message);
  return out;
}

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::error; });
}

}  // namespace bsim
