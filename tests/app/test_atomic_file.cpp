// Replacing a file whole or not at all (core/app/atomic_file): the content replaced, the replaced
// file's permissions kept, and nothing left behind when the write fails.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "atomic_file.h"
#include "png_file.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

/// The names in `dir`, to show that no temporary file is left.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

unsigned mode_of(const fs::path& path) {
  struct stat info {};
  REQUIRE(::stat(path.c_str(), &info) == 0);
  return static_cast<unsigned>(info.st_mode & 07777);
}

}  // namespace

TEST_SUITE("atomic_file") {
  TEST_CASE("a file is written whole, and replaces the older one with its permissions") {
    test::TempDir dir;
    const std::string path = (dir.path / "notes.txt").string();
    std::string error;
    REQUIRE_MESSAGE(write_file_atomically(path, "first\n", error), error);
    CHECK(test::require_file(path) == "first\n");

    ::chmod(path.c_str(), 0640);
    REQUIRE_MESSAGE(write_file_atomically(path, "second, longer\n", error), error);
    CHECK(test::require_file(path) == "second, longer\n");
    CHECK(mode_of(path) == 0640);
    CHECK(names_in(dir.path) == std::vector<std::string>{"notes.txt"});

    // An explicit mode wins over the older file's.
    REQUIRE_MESSAGE(write_file_atomically(path, "third\n", error, 0600u), error);
    CHECK(mode_of(path) == 0600);
    REQUIRE_MESSAGE(write_file_atomically(path, "", error), error);
    CHECK(test::require_file(path).empty());
  }

  TEST_CASE("a write that fails says why, leaves the target as it was and no temporary file") {
    test::TempDir dir;
    std::string error;
    // The target is a directory: the content is written, and the rename refuses.
    fs::create_directories(dir.path / "folder" / "inside");
    const std::string folder = (dir.path / "folder").string();
    CHECK_FALSE(write_file_atomically(folder, "text", error));
    CHECK(error == "cannot write " + folder + ": Is a directory");
    CHECK(fs::is_directory(folder));
    CHECK(names_in(dir.path) == std::vector<std::string>{"folder"});

    // The directory is missing: no temporary file can be made.
    const std::string nowhere = (dir.path / "missing" / "file.txt").string();
    error.clear();
    CHECK_FALSE(write_file_atomically(nowhere, "text", error));
    CHECK(error == "cannot write " + nowhere + ": No such file or directory");
    CHECK(names_in(dir.path) == std::vector<std::string>{"folder"});
  }

  TEST_CASE("a file a child program wrote is moved into place, and removed when it cannot be") {
    test::TempDir dir;
    const std::string target = dir.file("movie.mp4", "old movie");
    ::chmod(target.c_str(), 0604);
    const std::string written = dir.file(".movie.tmp.mp4", "new movie");
    std::string error;
    REQUIRE_MESSAGE(move_into_place(written, target, error), error);
    CHECK(test::require_file(target) == "new movie");
    CHECK(mode_of(target) == 0604);
    CHECK(names_in(dir.path) == std::vector<std::string>{"movie.mp4"});

    fs::create_directories(dir.path / "folder" / "inside");
    const std::string again = dir.file(".again.tmp", "text");
    const std::string folder = (dir.path / "folder").string();
    CHECK_FALSE(move_into_place(again, folder, error));
    CHECK(error == "cannot write " + folder + ": Is a directory");
    CHECK(names_in(dir.path) == std::vector<std::string>{"folder", "movie.mp4"});
  }

  TEST_CASE("the PNG encoder makes the same bytes from the same pixels, and writes them whole") {
    const std::vector<std::uint8_t> rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
    const std::string png = encode_png(rgb, 2, 2);
    CHECK(png == encode_png(rgb, 2, 2));
    CHECK(png.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
    test::TempDir dir;
    const std::string path = (dir.path / "picture.png").string();
    std::string error;
    REQUIRE_MESSAGE(write_png(path, rgb, 2, 2, error), error);
    CHECK(test::require_file(path) == png);
  }
}
