#pragma once
// Which rendered frames are still good: a small file beside the frames records, for each PNG, a
// hash of everything that made it (its .pov text, the shared include, size and quality), so a
// re-run renders only the frames whose inputs changed.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace bsim {

/// File name of the record, inside the frames directory.
inline constexpr std::string_view kFrameCacheName = "rendered.txt";

/// 64-bit FNV-1a, continued from `seed`: stable across runs and machines.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ULL);

class FrameCache {
 public:
  /// Reads the record in `frames_dir` (a missing or unreadable one is empty).
  explicit FrameCache(std::string frames_dir);

  bool up_to_date(const std::string& png_name, std::uint64_t key) const;
  void set(const std::string& png_name, std::uint64_t key) { keys_[png_name] = key; }
  void erase(const std::string& png_name) { keys_.erase(png_name); }
  /// Writes the record (to a temporary name, then renamed). Returns false if it cannot.
  bool save() const;

 private:
  std::string dir_;
  std::map<std::string, std::uint64_t> keys_;
};

}  // namespace bsim
