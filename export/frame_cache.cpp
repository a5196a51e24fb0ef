#include "frame_cache.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "atomic_file.h"

namespace fs = std::filesystem;

namespace bsim {

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::string default_frame_cache_dir() {
  auto variable = [](const char* name) {
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
  };
  const std::string chosen = variable("BSIM_CACHE_DIR");
  if (chosen == "off") return "";
  if (!chosen.empty()) return chosen;
  if (const std::string xdg = variable("XDG_CACHE_HOME"); !xdg.empty()) return xdg + "/billiards-sim/frames";
  if (const std::string home = variable("HOME"); !home.empty()) return home + "/.cache/billiards-sim/frames";
  return "";
}

FrameCache::FrameCache(std::string store_dir, std::string frames_dir)
    : store_(std::move(store_dir)), frames_(std::move(frames_dir)) {
  if (store_.empty()) return;
  std::error_code ec;
  fs::create_directories(store_, ec);
  if (ec) store_.clear();  // no store: every frame is rendered, as it would be the first time
}

std::string FrameCache::picture(std::uint64_t key) const {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.png", static_cast<unsigned long long>(key));
  return store_ + "/" + name;
}

bool FrameCache::fetch(const std::string& png_name, std::uint64_t key) const {
  if (store_.empty()) return false;
  const std::string stored = picture(key);
  std::error_code ec;
  if (!fs::is_regular_file(stored, ec) || fs::file_size(stored, ec) == 0 || ec) return false;
  if (!fs::copy_file(stored, frames_ + "/" + png_name, fs::copy_options::overwrite_existing, ec) || ec) return false;
  fs::last_write_time(stored, fs::file_time_type::clock::now(), ec);  // recently used: trimmed last
  return true;
}

void FrameCache::set(const std::string& png_name, std::uint64_t key) const {
  if (store_.empty()) return;
  // Copied under a name of this process, then renamed: a reader never sees half a picture, and two
  // runs storing the same picture at once each rename a whole one.
  const std::string stored = picture(key);
  const std::string temp = stored + "." + std::to_string(::getpid()) + ".tmp";
  std::error_code ec;
  std::string ignored;
  if (fs::copy_file(frames_ + "/" + png_name, temp, fs::copy_options::overwrite_existing, ec) && !ec)
    move_into_place(temp, stored, ignored);
  else
    fs::remove(temp, ec);
}

namespace {

// A `.tmp` copy is renamed into place within moments of being written; one an hour old was left by a
// process that was killed between the two, and nothing will ever rename it.
void remove_if_stale(const fs::path& temp) {
  std::error_code ec;
  const fs::file_time_type written = fs::last_write_time(temp, ec);
  if (!ec && fs::file_time_type::clock::now() - written > std::chrono::hours(1)) fs::remove(temp, ec);
}

}  // namespace

void FrameCache::trim(std::uintmax_t limit) const {
  if (store_.empty()) return;
  struct Entry {
    fs::file_time_type used;
    std::uintmax_t size;
    fs::path path;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (auto it = fs::directory_iterator(store_, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    if (it->path().extension() == ".tmp") {
      remove_if_stale(it->path());
      continue;
    }
    if (it->path().extension() != ".png") continue;
    std::error_code entry_ec;
    const std::uintmax_t size = it->file_size(entry_ec);
    const fs::file_time_type used = it->last_write_time(entry_ec);
    if (entry_ec) continue;
    entries.push_back({used, size, it->path()});
    total += size;
  }
  if (total <= limit) return;
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= limit) break;
    if (fs::remove(e.path, ec)) total -= e.size;
  }
}

}  // namespace bsim
