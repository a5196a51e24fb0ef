// The frame store: fetch what was set, trim the least recently used pictures to a size, and clear
// the half-stored copies a killed process leaves behind.
#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "frame_cache.h"
#include "support.h"

namespace fs = std::filesystem;
using namespace bsim;

namespace {

void write_bytes(const fs::path& path, std::size_t n) {
  std::ofstream out(path, std::ios::binary);
  out << std::string(n, 'x');
}

void age(const fs::path& path, std::chrono::minutes by) {
  fs::last_write_time(path, fs::file_time_type::clock::now() - by);
}

}  // namespace

TEST_SUITE("frame store") {
  TEST_CASE("a stored picture is fetched by its key; an unknown key is not") {
    test::TempDir dir;
    fs::create_directories(dir.path / "frames");
    const FrameCache cache((dir.path / "store").string(), (dir.path / "frames").string());
    write_bytes(dir.path / "frames" / "a.png", 100);
    cache.set("a.png", 42);
    CHECK(cache.fetch("b.png", 42));
    CHECK(fs::file_size(dir.path / "frames" / "b.png") == 100);
    CHECK_FALSE(cache.fetch("c.png", 43));
  }

  TEST_CASE("trimming removes the least recently used pictures first, and stale half-stored copies") {
    test::TempDir dir;
    const fs::path store = dir.path / "store";
    fs::create_directories(store);
    const FrameCache cache(store.string(), (dir.path / "frames").string());
    write_bytes(store / "0000000000000001.png", 1000);
    write_bytes(store / "0000000000000002.png", 1000);
    write_bytes(store / "0000000000000003.png", 1000);
    age(store / "0000000000000001.png", std::chrono::minutes(30));
    age(store / "0000000000000002.png", std::chrono::minutes(20));
    write_bytes(store / "0000000000000004.png.123.tmp", 10);  // a run storing it now
    write_bytes(store / "0000000000000005.png.456.tmp", 10);  // a run killed two hours ago
    age(store / "0000000000000005.png.456.tmp", std::chrono::minutes(120));

    cache.trim(2500);
    CHECK_FALSE(fs::exists(store / "0000000000000001.png"));  // the oldest goes
    CHECK(fs::exists(store / "0000000000000002.png"));
    CHECK(fs::exists(store / "0000000000000003.png"));
    CHECK(fs::exists(store / "0000000000000004.png.123.tmp"));
    CHECK_FALSE(fs::exists(store / "0000000000000005.png.456.tmp"));

    cache.trim(0);
    CHECK_FALSE(fs::exists(store / "0000000000000002.png"));
    CHECK_FALSE(fs::exists(store / "0000000000000003.png"));
  }
}
