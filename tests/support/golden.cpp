#include "golden.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <string_view>

#include "files.h"

namespace bsim::test {

bool updating_goldens() {
  const char* value = std::getenv(kUpdateGoldens);
  return value != nullptr && std::string_view(value) != "" && std::string_view(value) != "0";
}

std::filesystem::path golden_path(const std::string& kind, const std::string& name) {
  return source_path("tests/golden") / kind / name;
}

std::string missing_golden_message(const std::filesystem::path& golden) {
  return "no golden file " + golden.string() + "; make it with " + kUpdateGoldens + "=1 build/bin/bsim_tests";
}

void write_golden(const std::filesystem::path& golden, const std::string& bytes) {
  if (read_file(golden) == bytes) return;  // unchanged files keep their time stamps
  std::error_code ignored;
  std::filesystem::create_directories(golden.parent_path(), ignored);
  REQUIRE_MESSAGE(write_file(golden, bytes), "cannot write " << golden);
  MESSAGE("rewrote " << golden);
}

void check_golden_text(const std::filesystem::path& golden, const std::string& text) {
  if (updating_goldens()) write_golden(golden, text);
  const std::optional<std::string> expected = read_file(golden);
  if (!expected) {
    FAIL_CHECK(missing_golden_message(golden));
    return;
  }
  if (*expected == text) return;
  // Name the first line that differs rather than printing both files whole.
  std::size_t line = 1, at = 0;
  while (at < expected->size() && at < text.size() && (*expected)[at] == text[at]) line += text[at++] == '\n';
  auto line_at = [](const std::string& s, std::size_t from) {
    const std::size_t begin = s.rfind('\n', from == 0 ? 0 : from - 1);
    const std::size_t start = begin == std::string::npos || from == 0 ? 0 : begin + 1;
    return s.substr(start, s.find('\n', start) - start);
  };
  FAIL_CHECK("the text differs from " << golden << " at line " << line << ":\n  golden: " << line_at(*expected, at)
                                      << "\n  now:    " << line_at(text, at));
}

}  // namespace bsim::test
