#include "farm_files.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "frames.h"
#include "pov_frame.h"

namespace fs = std::filesystem;

namespace bsim::farm {

namespace {

/// `s` in single quotes for /bin/sh.
std::string sh_quote(const std::string& s) {
  std::string quoted = "'";
  for (char ch : s) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

}  // namespace

std::string conf_text(const FarmConf& c) {
  char duration[64];
  std::snprintf(duration, sizeof duration, "%.17g", c.duration);
  std::ostringstream out;
  out << "# billiards-export --farm slurm: the run's settings, read by its jobs\n"
      << "fps=" << c.fps << "\nwidth=" << c.width << "\nheight=" << c.height << "\nquality=" << quality_name(c.quality)
      << "\nduration=" << duration << "\nframes=" << c.frames << "\n";
  if (!c.frames_job.empty()) out << "frames_job=" << c.frames_job << "\n";
  if (!c.movie_job.empty()) out << "movie_job=" << c.movie_job << "\n";
  return out.str();
}

bool read_conf(const std::string& dir, FarmConf& c, std::string& error) {
  const std::string path = dir + "/" + kConf;
  std::ifstream in(path);
  if (!in) {
    error = dir + " holds no farm run (no " + kConf + "); submit one with `billiards-export SCENE --farm slurm -o " +
            dir + "`";
    return false;
  }
  std::map<std::string, std::string> values;
  for (std::string line; std::getline(in, line);) {
    const std::size_t eq = line.find('=');
    if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
    values[line.substr(0, eq)] = line.substr(eq + 1);
  }
  auto number = [&](const char* key) { return std::atoi(values[key].c_str()); };
  c.fps = number("fps");
  c.width = number("width");
  c.height = number("height");
  c.frames = number("frames");
  c.quality = values["quality"] == "draft" ? Quality::draft : Quality::final;
  c.duration = std::strtod(values["duration"].c_str(), nullptr);
  c.frames_job = values["frames_job"];
  c.movie_job = values["movie_job"];
  if (c.fps <= 0 || c.width <= 0 || c.height <= 0 || c.frames <= 0 || !(c.duration > 0)) {
    error = path + ": error: not a farm run's settings (fps, width, height, frames, duration)";
    return false;
  }
  return true;
}

bool picture_there(const std::string& dir, int frame) {
  std::error_code ec;
  const auto size = fs::file_size(dir + "/frames/" + frame_name(frame) + ".png", ec);
  return !ec && size > 0;
}

bool link_or_copy(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  return !ec;
}

FrameCopies read_copies(const std::string& dir) {
  FrameCopies c;
  std::ifstream in(dir + "/" + kCopies);
  for (int frame, from; in >> frame >> from;) c.add(frame, from);
  return c;
}

std::string copies_text(const FrameCopies& c) {
  std::string text;
  for (const auto& [frame, from] : c.source) text += std::to_string(frame) + " " + std::to_string(from) + "\n";
  return text;
}

std::map<int, PartialPlan> read_partial(const std::string& dir) {
  std::map<int, PartialPlan> plans;
  std::ifstream in(dir + "/" + kPartial);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    int frame = 0;
    PartialPlan plan;
    if (!(words >> frame >> plan.reference)) continue;
    for (PixelRect r; words >> r.x0 >> r.y0 >> r.x1 >> r.y1;) plan.rects.push_back(r);
    plans[frame] = plan;
  }
  return plans;
}

std::string partial_text(const std::map<int, PartialPlan>& plans) {
  std::string text;
  for (const auto& [frame, plan] : plans) {
    text += std::to_string(frame) + " " + std::to_string(plan.reference);
    for (const PixelRect& r : plan.rects)
      text += " " + std::to_string(r.x0) + " " + std::to_string(r.y0) + " " + std::to_string(r.x1) + " " +
              std::to_string(r.y1);
    text += "\n";
  }
  return text;
}

bool copy_picture(const std::string& frames_dir, const FrameCopies& c, int from) {
  const auto it = c.copies.find(from);
  if (it == c.copies.end()) return true;
  bool ok = true;
  for (int frame : it->second) {
    std::error_code ec;
    const std::string to = frames_dir + "/" + frame_name(frame) + ".png";
    if (fs::file_size(to, ec) > 0 && !ec) continue;
    ok = link_or_copy(frames_dir + "/" + frame_name(from) + ".png", to) && ok;
  }
  return ok;
}

std::vector<int> missing_frames(const std::string& dir, int frames, const FrameCopies& c) {
  std::vector<int> missing;
  for (int k = 0; k < frames; ++k) {
    const auto it = c.source.find(k);
    if (!picture_there(dir, k) && (it == c.source.end() || !picture_there(dir, it->second))) missing.push_back(k);
  }
  return missing;
}

std::string chunks_text(const std::vector<std::pair<int, int>>& chunks) {
  std::string chunk_lines;
  for (const auto& c : chunks) chunk_lines += std::to_string(c.first) + "-" + std::to_string(c.second) + "\n";
  return chunk_lines;
}

namespace {

/// The lines of a job script that choose the program it runs: billiards-export as installed on the
/// node (the Debian package, README "Rendering on a Slurm cluster") when it is this very version,
/// otherwise the copy submitted with the run. The job's log names the one chosen.
std::string program_choice(const std::string& quoted_dir) {
  return "dir=" + quoted_dir +
         "\n"
         "program=\"$dir/" +
         kProgram +
         "\"\n"
         "installed=$(command -v billiards-export || true)\n"
         "if [ -n \"$installed\" ] && [ \"$(\"$installed\" --version 2>/dev/null || true)\" = " +
         sh_quote("billiards-export " BSIM_VERSION) +
         " ]; then\n"
         "  program=$installed\n"
         "fi\n"
         "echo \"running $program\" >&2\n";
}

}  // namespace

std::string task_script(const std::string& dir) {
  return "#!/bin/sh\n"
         "# A task of the frame array (billiards-export --farm slurm): renders the frames of its chunk,\n"
         "# line SLURM_ARRAY_TASK_ID + 1 of chunks.txt (FIRST-LAST), that are not rendered yet.\n"
         "set -eu\n" +
         program_choice(sh_quote(dir)) + "frames=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" \"$dir/" + kChunks +
         "\")\n"
         "exec \"$program\" \"$dir\" --farm render --frames \"$frames\"\n";
}

std::string movie_script(const std::string& dir) {
  return "#!/bin/sh\n"
         "# The movie job (billiards-export --farm slurm): runs when every task of the frame array has\n"
         "# ended; checks every frame, names the missing ones, and encodes movie.mp4 as a local run does.\n"
         "set -eu\n" +
         program_choice(sh_quote(dir)) + "exec \"$program\" \"$dir\" --farm assemble\n";
}

std::string task_log(const std::string& dir, const FarmConf& conf, int frame) {
  std::ifstream in(dir + "/" + kChunks);
  int index = 0;
  for (std::string line; std::getline(in, line); ++index) {
    const int first = std::atoi(line.c_str()), last = std::atoi(line.c_str() + line.find('-') + 1);
    if (frame >= first && frame <= last)
      return std::string(kLogs) + "/frames-" + conf.frames_job + "_" + std::to_string(index) + ".log";
  }
  return kLogs;
}

std::string shown_picture(int frame) {
  return "frame " + std::to_string(frame) + " (frames/" + frame_name(frame) + ".png)";
}

}  // namespace bsim::farm
