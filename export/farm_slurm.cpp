#include "farm_slurm.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "atomic_file.h"
#include "child_process.h"
#include "ffmpeg_assemble.h"
#include "frame_cache.h"
#include "frames.h"
#include "movie_export.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "pov_table.h"
#include "render_jobs.h"
#include "scene_file.h"
#include "shot.h"

namespace fs = std::filesystem;

namespace bsim {

namespace {

constexpr const char* kConf = "farm/farm.conf";
constexpr const char* kChunks = "farm/chunks.txt";
constexpr const char* kCopies = "farm/copies.txt";
constexpr const char* kProgram = "farm/billiards-export";
constexpr const char* kTaskScript = "farm/task.sh";
constexpr const char* kMovieScript = "farm/movie.sh";
constexpr const char* kLogs = "farm/logs";

/// POV-Ray's start-up and its cost a pixel (s), fitted to README's render-time table: draft 1.3 s
/// at 640x360 and 5.1 s at 1280x720, final 2.8 s and 9.0 s.
constexpr double kStartSeconds = 0.6;
constexpr double kDraftPixelSeconds = 5.5e-6;
constexpr double kFinalPixelSeconds = 9.0e-6;

/// The settings a farm run's jobs read (farm/farm.conf, `key=value` lines).
struct FarmConf {
  int fps = 0, width = 0, height = 0, frames = 0;
  Quality quality = Quality::final;
  double duration = 0;
  std::string frames_job, movie_job;  ///< ids of the last submission; empty when none
};

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

/// `s` in single quotes for /bin/sh.
std::string sh_quote(const std::string& s) {
  std::string quoted = "'";
  for (char ch : s) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

/// Runs argv (argv[0] a full path), its standard output and error together in `output` (by way of a
/// file in $TMPDIR, else /tmp); true when it exited with status 0.
bool run_captured(const std::vector<std::string>& argv, std::string& output, std::string& error) {
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string folder = tmpdir && *tmpdir ? tmpdir : "/tmp";
  std::string log = folder + "/billiards-export-XXXXXX";
  const int fd = ::mkstemp(log.data());
  if (fd < 0) {
    error = "cannot create a temporary file in " + folder + ": " + std::strerror(errno);
    return false;
  }
  ::close(fd);
  const pid_t pid = start_process(argv, ".", log, error);
  const bool ok = pid > 0 && wait_for(pid);
  output = read_text_file(log);
  std::error_code ignored;
  fs::remove(log, ignored);
  while (!output.empty() && (output.back() == '\n' || output.back() == ' ')) output.pop_back();
  return ok;
}

bool picture_there(const std::string& dir, int frame) {
  std::error_code ec;
  const auto size = fs::file_size(dir + "/frames/" + frame_name(frame) + ".png", ec);
  return !ec && size > 0;
}

/// Hard-links `from` to `to` (one shared file system), copying when a link cannot be made.
bool link_or_copy(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  return !ec;
}

/// Frames whose .pov text is an earlier frame's (balls at rest under a still camera): the same
/// picture, rendered once and copied (farm/copies.txt, `FRAME SOURCE` lines).
struct FrameCopies {
  std::map<int, int> source;               ///< copy -> the frame it copies
  std::map<int, std::vector<int>> copies;  ///< rendered frame -> its copies
  bool is_copy(int frame) const { return source.count(frame) > 0; }
  void add(int frame, int from) {
    source[frame] = from;
    copies[from].push_back(frame);
  }
};

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

/// Copies frame `from`'s picture to each of its copies that has none yet; false when one cannot be.
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

/// Frames with no picture, a copy counting as there when the frame it copies is.
std::vector<int> missing_frames(const std::string& dir, int frames, const FrameCopies& c) {
  std::vector<int> missing;
  for (int k = 0; k < frames; ++k) {
    const auto it = c.source.find(k);
    if (!picture_there(dir, k) && (it == c.source.end() || !picture_there(dir, it->second))) missing.push_back(k);
  }
  return missing;
}

/// The job ids of `conf` still in the queue (empty when squeue is missing or knows none of them).
std::string jobs_in_queue(const std::string& squeue, const FarmConf& conf) {
  if (squeue.empty() || (conf.frames_job.empty() && conf.movie_job.empty())) return "";
  std::string ids = conf.frames_job;
  if (!conf.movie_job.empty()) ids += (ids.empty() ? "" : ",") + conf.movie_job;
  std::string output, error;
  // Unknown ids (jobs long finished) make squeue fail: none of them is queued.
  if (!run_captured({squeue, "--noheader", "--jobs=" + ids, "--format=%i"}, output, error)) return "";
  std::string found;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    line.erase(0, line.find_first_not_of(' '));
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) found += (found.empty() ? "" : " ") + line;
  }
  return found;
}

/// The job id sbatch --parsable printed: its last line's digits before any ';cluster'.
std::string job_id(const std::string& output) {
  const std::size_t line_start = output.rfind('\n');
  std::string line = output.substr(line_start == std::string::npos ? 0 : line_start + 1);
  line = line.substr(0, line.find(';'));
  if (line.empty() || line.find_first_not_of("0123456789") != std::string::npos) return "";
  return line;
}

/// "frame 7 (frames/frame_00007.png)".
std::string shown_picture(int frame) {
  return "frame " + std::to_string(frame) + " (frames/" + frame_name(frame) + ".png)";
}

int farm_status(const std::string& dir, const FarmConf& conf) {
  std::string error;
  const int missing = static_cast<int>(missing_frames(dir, conf.frames, read_copies(dir)).size());
  std::error_code ec;
  const bool movie = fs::is_regular_file(dir + "/movie.mp4", ec);
  std::cout << dir << ": " << conf.frames - missing << " of " << conf.frames << " frames rendered (" << conf.width
            << "x" << conf.height << ", " << quality_name(conf.quality) << ", " << conf.fps << " fps); movie.mp4 "
            << (movie ? "is made" : "not made yet") << "\n";
  if (!conf.frames_job.empty() || !conf.movie_job.empty())
    std::cout << "jobs: " << (conf.frames_job.empty() ? "" : conf.frames_job + " (frames) ") << conf.movie_job
              << " (movie); logs in " << dir << "/" << kLogs << "\n";
  const std::string squeue = find_program("squeue");
  const std::string queued = jobs_in_queue(squeue, conf);
  if (!queued.empty()) {
    std::string ids = conf.frames_job + (conf.frames_job.empty() ? "" : ",") + conf.movie_job, output;
    run_captured({squeue, "--jobs=" + ids, "--format=%.20i %.10T %.10M %R"}, output, error);
    std::cout << output << "\n";
  } else if (!movie) {
    std::cout << (squeue.empty() ? "squeue is not on PATH: the queue is not shown\n"
                                 : "no job of this run is queued\n");
    if (missing > 0 && (squeue.empty() || !conf.movie_job.empty()))
      std::cout << "run the same `billiards-export SCENE --farm slurm -o " << dir
                << "` command again to render the missing frames\n";
  }
  return 0;
}

int farm_render(const ExportOptions& options, const std::string& dir, const FarmConf& conf) {
  std::string error;
  RenderSettings render{find_program("povray"), conf.width, conf.height, conf.quality, 1, dir + "/frames", true};
  if (render.povray.empty()) {
    char host[256] = "this node";
    ::gethostname(host, sizeof host - 1);
    std::cerr << "billiards-export: error: povray is not on PATH on " << host
              << ": load its module (or set PATH) before submitting, since sbatch passes your environment to "
                 "the jobs\n";
    return 1;
  }
  InterruptGuard guard;  // scancel's SIGTERM stops POV-Ray and removes its half-written picture
  FrameCache no_store("", dir + "/frames");
  const FrameCopies copies = read_copies(dir);
  const int last = options.last_frame < 0 ? conf.frames - 1 : std::min(options.last_frame, conf.frames - 1);
  int rendered = 0;
  std::vector<int> failed;
  for (int k = options.first_frame; k <= last && !InterruptGuard::interrupted(); ++k) {
    if (copies.is_copy(k)) continue;  // the task of the frame it copies copies it
    if (!picture_there(dir, k)) {
      error.clear();
      if (render_frames(dir + "/frames", {{k, 0}}, 1, render, no_store, error) == RunOutcome::done) {
        ++rendered;
        std::cerr << "billiards-export: frame " << k << " rendered\n";
      } else {
        if (!InterruptGuard::interrupted()) {
          std::cerr << "billiards-export: error: " << error << "\n";
          failed.push_back(k);  // the others of the chunk are still worth rendering
        }
        continue;
      }
    }
    // Its copies are the same picture: the movie job would copy them too, but --farm status counts
    // them done from now on.
    if (!copy_picture(dir + "/frames", copies, k))
      std::cerr << "billiards-export: warning: cannot copy frame " << k << " to its copies; the movie job will\n";
  }
  if (InterruptGuard::interrupted()) {
    std::cerr << "billiards-export: error: interrupted\n";
    guard.finish();
    return 1;
  }
  std::cerr << "billiards-export: frames " << options.first_frame << "-" << last << ": " << rendered << " rendered, "
            << failed.size() << " failed\n";
  return failed.empty() ? 0 : 1;
}

/// The log of the array task that rendered (or failed) `frame`, a frame of its own (not a copy), as a
/// path inside DIR.
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

int farm_assemble(const ExportOptions& options, const std::string& dir, const FarmConf& conf) {
  std::string error;
  // Frames the same as an earlier one are that one's picture, copied.
  const FrameCopies copies = read_copies(dir);
  for (const auto& entry : copies.copies) {
    if (picture_there(dir, entry.first) && !copy_picture(dir + "/frames", copies, entry.first)) {
      std::cerr << "billiards-export: error: cannot copy " << shown_picture(entry.first) << " to its copies\n";
      return 1;
    }
  }
  const std::vector<int> missing = missing_frames(dir, conf.frames, copies);
  if (!missing.empty()) {
    // The frames to render are named; their copies are only counted.
    constexpr std::size_t kNamed = 10;
    std::size_t named = 0;
    for (std::size_t i = 0; i < missing.size() && named < kNamed; ++i) {
      if (copies.is_copy(missing[i])) continue;
      std::cerr << "billiards-export: error: " << shown_picture(missing[i]) << " was not rendered; see its task's log, "
                << task_log(dir, conf, missing[i]) << "\n";
      ++named;
    }
    if (missing.size() > named)
      std::cerr << "billiards-export: error: and " << missing.size() - named << " more frames\n";
    std::cerr << "billiards-export: error: no movie: " << missing.size() << " of " << conf.frames
              << " frames are missing; the frames done are kept, and submitting the same command again renders "
                 "only the missing ones\n";
    return 1;
  }
  const std::string ffmpeg = find_program("ffmpeg");
  if (ffmpeg.empty()) {
    std::cerr << "billiards-export: error: ffmpeg is not on PATH: load its module (or set PATH) before "
                 "submitting, since sbatch passes your environment to the jobs\n";
    return 1;
  }
  InterruptGuard guard;
  // The one encoding a local run does too (ffmpeg_assemble.h): the same movie, byte for byte.
  const MovieSettings movie{ffmpeg, conf.fps, conf.duration, options.quiet};
  if (assemble_movie(dir, movie, error) != RunOutcome::done) {
    std::cerr << "billiards-export: error: " << (InterruptGuard::interrupted() ? "interrupted" : error) << "\n";
    guard.finish();
    return 1;
  }
  // Kept in the frame store too, as a local run keeps its pictures (best effort).
  ExportOptions rendered;
  rendered.width = conf.width;
  rendered.height = conf.height;
  rendered.quality = conf.quality;
  const FrameCache store(default_frame_cache_dir(), dir + "/frames");
  const std::vector<std::uint64_t> keys = frame_store_keys(dir + "/frames", conf.frames, rendered);
  for (int k = 0; k < conf.frames; ++k) store.set(frame_name(k) + ".png", keys[k]);
  store.trim();
  std::cerr << "wrote " << dir << "/movie.mp4 (" << conf.frames << " frames)\n";
  return 0;
}

}  // namespace

