#pragma once
// Rendered frames kept for the next run: a store of PNG pictures named by a hash of everything that
// made them (the frame's .pov text, the shared include, size, quality and how it is developed). A run
// copies a stored picture instead of rendering it again, so a re-run renders only the frames whose
// inputs changed, a run that failed or was interrupted loses none of the frames it finished, and two
// frames with the same inputs in one run (balls at rest under a still camera) are rendered once.
//
// The store lives outside every output directory (BSIM_CACHE_DIR, else $XDG_CACHE_HOME/billiards-sim,
// else ~/.cache/billiards-sim), so it is never mistaken for finished output; it is trimmed to
// kFrameCacheLimit bytes after each run, least recently used pictures first.
#include <cstdint>
#include <string>
#include <string_view>

namespace bsim {

/// Bytes the store keeps at most: about a dozen final 1280x720 movies.
inline constexpr std::uintmax_t kFrameCacheLimit = 4ULL << 30;

/// 64-bit FNV-1a, continued from `seed`: stable across runs and machines.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ULL);

/// The store's directory from the environment (see above); empty when none can be named (no HOME),
/// or when BSIM_CACHE_DIR is set to "off".
std::string default_frame_cache_dir();

class FrameCache {
 public:
  /// The store in `store_dir` (empty: no store; nothing is found or kept) for pictures in `frames_dir`.
  FrameCache(std::string store_dir, std::string frames_dir);

  /// Copies the stored picture for `key` to frames_dir/png_name; false when none is stored.
  bool fetch(const std::string& png_name, std::uint64_t key) const;
  /// Keeps frames_dir/png_name under `key` (best effort: a store that cannot be written only costs
  /// the next run time).
  void set(const std::string& png_name, std::uint64_t key) const;
  /// Removes the least recently used pictures until the store holds at most `limit` bytes, and any
  /// `.tmp` copy over an hour old (left by a process killed while storing).
  void trim(std::uintmax_t limit = kFrameCacheLimit) const;

  const std::string& store_dir() const { return store_; }

 private:
  std::string picture(std::uint64_t key) const;

  std::string store_;
  std::string frames_;
};

}  // namespace bsim
