#include "support.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>

namespace bsim::test {

namespace {
std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

CommandResult run_command(const std::string& command) {
  TempDir capture;
  const auto out = capture.path / "out", err = capture.path / "err";
  const std::string full = "(" + command + ") </dev/null >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(full.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::string bin(const std::string& name) { return std::string(BSIM_BIN_DIR) + "/" + name; }

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
  std::ofstream(p, std::ios::binary) << contents;
  return p.string();
}

}  // namespace bsim::test
