#pragma once
// Helpers shared by the tests: running the binaries and the tools they call, temporary directories.
#include <filesystem>
#include <string>
#include <vector>

namespace bsim::test {

/// The sanitized test build (tests/CMakeLists.txt): the heaviest cases (whole games) run smaller there.
#ifdef BSIM_SANITIZED_TESTS
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `command` through /bin/sh with stdin from /dev/null, capturing both streams.
CommandResult run_command(const std::string& command);

/// Path of a built binary, e.g. bin("billiards-export").
std::string bin(const std::string& name);

/// `s` in single quotes for /bin/sh (paths here never hold a quote).
std::string quoted(const std::string& s);

/// Fails the test case unless `program` is on PATH. The tools the tests drive (povray, ffmpeg,
/// ffprobe, xvfb-run) are installed by the test command, so a missing one is a broken set-up, never
/// a reason to pass without testing.
void require_program(const std::string& program);

/// The bytes of the file at `path`; fails the test case if it cannot be read (so two missing files
/// never compare equal).
std::string require_file(const std::filesystem::path& path);

/// Files below `dir` a run must never leave: hidden ones (temporary pictures, logs, staging
/// directories) and any with ".tmp" in the name.
std::vector<std::string> leftovers(const std::filesystem::path& dir);

/// A fresh empty directory under the system temp directory, removed when the object dies.
struct TempDir {
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path path;
  /// Writes `contents` to `name` inside (creating folders on the way), returns its path.
  std::string file(const std::string& name, const std::string& contents) const;
};

}  // namespace bsim::test