double estimated_frame_seconds(int width, int height, Quality quality) {
  const double pixel = quality == Quality::final ? kFinalPixelSeconds : kDraftPixelSeconds;
  return kStartSeconds + pixel * width * height;
}

int default_farm_chunk(int width, int height, Quality quality) {
  const double frames = std::floor(kFarmTaskSeconds / estimated_frame_seconds(width, height, quality));
  return static_cast<int>(std::clamp(frames, 1.0, static_cast<double>(kMaxFarmChunk)));
}

std::vector<std::pair<int, int>> farm_chunks(const std::vector<int>& missing, int chunk) {
  std::vector<std::pair<int, int>> runs;  // contiguous runs of missing frames
  for (int frame : missing) {
    if (!runs.empty() && runs.back().second == frame - 1)
      runs.back().second = frame;
    else
      runs.emplace_back(frame, frame);
  }
  // Each run in as few chunks as --chunk allows, of sizes that differ by one at most, so that no
  // task is left with a short tail.
  std::vector<std::pair<int, int>> chunks;
  for (const auto& run : runs) {
    const int length = run.second - run.first + 1, pieces = (length + chunk - 1) / chunk;
    int first = run.first;
    for (int i = 0; i < pieces; ++i) {
      const int size = length / pieces + (i < length % pieces ? 1 : 0);
      chunks.emplace_back(first, first + size - 1);
      first += size;
    }
  }
  return chunks;
}

