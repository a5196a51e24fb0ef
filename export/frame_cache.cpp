#include "frame_cache.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace bsim {

std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

FrameCache::FrameCache(std::string frames_dir) : dir_(std::move(frames_dir)) {
  std::ifstream in(dir_ + "/" + std::string(kFrameCacheName));
  std::string name, hex;
  while (in >> name >> hex) {
    std::uint64_t key = 0;
    const auto [end, ec] = std::from_chars(hex.data(), hex.data() + hex.size(), key, 16);
    if (ec == std::errc() && end == hex.data() + hex.size()) keys_[name] = key;
  }
}

bool FrameCache::up_to_date(const std::string& png_name, std::uint64_t key) const {
  const auto it = keys_.find(png_name);
  return it != keys_.end() && it->second == key && std::filesystem::exists(dir_ + "/" + png_name);
}

bool FrameCache::save() const {
  const std::string path = dir_ + "/" + std::string(kFrameCacheName);
  const std::string temp = dir_ + "/." + std::string(kFrameCacheName) + ".tmp";
  {
    std::ofstream out(temp, std::ios::binary);
    for (const auto& [name, key] : keys_) {
      char hex[24];
      std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(key));
      out << name << ' ' << hex << '\n';
    }
    if (!out.flush()) return false;
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  return !ec;
}

}  // namespace bsim
