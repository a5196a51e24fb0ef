#pragma once
// Shortest round-trip text for doubles, so output files are exact and byte-for-byte reproducible.
#include <charconv>
#include <string>

namespace bsim {

inline std::string format_number(double value) {
  if (value == 0.0) value = 0.0;  // print -0 as 0
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;
  return std::string(buffer, end);
}

}  // namespace bsim
