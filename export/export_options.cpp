#include "export_options.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "command_line.h"
#include "mastering.h"

namespace bsim {

namespace {

constexpr const char* kUsageHead = R"(usage: billiards-export [SCENE] [-o DIR] [options]

Simulates SCENE (default: the built-in break) and writes into DIR events.json, trajectory.csv,
camera.csv, the POV-Ray frames, soundtrack.wav, the rendered frames and movie.mp4.

options:
)";

constexpr const char* kUsageTail = R"(
exit status: 0 done, 1 bad scene or failed run, 2 bad command line
)";

/// --quality's presets, in the order of Quality's values.
constexpr std::string_view kQualityPresets = "draft|final";
/// --captions' values: on (0) or off.
constexpr std::string_view kCaptionsChoices = "on|off";

bool bad(std::string& message, const std::string& name, const std::string& text, const std::string& expected) {
  message = bad_value_message(name, text, expected);
  return false;
}

/// --frames FIRST-LAST (or one frame).
bool apply_frames(ExportOptions& o, const std::string& name, const std::string& v, std::string& m) {
  const std::size_t dash = v.find('-');
  const auto first = parse_int_option(v.substr(0, dash), 0, 100000000);
  const auto last = dash == std::string::npos ? first : parse_int_option(v.substr(dash + 1), 0, 100000000);
  if (!first || !last || *last < *first) return bad(m, name, v, "frames FIRST-LAST");
  o.first_frame = *first;
  o.last_frame = *last;
  return true;
}

bool apply_farm(ExportOptions& o, const std::string& name, const std::string& v, std::string& m) {
  static const std::vector<std::pair<std::string, FarmMode>> modes = {{"slurm", FarmMode::slurm},
                                                                      {"status", FarmMode::status},
                                                                      {"render", FarmMode::render},
                                                                      {"assemble", FarmMode::assemble}};
  for (const auto& [word, mode] : modes)
    if (v == word) return (o.farm = mode), true;
  return bad(m, name, v, "slurm, status, assemble or render");
}

bool apply_loudness(ExportOptions& o, const std::string& name, const std::string& v, std::string& m) {
  if (v == "off") {
    o.level = {.mode = LevelMode::off, .loudness = kDefaultLoudness};
    return true;
  }
  const auto lufs = parse_real_option(v);
  if (!lufs || *lufs < kMinLoudness || *lufs > kMaxLoudness) return bad(m, name, v, "LUFS from -40 to -10, or off");
  o.level = {.mode = LevelMode::normalised, .loudness = *lufs};
  return true;
}

/// The rows of the farm: its options, the modes on a submitted directory and the hidden --frames.
void add_farm_rows(OptionTable& table, ExportOptions& o) {
  using S = const std::string&;
  table.push_back({"", "", "", {}});
  table.push_back({"", "", "rendering on a Slurm cluster (see README):", {}});
  table.push_back({"--farm", "slurm",
                   "write the inputs into DIR (on a shared file system) and submit the frames as\n"
                   "a job array and the movie as a job that waits for it; print the job ids",
                   [&o](S n, S v, std::string& m) { return apply_farm(o, n, v, m); }});
  table.push_back(
      {"--chunk", "N", "frames a task renders (default: about three minutes of work)", [&o](S n, S v, std::string& m) {
         const auto chunk = parse_int_option(v, 1, kMaxFarmChunk);
         if (!chunk) return bad(m, n, v, "a number of frames from 1 to " + std::to_string(kMaxFarmChunk));
         o.chunk = *chunk;
         return true;
       }});
  table.push_back({"--sbatch-option", "ARG", "passed to sbatch, e.g. --sbatch-option=--partition=short (repeatable)",
                   [&o](S n, S v, std::string& m) {
                     if (v.empty()) return bad(m, n, v, "an sbatch option");
                     o.sbatch_options.push_back(v);
                     return true;
                   }});
  table.push_back(
      {"", "", "  billiards-export DIR --farm status     frames rendered so far and the jobs in the queue", {}});
  table.push_back(
      {"", "", "  billiards-export DIR --farm assemble   check every frame and make movie.mp4 (the movie job)", {}});
  table.push_back(
      {"", "", "  billiards-export DIR --farm render --frames A-B   render the missing frames A to B (a task)", {}});
  table.push_back({"--frames", "A-B", "", [&o](S n, S v, std::string& m) { return apply_frames(o, n, v, m); }, false});
}