bool SlurmSubmission::prepare(const ExportOptions& options, const std::string& dir, std::string& error) {
  sbatch_ = find_program("sbatch");
  if (sbatch_.empty()) {
    error =
        "sbatch is not on PATH: --farm slurm submits jobs with Slurm's sbatch; run it on a machine of the "
        "cluster (a login node), or install Slurm's client programs (Debian: slurm-client)";
    return false;
  }
  squeue_ = find_program("squeue");
  scancel_ = find_program("scancel");
  dir_ = fs::absolute(dir).lexically_normal().string();
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
  name_ = "bsim-" + (options.scene_path ? fs::path(*options.scene_path).stem().string() : std::string("break"));
  user_options_ = options.sbatch_options;
  FarmConf earlier;
  std::string ignored;
  if (read_conf(dir, earlier, ignored)) {
    const std::string queued = jobs_in_queue(squeue_, earlier);
    if (!queued.empty()) {
      error = "job " + queued + " of the earlier submission into " + dir +
              " is still queued or running (see `billiards-export " + dir +
              " --farm status`); wait for it, or cancel it with `scancel " + queued + "`";
      return false;
    }
  }
  return true;
}

bool SlurmSubmission::stage(const Shot& shot, const ExportOptions& options, const OutputStage& stage,
                            std::string& error) {
  FarmConf conf;
  conf.fps = options.fps;
  conf.width = options.width;
  conf.height = options.height;
  conf.quality = options.quality;
  conf.duration = shot.timeline.duration();
  conf.frames = frames_ = frame_count(conf.duration, conf.fps);

  // The others may be in this machine's frame store, from a local run or an earlier farm run.
  const FrameCache store(default_frame_cache_dir(), stage.path("frames"));
  const std::vector<std::uint64_t> keys = frame_store_keys(stage.path("frames"), frames_, options);
  // Frames an earlier submission finished are kept when everything they depend on is unchanged: the
  // same size and quality, and the same frame store key (their .pov text, the shared include).
  FarmConf earlier;
  std::string ignored;
  std::vector<std::uint64_t> earlier_keys;
  if (read_conf(dir_, earlier, ignored) && earlier.width == conf.width && earlier.height == conf.height &&
      earlier.quality == conf.quality)
    earlier_keys = frame_store_keys(dir_ + "/frames", std::min(earlier.frames, frames_), options);
  // A frame whose inputs are an earlier frame's is that frame's picture: rendered once, then copied
  // by the task that renders it (and by the movie job, whatever happened to the task).
  FrameCopies copies;
  std::map<std::uint64_t, int> first;
  for (int k = 0; k < frames_; ++k) {
    const auto found = first.emplace(keys[static_cast<std::size_t>(k)], k);
    if (!found.second) copies.add(k, found.first->second);
  }
  std::vector<int> missing;
  copies_ = 0;
  for (int k = 0; k < frames_; ++k) {
    const std::string png = "frames/" + frame_name(k) + ".png";
    const auto i = static_cast<std::size_t>(k);
    if (i < earlier_keys.size() && earlier_keys[i] == keys[i] && picture_there(dir_, k) &&
        link_or_copy(dir_ + "/" + png, stage.path(png)))
      continue;
    if (const auto it = copies.source.find(k); it != copies.source.end()) {
      const std::string from = stage.path("frames/" + frame_name(it->second) + ".png");
      std::error_code ec;
      if (!(fs::file_size(from, ec) > 0 && !ec && link_or_copy(from, stage.path(png)))) ++copies_;
      continue;
    }
    if (store.fetch(frame_name(k) + ".png", keys[static_cast<std::size_t>(k)])) continue;
    missing.push_back(k);
  }
  missing_ = static_cast<int>(missing.size());
  chunk_ = options.chunk > 0 ? options.chunk : default_farm_chunk(conf.width, conf.height, conf.quality);
  chunks_ = farm_chunks(missing, chunk_);

  std::string chunk_lines;
  for (const auto& c : chunks_) chunk_lines += std::to_string(c.first) + "-" + std::to_string(c.second) + "\n";
  const std::string quoted_dir = sh_quote(dir_);
  const std::string task =
      "#!/bin/sh\n"
      "# A task of the frame array (billiards-export --farm slurm): renders the frames of its chunk,\n"
      "# line SLURM_ARRAY_TASK_ID + 1 of chunks.txt (FIRST-LAST), that are not rendered yet.\n"
      "set -eu\n"
      "dir=" +
      quoted_dir +
      "\n"
      "frames=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" \"$dir/" +
      kChunks +
      "\")\n"
      "exec \"$dir/" +
      kProgram + "\" \"$dir\" --farm render --frames \"$frames\"\n";
  const std::string movie =
      "#!/bin/sh\n"
      "# The movie job (billiards-export --farm slurm): runs when every task of the frame array has\n"
      "# ended; checks every frame, names the missing ones, and encodes movie.mp4 as a local run does.\n"
      "set -eu\n"
      "dir=" +
      quoted_dir +
      "\n"
      "exec \"$dir/" +
      kProgram + "\" \"$dir\" --farm assemble\n";
  std::error_code ec;
  fs::create_directories(stage.path(kLogs), ec);
  if (ec) {
    error = "cannot create " + stage.path(kLogs) + ": " + ec.message();
    return false;
  }
  // The logs of earlier submissions stay: a frame that failed is explained there.
  for (auto it = fs::directory_iterator(dir_ + "/" + kLogs, ec); !ec && it != fs::directory_iterator();
       it.increment(ec))
    link_or_copy(it->path().string(), stage.path(std::string(kLogs) + "/" + it->path().filename().string()));
  if (!write_file_atomically(stage.path(kConf), conf_text(conf), error) ||
      !write_file_atomically(stage.path(kChunks), chunk_lines, error) ||
      !write_file_atomically(stage.path(kCopies), copies_text(copies), error) ||
      !write_file_atomically(stage.path(kTaskScript), task, error) ||
      !write_file_atomically(stage.path(kMovieScript), movie, error))
    return false;
  // The jobs run this very program from DIR: nothing on the nodes but povray and ffmpeg is assumed.
  const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
  if (ec || !fs::copy_file(self, stage.path(kProgram), ec) || ec) {
    error = "cannot copy billiards-export into " + stage.path(kProgram) + (ec ? ": " + ec.message() : "");
    return false;
  }
  for (const char* script : {kTaskScript, kMovieScript, kProgram}) {
    fs::permissions(stage.path(script),
                    fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                        fs::perms::others_exec,
                    ec);
    if (ec) {
      error = "cannot make " + stage.path(script) + " executable: " + ec.message();
      return false;
    }
  }

  // Slurm checks the options (partition, account, time limit) now, before anything is submitted.
  std::vector<std::string> test = {sbatch_, "--test-only", "--job-name=" + name_ + "-movie"};
  test.insert(test.end(), user_options_.begin(), user_options_.end());
  test.push_back(stage.path(kMovieScript));
  std::string output;
  if (!run_captured(test, output, error)) {
    // `error` alone when sbatch could not be run at all (no temporary file, no process).
    if (!output.empty() || error.empty()) error = "sbatch would not take the jobs: " + output;
    return false;
  }
  return true;
}

