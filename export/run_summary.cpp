#include "run_summary.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "child_process.h"

namespace fs = std::filesystem;

namespace bsim {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

namespace {

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", s);
  return text;
}

/// Decibels to a hundredth.
std::string decibels(double db) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", db);
  return text;
}

/// Every top-level file with its size; each folder as its count of files and their bytes.
std::string files_json(const std::string& dir) {
  struct Item {
    std::string name;
    std::uintmax_t bytes = 0;
    int files = -1;  ///< -1 for a plain file
  };
  std::vector<Item> items;
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name == kRunSummaryName || name.starts_with('.')) continue;
    Item item{name};
    if (it->is_directory()) {
      item.files = 0;
      for (const auto& inner : fs::recursive_directory_iterator(it->path(), ec))
        if (inner.is_regular_file()) {
          ++item.files;
          item.bytes += inner.file_size();
        }
      item.name += "/";
    } else {
      item.bytes = it->file_size(ec);
    }
    items.push_back(item);
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.name < b.name; });
  std::string out = "[";
  for (std::size_t k = 0; k < items.size(); ++k) {
    out += k ? ",\n    " : "\n    ";
    out += "{\"path\": " + json_string(items[k].name) + ", \"bytes\": " + std::to_string(items[k].bytes);
    if (items[k].files >= 0) out += ", \"files\": " + std::to_string(items[k].files);
    out += "}";
  }
  return out + (items.empty() ? "]" : "\n  ]");
}

}  // namespace

std::string program_version(const std::string& program, const std::string& flag, const std::string& prefix) {
  if (program.empty()) return "";
  const fs::path log = fs::temp_directory_path() / ("bsim-version-" + std::to_string(::getpid()) + ".log");
  std::string error;
  const pid_t pid = start_process({program, flag}, ".", log.string(), error);
  if (pid < 0) return "";
  wait_for(pid);  // POV-Ray says its version on standard error, after a complaint or two
  std::ifstream in(log);
  std::string line, found;
  while (std::getline(in, line)) {
    line.erase(0, line.find_first_not_of(" \t\r"));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.starts_with(prefix)) {
      found = line.substr(0, line.find(" Copyright"));
      break;
    }
  }
  std::error_code ec;
  fs::remove(log, ec);
  return found;
}

bool write_run_summary(const RunSummary& s, const ExportOptions& o, const std::string& staged_dir, std::string& error) {
  const std::string path = staged_dir + "/" + kRunSummaryName;
  std::ofstream out(path, std::ios::binary);
  const double total = s.simulating + s.writing + s.rendering + s.encoding;
  out << "{\n"
      << "  \"program\": " << json_string("billiards-export " BSIM_VERSION) << ",\n"
      << "  \"scene\": " << json_string(s.scene) << ",\n"
      << "  \"output\": " << json_string(s.output) << ",\n"
      << "  \"options\": {\"fps\": " << o.fps << ", \"size\": \"" << o.width << "x" << o.height << "\", \"quality\": \""
      << quality_name(o.quality) << "\", \"jobs\": " << o.jobs << ", \"audio_lead\": " << o.audio_lead
      << ", \"music\": " << json_string(o.music_path) << ", \"strict\": " << (o.strict ? "true" : "false")
      << ", \"camera\": \"" << (o.auto_camera ? "auto" : "scene")
      << "\", \"no_render\": " << (o.no_render ? "true" : "false")
      << ", \"whole_frames\": " << (o.whole_frames ? "true" : "false") << "},\n"
      << "  \"frames\": {\"total\": " << s.frames_total << ", \"rendered\": " << s.frames_rendered
      << ", \"reused\": " << s.frames_reused << ", \"partial\": " << s.frames_partial
      << ", \"traced\": " << seconds(s.traced_share) << "},\n"
      << "  \"seconds\": {\"simulating\": " << seconds(s.simulating) << ", \"writing\": " << seconds(s.writing)
      << ", \"rendering\": " << seconds(s.rendering) << ", \"encoding\": " << seconds(s.encoding)
      << ", \"total\": " << seconds(total) << "},\n"
      << "  \"sound\": {\"level\": \"" << level_mode_name(o.level.mode) << "\", \"target_lufs\": "
      << (o.level.mode == LevelMode::normalised ? decibels(o.level.loudness) : std::string("null"))
      << ", \"loudness_lufs\": " << (s.loudness_lufs ? decibels(*s.loudness_lufs) : std::string("null"))
      << ", \"true_peak_dbtp\": " << decibels(s.true_peak_dbtp) << "},\n"
      << "  \"tools\": {\"povray\": " << json_string(s.povray_version)
      << ", \"ffmpeg\": " << json_string(s.ffmpeg_version) << "},\n"
      << "  \"files\": " << files_json(staged_dir) << "\n"
      << "}\n";
  out.flush();
  if (!out) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace bsim
