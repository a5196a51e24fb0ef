#include "scene_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "builtin_scene.h"

namespace bsim {

namespace {

/// Closes the descriptor when it goes out of scope.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::optional<std::string> read_scene_file(const std::string& path, std::string& error) {
  const auto cannot_read = [&](int code) {
    error = path + ": error: cannot read the scene file: " + std::strerror(code);
    return std::nullopt;
  };
  const auto is_directory = [&]() {
    error = path + ": error: is a directory, not a scene file";
    return std::nullopt;
  };
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) return errno == EISDIR ? is_directory() : cannot_read(errno);
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) return cannot_read(errno);
  if (S_ISDIR(info.st_mode)) return is_directory();
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      return cannot_read(errno);
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

SceneOrigin scene_origin(const std::optional<std::string>& path) {
  if (!path) return {std::nullopt, "<built-in break.scn>", std::string(kBuiltinSceneName)};
  return {*path, *path, std::filesystem::path(*path).stem().string()};
}

std::optional<std::string> read_scene_text(const SceneOrigin& origin, std::string& error) {
  if (!origin.path) return std::string(builtin_scene_text());
  return read_scene_file(*origin.path, error);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace bsim