int SlurmSubmission::submit(std::string& error) {
  auto sbatch = [&](const std::vector<std::string>& own, const std::string& script, std::string& id) {
    std::vector<std::string> argv = {sbatch_, "--parsable", "--chdir=" + dir_};
    argv.insert(argv.end(), own.begin(), own.end());
    argv.insert(argv.end(), user_options_.begin(), user_options_.end());
    argv.push_back(dir_ + "/" + script);
    std::string output;
    if (!run_captured(argv, output, error) || (id = job_id(output)).empty()) {
      error = "sbatch failed: " + (output.empty() ? error : output);
      return false;
    }
    return true;
  };
  FarmConf conf;
  if (!read_conf(dir_, conf, error)) return 1;
  std::string frames_job, movie_job;
  if (!chunks_.empty() && !sbatch({"--job-name=" + name_ + "-frames", "--array=0-" + std::to_string(chunks_.size() - 1),
                                   "--output=" + dir_ + "/" + kLogs + "/frames-%A_%a.log"},
                                  kTaskScript, frames_job))
    return 1;
  std::vector<std::string> movie_options = {"--job-name=" + name_ + "-movie",
                                            "--output=" + dir_ + "/" + kLogs + "/movie-%j.log"};
  // afterany, not afterok: the movie job runs even when a task failed, and names the missing frames.
  if (!frames_job.empty())
    movie_options.insert(movie_options.end(), {"--dependency=afterany:" + frames_job, "--kill-on-invalid-dep=no"});
  if (!sbatch(movie_options, kMovieScript, movie_job)) {
    if (!frames_job.empty() && !scancel_.empty()) {
      std::string ignored_output, ignored;
      run_captured({scancel_, frames_job}, ignored_output, ignored);  // no frames without the movie job
    }
    return 1;
  }
  conf.frames_job = frames_job;
  conf.movie_job = movie_job;
  if (!write_file_atomically(dir_ + "/" + kConf, conf_text(conf), error)) return 1;
  int largest = 0;
  for (const auto& c : chunks_) largest = std::max(largest, c.second - c.first + 1);
  if (!frames_job.empty())
    std::cout << "submitted job " << frames_job << ": " << chunks_.size() << (chunks_.size() == 1 ? " task" : " tasks")
              << " render " << missing_ << " of " << frames_ << " frames, up to " << largest << " a task"
              << (copies_ == 0 ? ""
                  : copies_ == 1
                      ? "; 1 more frame is the same as one of them and is copied"
                      : "; " + std::to_string(copies_) + " more frames are the same as some of them and are copied")
              << "\n";
  else
    std::cout << "all " << frames_ << " frames are rendered already\n";
  std::cout << "submitted job " << movie_job << ": checks every frame and writes " << dir_
            << "/movie.mp4 when the frames are done\n"
            << "follow them with: billiards-export " << dir_ << " --farm status\n";
  return 0;
}

int run_farm_command(const ExportOptions& options) {
  const std::string dir = options.scene_path.value_or(".");
  // Every mode on a submitted directory starts from its farm.conf.
  FarmConf conf;
  std::string error;
  if (!read_conf(dir, conf, error)) {
    std::cerr << "billiards-export: error: " << error << "\n";
    return 1;
  }
  switch (options.farm) {
    case FarmMode::status: return farm_status(dir, conf);
    case FarmMode::render: return farm_render(options, dir, conf);
    case FarmMode::assemble: return farm_assemble(options, dir, conf);
    case FarmMode::none:
    case FarmMode::slurm: break;
  }
  return 2;
}

}  // namespace bsim
