#include "output_stage.h"

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace bsim {

namespace {

/// The closest directory that already exists at or above `dir` ("." for a relative path with none).
fs::path nearest_existing(const fs::path& dir) {
  std::error_code ec;
  for (fs::path p = dir; !p.empty(); p = p.parent_path()) {
    if (fs::is_directory(p, ec)) return p;
    if (p == p.parent_path()) break;
  }
  return ".";
}

std::string reason(const std::error_code& ec) { return ec.message(); }

}  // namespace

bool OutputStage::open(const std::string& dir, std::string& error) {
  discard();
  destination_ = dir;
  std::error_code ec;
  const fs::path destination(dir);
  const auto status = fs::status(destination, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    error = "the output path '" + dir + "' exists and is not a directory";
    return false;
  }
  // Inside the destination when it exists, else beside it in the closest existing directory, so that
  // the final renames stay on one file system and a failed run creates no output directory.
  std::string tag = ".partial-";
  tag += std::to_string(::getpid());
  std::string beside = ".";
  beside += destination.filename().string();
  beside += tag;
  const fs::path staging =
      fs::is_directory(status) ? destination / tag : nearest_existing(destination.parent_path()) / beside;
  fs::remove_all(staging, ec);
  if (!fs::create_directory(staging, ec) || ec) {
    error = "cannot create the staging directory '" + staging.string() + "': " + reason(ec);
    return false;
  }
  staging_ = staging.string();
  open_ = true;
  return true;
}

std::string OutputStage::path(const std::string& relative) const {
  const fs::path p = fs::path(staging_) / relative;
  std::error_code ec;
  fs::create_directories(p.parent_path(), ec);  // a failure shows when the caller opens the file
  return p.string();
}

bool OutputStage::commit(std::string& error, const std::vector<std::string>& owned,
                         const std::vector<std::string>& later) {
  kept_.clear();
  if (!open_) {
    error = "nothing staged to commit";
    return false;
  }
  std::error_code ec;
  const fs::path destination(destination_);
  if (!fs::exists(destination, ec)) {
    if (destination.has_parent_path()) fs::create_directories(destination.parent_path(), ec);
    if (!ec) fs::rename(staging_, destination, ec);
    if (ec) {
      error = "cannot move the staged outputs to '" + destination_ + "': " + reason(ec);
      return false;
    }
    open_ = false;
    return true;
  }
  std::vector<fs::path> entries;
  for (auto it = fs::directory_iterator(staging_, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    entries.push_back(it->path().filename());
  if (ec) {
    error = "cannot list the staged files in '" + staging_ + "': " + reason(ec);
    return false;
  }
  // Name order for a reproducible sequence; events.json last, since its presence marks a whole run.
  std::sort(entries.begin(), entries.end(), [](const fs::path& a, const fs::path& b) {
    const bool a_last = a == "events.json", b_last = b == "events.json";
    return a_last != b_last ? b_last : a < b;
  });
  for (const fs::path& name : entries) {
    const fs::path from = fs::path(staging_) / name, to = destination / name;
    if (fs::is_directory(from, ec) && fs::exists(to, ec)) {
      // The older folder steps aside under a hidden name, the new one takes its place, the old goes.
      const fs::path old = destination / ("." + name.string() + ".old-" + std::to_string(::getpid()));
      fs::remove_all(old, ec);
      fs::rename(to, old, ec);
      if (!ec) {
        fs::rename(from, to, ec);
        std::error_code ignored;
        if (ec) fs::rename(old, to, ignored);  // put the older folder back: the destination stays whole
        fs::remove_all(old, ignored);
      }
    } else {
      fs::rename(from, to, ec);  // atomic replacement of an older copy
    }
    if (ec) {
      error = "cannot move '" + name.string() + "' into '" + destination_ + "': " + reason(ec);
      return false;
    }
  }
  for (const std::string& name : later) {
    fs::remove_all(destination / name, ec);
    if (ec) {
      error = "cannot remove the older '" + name + "' from '" + destination_ + "': " + reason(ec);
      return false;
    }
  }
  for (const std::string& name : owned) {
    if (std::find(entries.begin(), entries.end(), fs::path(name)) != entries.end()) continue;
    if (std::find(later.begin(), later.end(), name) != later.end()) continue;
    const auto status = fs::symlink_status(destination / name, ec);
    if (fs::exists(status)) kept_.push_back(name + (fs::is_directory(status) ? "/" : ""));
  }
  discard();
  return true;
}

void OutputStage::discard() {
  if (!open_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  open_ = false;
}

OutputStage::~OutputStage() { discard(); }

}  // namespace bsim
