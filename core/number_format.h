#pragma once
// Shortest round-trip text for doubles, so output files are exact and byte-for-byte reproducible.
#include <charconv>
#include <string>

namespace bsim {

/// Appends format_number(value) to `out` (no string of its own: for files of many numbers).
inline void append_number(std::string& out, double value) {
  if (value == 0.0) value = 0.0;  // print -0 as 0
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;
  out.append(buffer, end);
}

inline std::string format_number(double value) {
  std::string out;
  append_number(out, value);
  return out;
}

}  // namespace bsim