/// One rule for every option: one that does nothing beside the others given is a mistake, said so
/// (exit 2) rather than accepted in silence. Empty when each option given has an effect.
std::string inert_option_message(const ExportOptions& o) {
  const auto given = [&o](std::string_view name) {
    return std::find(o.given.begin(), o.given.end(), name) != o.given.end() || (name == "--size" && o.size_given);
  };
  struct Inert {
    bool mode;
    const char* mode_name;
    const char* why;
    std::vector<std::string_view> options;
  };
  const Inert rules[] = {
      {o.events_only,
       "--events-only",
       "it writes no frames, sound or movie",
       {"--no-render", "--size", "--quality", "--jobs", "--whole-frames", "--captions", "--audio-lead", "--music",
        "--loudness"}},
      {o.no_render, "--no-render", "it runs no POV-Ray", {"--jobs", "--whole-frames"}},
  };
  for (const Inert& rule : rules) {
    if (!rule.mode) continue;
    for (std::string_view option : rule.options)
      if (given(option))
        return std::string(option) + " does nothing with " + rule.mode_name + " (" + rule.why +
               "); leave one of them out";
  }
  return "";
}

/// --music names a file that can be read: a missing one is a mistake on the command line.
bool apply_music(ExportOptions& o, const std::string& name, const std::string& v, std::string& m) {
  if (v.empty()) return bad(m, name, v, "a file");
  std::error_code ec;
  const auto status = std::filesystem::status(v, ec);
  if (!std::filesystem::exists(status) || std::filesystem::is_directory(status)) {
    m = "--music: cannot read '" + v + "': " +
        (std::filesystem::is_directory(status) ? std::string("it is a directory") : std::string("no such file"));
    return false;
  }
  if (!std::ifstream(v, std::ios::binary)) {
    m = "--music: cannot read '" + v + "': " + std::strerror(errno);
    return false;
  }
  o.music_path = v;
  return true;
}

}  // namespace

