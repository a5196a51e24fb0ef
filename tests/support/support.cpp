#include "support.h"

#include <doctest/doctest.h>

#include <sys/wait.h>
#include <cstdlib>
#include <optional>
#include <random>
#include <utility>

#include "files.h"

namespace bsim::test {

CommandResult run_command(const std::string& command) {
  TempDir capture;
  const auto out = capture.path / "out", err = capture.path / "err";
  const std::string full = "(" + command + ") </dev/null >" + quoted(out.string()) + " 2>" + quoted(err.string());
  const int status = std::system(full.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_file(out).value_or("");
  r.err = read_file(err).value_or("");
  return r;
}

std::string bin(const std::string& name) { return std::string(BSIM_BIN_DIR) + "/" + name; }

std::string quoted(const std::string& s) { return "'" + s + "'"; }

void require_program(const std::string& program) {
  const bool found = run_command("command -v " + quoted(program)).exit_code == 0;
  REQUIRE_MESSAGE(found, program << " is not installed: run bash .ci/test, which installs it");
}

std::string require_file(const std::filesystem::path& path) {
  std::optional<std::string> bytes = read_file(path);
  REQUIRE_MESSAGE(bytes.has_value(), "cannot read " << path);
  return std::move(*bytes);
}

std::vector<std::string> leftovers(const std::filesystem::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.starts_with('.') || name.find(".tmp") != std::string::npos) found.push_back(name);
  }
  return found;
}

TempDir::TempDir() {
  std::random_device device;
  std::mt19937_64 random(device());
  for (;;) {
    path = std::filesystem::temp_directory_path() / ("bsim-test-" + std::to_string(random()));
    if (std::filesystem::create_directory(path)) break;
  }
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path, ignored);
}

std::string TempDir::file(const std::string& name, const std::string& contents) const {
  const auto p = path / name;
  std::filesystem::create_directories(p.parent_path());
  REQUIRE_MESSAGE(write_file(p, contents), "cannot write " << p);
  return p.string();
}

}  // namespace bsim::test
