#pragma once
// Checks of what a caller promises at the seams between modules: a ball index in range, a time the
// shot has a motion segment for, a kind a switch knows. A broken promise is a bug in the program,
// not a mistake in the input (those are reported as diagnostics), so the program stops at once with
// the file, line and what was expected, instead of reading past the end of an array or going on
// with nonsense.
//
// Active in every build: the tests and the movies run the release build, where a check that only a
// debug build makes would never fire. Each sits where a module is entered, not in an inner loop, and
// costs a comparison and a branch the compiler lays out as not taken (the report is a cold function).
namespace bsim {

/// Prints "file:line: internal error: message (expected: condition)" to standard error and aborts.
[[noreturn, gnu::cold]] void expectation_failed(const char* file, int line, const char* condition, const char* message);

}  // namespace bsim

/// Stops the program with `message` (a string literal) unless `condition` holds.
#define BSIM_EXPECT(condition, message) \
  ((condition) ? static_cast<void>(0) : ::bsim::expectation_failed(__FILE__, __LINE__, #condition, message))
