#pragma once
// Helpers shared by the tests: running the binaries, temporary directories, scenes from text.
#include <filesystem>
#include <string>

namespace bsim::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `command` through /bin/sh with stdin from /dev/null, capturing both streams.
CommandResult run_command(const std::string& command);

/// Path of a built binary, e.g. bin("billiards-export").
std::string bin(const std::string& name);

/// A fresh empty directory under the system temp directory, removed when the object dies.
struct TempDir {
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path path;
  std::string file(const std::string& name, const std::string& contents) const;  ///< writes, returns its path
};

}  // namespace bsim::test