OptionTable export_option_table(ExportOptions& o) {
  using S = const std::string&;
  OptionTable table = {
      {"-o, --output", "DIR", "output directory (default: out/<scene name>)",
       [&o](S n, S v, std::string& m) {
         if (v.empty()) return bad(m, n, v, "a directory");
         o.out_dir = v;
         return true;
       }},
      {"--events-only", "", "write only events.json, trajectory.csv and camera.csv",
       [&o](S, S, std::string&) { return o.events_only = true; }},
      {"--no-render", "", "write the .pov frames and soundtrack.wav, but run neither POV-Ray nor ffmpeg",
       [&o](S, S, std::string&) { return o.no_render = true; }},
      {"--fps", "N", "frames per second, 1 to 1000 (default: 30)", {}},
      {"--size", "WxH", "frame size in pixels (default: 1280x720)", {}},
      {"--quality", kQualityPresets, "POV-Ray quality: draft is fast, final antialiased (default: final)",
       [&o](S n, S v, std::string& m) {
         const auto preset = choice_index(kQualityPresets, v);
         if (!preset) return bad(m, n, v, "draft or final");
         o.quality = *preset == 0 ? Quality::draft : Quality::final;
         return true;
       }},
      {"--jobs", "N",
       "POV-Ray processes tracing at once, 1 to 1024 (default: one per core); while one\n"
       "starts up, a partial frame's rectangle may start too",
       [&o](S n, S v, std::string& m) {
         const auto jobs = parse_int_option(v, 1, kMaxJobs);
         if (!jobs) return bad(m, n, v, "a number of processes from 1 to " + std::to_string(kMaxJobs));
         o.jobs = *jobs;
         return true;
       }},
      {"--whole-frames", "",
       "trace every pixel of every frame (by default a frame of a still camera traces only\n"
       "what changed and takes the rest from the frame before: the same pixels)",
       [&o](S, S, std::string&) { return o.whole_frames = true; }},
      {"--captions", kCaptionsChoices,
       "a game's captions on its frames: the players, the balls left, the referee's\ncalls (default: on)",
       [&o](S n, S v, std::string& m) {
         const auto choice = choice_index(kCaptionsChoices, v);
         if (!choice) return bad(m, n, v, "on or off");
         o.captions = *choice == 0;
         return true;
       }},
      {"--audio-lead", "SECONDS", "sounds start this long before their event, 0 to 1 (default: 0.005)",
       [&o](S n, S v, std::string& m) {
         const auto lead = parse_real_option(v);
         if (!lead || *lead < 0 || *lead > kMaxAudioLead) return bad(m, n, v, "seconds from 0 to 1");
         o.audio_lead = *lead;
         return true;
       }},
      {"--music", "FILE", "a music file mixed under the sound track (default: none)",
       [&o](S n, S v, std::string& m) { return apply_music(o, n, v, m); }},
      {"--loudness", "LUFS|off",
       "bring this shot's sound track to this integrated loudness, -40 to -10,\nor off: the mix's own "
       "level (default: one calibrated level for every shot,\nthe built-in break at -16 LUFS)",
       [&o](S n, S v, std::string& m) { return apply_loudness(o, n, v, m); }},
      {"--strict", "", kStrictHelp, {}},
      {"--quiet", "", "print no progress or closing lines (errors and warnings still print)", {}},
      {"--camera",
       kCameraChoices,
       "auto: film with the automatic director's camera script instead of the\nscene's own (default: scene)",
       {}},
      replay_option_row(o.replay),
      {"-h, --help", "", "show this help and exit", {}},
      {"--version", "", "show the version and exit", {}},
  };
  add_farm_rows(table, o);
  return table;
}

CommandLineOutcome parse_export_options(const std::vector<std::string>& args, ExportOptions& options,
                                        std::string& message) {
  options = ExportOptions{};
  options.audio_lead = kDefaultAudioLead;
  const OptionTable table = export_option_table(options);
  const auto apply = [&](ArgReader& reader, std::string& error) {
    options.given.push_back(reader.word());
    return apply_table_option(reader, table, error);
  };
  switch (read_arguments(args, options.scene_path, options, usage_text(kUsageHead, table, kUsageTail),
                         "billiards-export " BSIM_VERSION "\n", apply, message)) {
    case ArgumentsOutcome::exit_success: return CommandLineOutcome::exit_success;
    case ArgumentsOutcome::exit_usage: return CommandLineOutcome::exit_usage;
    case ArgumentsOutcome::run: break;
  }
  const bool submit = options.farm == FarmMode::slurm;
  if (!submit && (options.chunk > 0 || !options.sbatch_options.empty()))
    message = std::string(options.chunk > 0 ? "--chunk" : "--sbatch-option") + " needs --farm slurm";
  else if (options.farm != FarmMode::render && options.last_frame >= 0)
    message = "--frames needs --farm render";
  else if (submit && (options.events_only || options.no_render))
    message = std::string("--farm slurm renders on the cluster; it cannot go with ") +
              (options.events_only ? "--events-only" : "--no-render");
  else if (options.farm != FarmMode::none && !submit && !options.scene_path)
    message =
        "--farm status, assemble and render need the farm's output directory, as in `billiards-export DIR "
        "--farm status`";
  else
    message = inert_option_message(options);
  if (!message.empty()) return CommandLineOutcome::exit_usage;
  return CommandLineOutcome::run;
}

}  // namespace bsim
