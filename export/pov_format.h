#pragma once
// Numbers in POV-Ray files: fixed to the micrometre (1e-6), locale-free, never "-0", so the same
// shot always writes the same bytes and the golden files stay readable.
#include <charconv>
#include <cmath>
#include <string>

#include "vec.h"

namespace bsim {

inline std::string pov_number(double value) {
  double rounded = std::round(value * 1e6) / 1e6;
  if (rounded == 0.0) rounded = 0.0;  // no "-0.000000"
  char buffer[48];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed, 6);
  if (ec != std::errc()) return "0";
  std::string text(buffer, end);
  // Trim trailing zeros (keeping one digit after the point) to keep the files short.
  while (text.size() > 2 && text.back() == '0' && text[text.size() - 2] != '.') text.pop_back();
  return text;
}

inline std::string pov_vector(const Vec3& v) {
  return "<" + pov_number(v.x()) + ", " + pov_number(v.y()) + ", " + pov_number(v.z()) + ">";
}

inline std::string pov_vector2(double x, double y) { return "<" + pov_number(x) + ", " + pov_number(y) + ">"; }

}  // namespace bsim
