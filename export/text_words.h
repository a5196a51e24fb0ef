#pragma once
// Reading back the lines of text the export writes for itself (depth_scene.h, frame_lens.h): a word at
// a time from a line, each number exact (std::from_chars) and finite.
#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

#include "vec.h"

namespace bsim {

/// Reads the line's next word as a number; false at its end or at anything else.
inline bool take(std::istringstream& in, double& value) {
  std::string word;
  if (!(in >> word)) return false;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  return ec == std::errc() && end == word.data() + word.size() && std::isfinite(value);
}

/// Reads three numbers into `v`.
inline bool take(std::istringstream& in, Vec3& v) { return take(in, v.x()) && take(in, v.y()) && take(in, v.z()); }

/// Whether the line's next word is `expected`.
inline bool word_is(std::istringstream& in, const char* expected) {
  std::string word;
  return in >> word && word == expected;
}

}  // namespace bsim
